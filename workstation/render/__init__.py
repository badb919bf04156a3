"""Off-screen renders (pyvista/VTK, EGL or OSMesa, no display) and the HTML report."""

from .render import (RenderParams, VIEWS, projection_matrix, reconstruction_view, render, save_gif, save_png,
                     turntable)

__all__ = ["RenderParams", "VIEWS", "projection_matrix", "reconstruction_view", "render", "save_gif", "save_png",
           "turntable"]
