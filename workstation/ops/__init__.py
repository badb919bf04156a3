"""Everyday point cloud operations as plain functions on :class:`~workstation.core.cloud.Cloud`.

What a PDAL user reaches for first: crop by bounds or polygons (``filters.crop``), filter by
an expression (``filters.expression``), thin by voxels or Poisson disks
(``filters.voxelcentroidnearestneighbor``, ``filters.sample``), tile (``filters.splitter``),
merge (``filters.merge``), and the equivalent PDAL pipeline JSON of each run
(:mod:`workstation.ops.pdal`). :mod:`workstation.ops.stream` runs the per-point operations
chunk by chunk so memory stays bounded on big files.
"""

from .crop import CropParams, crop, crop_mask
from .expression import compile_expression, filter_expression
from .thin import PoissonParams, VoxelParams, poisson_thin, voxel_thin
from .vector import PolygonSet, read_polygons

__all__ = ["CropParams", "crop", "crop_mask", "compile_expression", "filter_expression", "PoissonParams",
           "VoxelParams", "poisson_thin", "voxel_thin", "PolygonSet", "read_polygons"]
