"""Strip adjustment and boresight calibration of airborne laser scanning from overlapping flight lines."""

from .adjust import AdjustParams, AdjustResult, apply_corrections, estimate_corrections
from .patches import PatchParams, Patches, find_patches
from .trajectory import Navigation, read_trajectory_csv

__all__ = ["AdjustParams", "AdjustResult", "Navigation", "PatchParams", "Patches", "apply_corrections",
           "estimate_corrections", "find_patches", "read_trajectory_csv"]
