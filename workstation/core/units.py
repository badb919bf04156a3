"""The one unit model: every length a user gives or reads is in metres; files keep their own.

A CRS says in which unit its coordinates are: the horizontal unit (metre, foot, US survey
foot, or degree for a geographic CRS) and the vertical unit (the height axis of a compound or
3-D CRS, a LAS ``VerticalUnitsGeoKey``, or else the horizontal unit). :class:`Units` holds
both as *metres per unit* and converts at the edge: a parameter in metres becomes CRS units
with :meth:`Units.h_from_m` / :meth:`Units.v_from_m` before it touches coordinates, and a
figure read from coordinates becomes metres with :meth:`Units.h_to_m` / :meth:`Units.v_to_m`
before it is shown. :func:`parse_length` reads a length with an optional unit suffix
(``3ft``, ``1m``, ``2.5 us-ft``); a bare number is metres.

This module is pure Python (no pyproj): :func:`workstation.io.crs.crs_units` builds a
:class:`Units` from a CRS.

Examples
--------
>>> u = Units(US_SURVEY_FOOT, US_SURVEY_FOOT, "US survey foot", "US survey foot")
>>> round(u.h_from_m(1.0), 3)
3.281
>>> u.describe_h(1.0)
'1 m (3.281 US ft in the CRS units)'
>>> METRES.describe_h(1.0)
'1 m'
>>> round(parse_length("3ft"), 6)
0.9144
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

#: Metres per international foot and per US survey foot (1200/3937 m).
FOOT = 0.3048
US_SURVEY_FOOT = 1200.0 / 3937.0
#: Metres per degree of latitude (for geographic CRSs; eastings scale by cos(latitude)).
METRES_PER_DEGREE = 111_320.0

#: Length suffixes a user may write after a number, in metres per unit.
SUFFIXES = {
    "m": 1.0, "metre": 1.0, "metres": 1.0, "meter": 1.0, "meters": 1.0,
    "cm": 0.01, "mm": 0.001, "km": 1000.0,
    "ft": FOOT, "foot": FOOT, "feet": FOOT, "ift": FOOT,
    "usft": US_SURVEY_FOOT, "us-ft": US_SURVEY_FOOT, "ftus": US_SURVEY_FOOT, "us_ft": US_SURVEY_FOOT,
    "sft": US_SURVEY_FOOT,
}
_LENGTH = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([A-Za-z_\-]*)\s*$")

#: Short names of the units CRSs use, for messages and labels.
_ABBREV = {"metre": "m", "meter": "m", "foot": "ft", "US survey foot": "US ft", "degree": "°",
           "kilometre": "km", "centimetre": "cm", "millimetre": "mm"}


def parse_length(text: str | float, default_unit: str = "m") -> float:
    """A length in metres from ``"3ft"``, ``"1 m"``, ``"2.5us-ft"`` or a bare number (metres).

    Raises
    ------
    ValueError
        Not a number, or an unknown unit suffix (the message lists the known ones).

    Examples
    --------
    >>> parse_length("2.5"), parse_length("10cm"), round(parse_length("1usft"), 10)
    (2.5, 0.1, 0.3048006096)
    """
    if isinstance(text, (int, float)):
        return float(text) * SUFFIXES[default_unit]
    m = _LENGTH.match(str(text))
    if not m:
        raise ValueError(f"{text!r} is not a length (a number with an optional unit, e.g. 1.5, 2m, 3ft)")
    unit = (m.group(2) or default_unit).lower()
    if unit not in SUFFIXES:
        raise ValueError(f"unknown length unit {m.group(2)!r} in {text!r}; use m, cm, mm, km, ft or usft")
    return float(m.group(1)) * SUFFIXES[unit]


def abbrev(unit_name: str) -> str:
    """Short form of a unit name for labels ("metre" -> "m", "US survey foot" -> "US ft")."""
    return _ABBREV.get(unit_name, unit_name)


def _num(x: float) -> str:
    """A length for messages: up to 4 significant digits, no trailing zeros."""
    return f"{x:.4g}" if abs(x) < 1e4 else f"{x:,.0f}"


@dataclass(frozen=True)
class Units:
    """Horizontal and vertical units of a CRS, as metres per unit and names.

    Attributes
    ----------
    h, v : float
        Metres per horizontal / vertical CRS unit (for a geographic CRS ``h`` is metres per
        degree of latitude, an approximation stated by :attr:`geographic`).
    h_name, v_name : str
        Unit names as pyproj spells them ("metre", "foot", "US survey foot", "degree").
    geographic : bool
        Horizontal coordinates are angles.
    known : bool
        False when the CRS is unknown and metres are assumed.
    """

    h: float = 1.0
    v: float = 1.0
    h_name: str = "metre"
    v_name: str = "metre"
    geographic: bool = False
    known: bool = True

    @property
    def is_metric(self) -> bool:
        """Both axes in metres (nothing to convert)."""
        return self.h == 1.0 and self.v == 1.0

    @property
    def h_abbrev(self) -> str:
        return abbrev(self.h_name)

    @property
    def v_abbrev(self) -> str:
        return abbrev(self.v_name)

    @property
    def z_factor(self) -> float:
        """Horizontal units per vertical unit, for slopes: dz/dx in metres/metre is
        ``z_factor`` × dz/dx in CRS units (0.3048 for feet heights on metre eastings)."""
        return self.v / self.h

    def h_from_m(self, metres):
        """A horizontal length in metres expressed in CRS units."""
        return metres / self.h

    def v_from_m(self, metres):
        """A height difference in metres expressed in CRS vertical units."""
        return metres / self.v

    def h_to_m(self, value):
        """A horizontal length in CRS units expressed in metres."""
        return value * self.h

    def v_to_m(self, value):
        """A height (difference) in CRS vertical units expressed in metres."""
        return value * self.v

    def area_to_m2(self, area):
        """An area in square CRS units expressed in m²."""
        return area * self.h * self.h

    def describe_h(self, metres: float) -> str:
        """A horizontal length in metres for a message, with its value in CRS units when those
        are not metres: ``'1 m (3.281 US ft in the CRS units)'``."""
        if self.h == 1.0:
            return f"{_num(metres)} m"
        return f"{_num(metres)} m ({_num(self.h_from_m(metres))} {self.h_abbrev} in the CRS units)"

    def describe_v(self, metres: float) -> str:
        """A height difference in metres for a message, with its value in the vertical unit."""
        if self.v == 1.0:
            return f"{_num(metres)} m"
        return f"{_num(metres)} m ({_num(self.v_from_m(metres))} {self.v_abbrev} in the CRS units)"

    def to_dict(self) -> dict:
        """JSON form: ``{"horizontal": name, "vertical": name, "metres_per_unit": {h, v}}``."""
        return {"horizontal": self.h_name, "vertical": self.v_name, "geographic": self.geographic,
                "known": self.known, "metres_per_unit": {"horizontal": self.h, "vertical": self.v}}

    @classmethod
    def from_dict(cls, d: dict | None) -> Units | None:
        """Inverse of :meth:`to_dict` (None for None or a malformed dict)."""
        try:
            mpu = d["metres_per_unit"]
            h, v = float(mpu["horizontal"]), float(mpu["vertical"])
        except (TypeError, KeyError, ValueError):
            return None
        if not (h > 0 and v > 0 and math.isfinite(h) and math.isfinite(v)):
            return None
        return cls(h, v, str(d.get("horizontal", "")), str(d.get("vertical", "")), bool(d.get("geographic", False)),
                   bool(d.get("known", True)))


#: Metres on both axes (also what an unknown CRS is assumed to be).
METRES = Units()
UNKNOWN = Units(known=False)
