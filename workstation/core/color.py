"""Colour scaling between the ``rgb`` dimension (integers) and unit floats in [0, 1].

``Cloud.attrs["rgb"]`` is uint16 (the LAS convention, 0..65535) and a mesh's vertex ``rgb`` is
uint8, while Open3D, MeshLab and VTK take colours as floats in [0, 1]. Every conversion to
unit colours goes through :func:`rgb_to_unit`, so all libraries see the same colours.

The scaling rule:

- floats are taken as unit colours already and clipped to [0, 1];
- ``uint8`` is divided by 255;
- any other integer array is divided by 255 when its largest value is at most 255, else by
  65535. Many tools write LAS files whose 16-bit colour fields hold 8-bit values (0..255):
  dividing those by 65535 would make every colour near-black. The price is that a genuinely
  16-bit array whose every channel is at most 255 (an all but black image) is read as 8-bit.
"""

from __future__ import annotations

import numpy as np


def rgb_to_unit(rgb: np.ndarray) -> np.ndarray:
    """Integer (or unit-float) colours (n, 3) -> float64 in [0, 1], by the module's rule.

    Examples
    --------
    >>> rgb_to_unit(np.array([[255, 0, 51]], np.uint8)).tolist()
    [[1.0, 0.0, 0.2]]
    >>> rgb_to_unit(np.array([[255, 0, 51]], np.uint16)).tolist()  # 8-bit values stored in 16 bits
    [[1.0, 0.0, 0.2]]
    >>> rgb_to_unit(np.array([[65535, 0, 13107]], np.uint16)).tolist()
    [[1.0, 0.0, 0.2]]
    """
    rgb = np.asarray(rgb)
    if rgb.dtype.kind == "f":
        return np.clip(rgb.astype(np.float64), 0.0, 1.0)
    scale = 255.0 if (rgb.dtype == np.uint8 or (rgb.size and int(rgb.max()) <= 255)) else 65535.0
    return rgb.astype(np.float64) / scale


def rgb_to_u8(rgb: np.ndarray) -> np.ndarray:
    """Integer or unit-float colours (n, 3) -> (n, 3) uint8 (through :func:`rgb_to_unit`)."""
    return np.round(rgb_to_unit(rgb) * 255.0).astype(np.uint8)


def unit_to_rgb16(c: np.ndarray) -> np.ndarray:
    """Colours in [0, 1] (clipped) -> (n, 3) uint16, the ``rgb`` dimension of a cloud."""
    return np.round(np.clip(np.asarray(c, dtype=np.float64), 0.0, 1.0) * 65535.0).astype(np.uint16)
