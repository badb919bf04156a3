"""The dimension table: one row per known per-point attribute.

Canonical names are snake_case. Each row gives the numpy dtype, the per-point shape
(``()`` for scalars, ``(3,)`` for rgb and normals), and the names the same quantity has in
LAS (laspy), PDAL and Open3D. Translation between names happens only at the IO and interop
boundary, through :func:`canonical_name` and the rows of :data:`DIMS`.

Any other attribute (an extra-byte dimension, a feature a stage computed) is allowed under
its own name with its own dtype.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Dim:
    """One known dimension.

    Attributes
    ----------
    name : str
        Canonical snake_case name, the key in ``Cloud.attrs``.
    dtype : numpy dtype
        Storage type.
    shape : tuple
        Per-point shape: ``()`` or ``(3,)``.
    las : tuple of str
        laspy dimension name(s); several for a vector (``red, green, blue``).
    pdal : tuple of str
        PDAL dimension name(s).
    open3d : str or None
        Open3D tensor attribute name.
    unit : str
        Unit or meaning of values.
    """

    name: str
    dtype: np.dtype
    shape: tuple = ()
    las: tuple = ()
    pdal: tuple = ()
    open3d: str | None = None
    unit: str = ""


def _d(name, dtype, shape=(), las=(), pdal=(), open3d=None, unit=""):
    return Dim(name, np.dtype(dtype), tuple(shape), tuple(las), tuple(pdal), open3d, unit)


DIMS: dict[str, Dim] = {
    d.name: d
    for d in [
        _d("intensity", "u2", las=("intensity",), pdal=("Intensity",), open3d="intensities", unit="return strength, 16-bit"),
        _d("return_number", "u1", las=("return_number",), pdal=("ReturnNumber",), unit="1-based"),
        _d("number_of_returns", "u1", las=("number_of_returns",), pdal=("NumberOfReturns",), unit="count"),
        _d("classification", "u1", las=("classification",), pdal=("Classification",), open3d="classification", unit="ASPRS code"),
        _d("scan_angle", "f4", las=("scan_angle",), pdal=("ScanAngleRank",), unit="degrees, negative to the left"),
        _d("gps_time", "f8", las=("gps_time",), pdal=("GpsTime",), unit="seconds (GPS week or adjusted standard time)"),
        _d("point_source_id", "u2", las=("point_source_id",), pdal=("PointSourceId",), unit="flight line / station"),
        _d("rgb", "u2", (3,), las=("red", "green", "blue"), pdal=("Red", "Green", "Blue"), open3d="colors", unit="16-bit colour"),
        _d("nir", "u2", las=("nir",), pdal=("Infrared",), unit="16-bit near infrared"),
        _d("normal", "f4", (3,), pdal=("NormalX", "NormalY", "NormalZ"), open3d="normals", unit="unit vector"),
        _d("user_data", "u1", las=("user_data",), pdal=("UserData",)),
        _d("scan_direction_flag", "u1", las=("scan_direction_flag",), pdal=("ScanDirectionFlag",), unit="0/1"),
        _d("edge_of_flight_line", "u1", las=("edge_of_flight_line",), pdal=("EdgeOfFlightLine",), unit="0/1"),
        _d("synthetic", "u1", las=("synthetic",), pdal=("Synthetic",), unit="0/1 flag"),
        _d("key_point", "u1", las=("key_point",), pdal=("KeyPoint",), unit="0/1 flag"),
        _d("withheld", "u1", las=("withheld",), pdal=("Withheld",), unit="0/1 flag"),
        _d("overlap", "u1", las=("overlap",), pdal=("Overlap",), unit="0/1 flag (LAS 1.4 formats 6-10)"),
        _d("scanner_channel", "u1", las=("scanner_channel",), pdal=("ScanChannel",), unit="0-3"),
        _d("wavepacket_index", "u1", las=("wavepacket_index",), pdal=("WavePacketDescriptorIndex",)),
        _d("wavepacket_offset", "u8", las=("wavepacket_offset",), pdal=("WaveformDataOffset",), unit="bytes"),
        _d("wavepacket_size", "u4", las=("wavepacket_size",), pdal=("WaveformPacketSize",), unit="bytes"),
        _d("return_point_wave_location", "f4", las=("return_point_wave_location",), pdal=("ReturnPointWaveformLocation",), unit="picoseconds"),
        _d("x_t", "f4", las=("x_t",), pdal=("WaveformXt",)),
        _d("y_t", "f4", las=("y_t",), pdal=("WaveformYt",)),
        _d("z_t", "f4", las=("z_t",), pdal=("WaveformZt",)),
        _d("hag", "f4", pdal=("HeightAboveGround",), unit="metres (CRS linear unit) above the ground surface"),
        _d("confidence", "f4", pdal=("Confidence",), unit="0-1, classifier probability of the predicted class"),
    ]
}

# Flags that share the LAS classification byte or flag byte.
LAS_FLAGS = ("synthetic", "key_point", "withheld", "overlap")

_ALIASES: dict[str, str] = {}
for _dim in DIMS.values():
    for _alias in (*_dim.las, *_dim.pdal, _dim.open3d):
        if _alias and len(_dim.las) <= 1 and len(_dim.pdal) <= 1:
            _ALIASES[_alias.lower()] = _dim.name
_ALIASES.update(
    {
        "scan_angle_rank": "scan_angle",
        "scanangle": "scan_angle",
        "gpstime": "gps_time",
        "label": "classification",
        "class": "classification",
        "colors": "rgb",
        "color": "rgb",
        "normals": "normal",
        "intensities": "intensity",
        "heightaboveground": "hag",
        "height_above_ground": "hag",
    }
)


def canonical_name(name: str) -> str:
    """Canonical name for a LAS, PDAL or Open3D dimension name; unknown names pass unchanged.

    Examples
    --------
    >>> canonical_name("Intensity"), canonical_name("ScanAngleRank"), canonical_name("treeID")
    ('intensity', 'scan_angle', 'treeID')
    """
    return _ALIASES.get(name.lower(), name)


def expected_dtype(name: str) -> np.dtype | None:
    """The table dtype of a known dimension, or None for a free attribute."""
    d = DIMS.get(name)
    return None if d is None else d.dtype
