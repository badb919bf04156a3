"""ASPRS point classes of LAS 1.4 R15 (Table 17, codes 0-22) and their display colours."""

from __future__ import annotations

from enum import IntEnum

import numpy as np


class ASPRSClass(IntEnum):
    """ASPRS standard point classes (LAS 1.4 R15). Codes 23-63 are reserved, 64-255 user defined."""

    CREATED_NEVER_CLASSIFIED = 0
    UNCLASSIFIED = 1
    GROUND = 2
    LOW_VEGETATION = 3
    MEDIUM_VEGETATION = 4
    HIGH_VEGETATION = 5
    BUILDING = 6
    LOW_POINT = 7
    """Low point (noise)."""
    RESERVED_8 = 8
    """Reserved; 'model key-point' in LAS 1.1-1.3."""
    WATER = 9
    RAIL = 10
    ROAD_SURFACE = 11
    RESERVED_12 = 12
    """Reserved; 'overlap points' in LAS 1.1-1.3."""
    WIRE_GUARD = 13
    WIRE_CONDUCTOR = 14
    TRANSMISSION_TOWER = 15
    WIRE_CONNECTOR = 16
    BRIDGE_DECK = 17
    HIGH_NOISE = 18
    OVERHEAD_STRUCTURE = 19
    IGNORED_GROUND = 20
    SNOW = 21
    TEMPORAL_EXCLUSION = 22

    @property
    def label(self) -> str:
        """Human-readable name as printed in the LAS specification."""
        return CLASS_NAMES[int(self)]


CLASS_NAMES: dict[int, str] = {
    0: "Created, never classified",
    1: "Unclassified",
    2: "Ground",
    3: "Low Vegetation",
    4: "Medium Vegetation",
    5: "High Vegetation",
    6: "Building",
    7: "Low Point (noise)",
    8: "Reserved (model key-point)",
    9: "Water",
    10: "Rail",
    11: "Road Surface",
    12: "Reserved (overlap)",
    13: "Wire - Guard (Shield)",
    14: "Wire - Conductor (Phase)",
    15: "Transmission Tower",
    16: "Wire-Structure Connector (Insulator)",
    17: "Bridge Deck",
    18: "High Noise",
    19: "Overhead Structure",
    20: "Ignored Ground",
    21: "Snow",
    22: "Temporal Exclusion",
}

VEGETATION = (ASPRSClass.LOW_VEGETATION, ASPRSClass.MEDIUM_VEGETATION, ASPRSClass.HIGH_VEGETATION)
NOISE = (ASPRSClass.LOW_POINT, ASPRSClass.HIGH_NOISE)


def class_name(code: int) -> str:
    """Name of a class code, including reserved and user-defined ranges.

    Examples
    --------
    >>> class_name(2)
    'Ground'
    >>> class_name(65)
    'User defined (65)'
    """
    code = int(code)
    if code in CLASS_NAMES:
        return CLASS_NAMES[code]
    if 23 <= code <= 63:
        return f"Reserved ({code})"
    return f"User defined ({code})"


# Colours (RGB 0-255) in the palette most viewers use for ASPRS classes.
CLASS_COLORS: dict[int, tuple[int, int, int]] = {
    0: (170, 170, 170),
    1: (200, 200, 200),
    2: (166, 113, 52),
    3: (160, 220, 110),
    4: (60, 180, 60),
    5: (15, 110, 30),
    6: (220, 60, 50),
    7: (255, 0, 255),
    8: (255, 255, 0),
    9: (40, 110, 230),
    10: (120, 80, 40),
    11: (90, 90, 90),
    12: (255, 255, 0),
    13: (255, 200, 0),
    14: (255, 150, 0),
    15: (200, 100, 0),
    16: (240, 180, 120),
    17: (150, 90, 200),
    18: (255, 80, 200),
    19: (120, 200, 200),
    20: (150, 120, 90),
    21: (240, 250, 255),
    22: (100, 100, 150),
}


def class_colors(codes: np.ndarray) -> np.ndarray:
    """RGB colours (n, 3) uint8 for class codes (n,); unknown codes are grey."""
    lut = np.full((256, 3), 128, dtype=np.uint8)
    for k, v in CLASS_COLORS.items():
        lut[k] = v
    return lut[np.asarray(codes, dtype=np.uint8)]
