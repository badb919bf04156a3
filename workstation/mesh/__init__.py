"""Meshing with MeshLab filters (pymeshlab): normals, screened Poisson, ball pivoting, 2.5D
Delaunay, cleaning, decimation, smoothing, colour transfer, a quality summary, and texture
from oriented photos. Screened Poisson runs Open3D's build of the same PoissonRecon by
default (MeshLab's is 2x slower here, PyMeshLab #408; see :class:`PoissonParams`).

pymeshlab and open3d are imported inside the functions; importing this package is cheap.
"""

from .chain import METHODS, MeshChainParams, MeshResult, mesh_cloud
from .clean import CleanParams, clean
from .color import ColorTransferParams, transfer_colors
from .normals import NormalParams, estimate_normals
from .quality import QualityParams, mesh_quality
from .reconstruct import (BallPivotingParams, Delaunay25dParams, PoissonParams, RefineParams, ball_pivoting,
                          delaunay25d, keep_vertices, poisson, refine_to_cloud)
from .simplify import DecimateParams, SmoothParams, decimate, smooth, subdivide_midpoint
from .steps import StepRecord, point_spacing
from .texture import TextureParams, texture_from_photos

__all__ = [
    "METHODS", "MeshChainParams", "MeshResult", "mesh_cloud", "CleanParams", "clean", "ColorTransferParams",
    "transfer_colors", "NormalParams", "estimate_normals", "QualityParams", "mesh_quality", "BallPivotingParams",
    "Delaunay25dParams", "PoissonParams", "RefineParams", "refine_to_cloud", "ball_pivoting", "delaunay25d",
    "keep_vertices", "poisson",
    "DecimateParams", "SmoothParams", "decimate", "smooth", "StepRecord", "point_spacing", "TextureParams",
    "texture_from_photos", "subdivide_midpoint",
]
