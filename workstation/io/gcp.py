"""GCP.csv: ground control and check points for georeferencing.

Format (comma-separated, one header line, ``#`` starts a comment line)::

    name,X,Y,Z,role,sigma,image,u,v
    GCP1,500012.31,4100023.55,102.31,control,0.02,IMG_0001.JPG,1523.4,876.2
    GCP1,,,,,,IMG_0002.JPG,1611.0,902.7
    CHK1,500040.10,4100011.00,101.80,check,,IMG_0002.JPG,310.5,1201.9

Columns:

========  ===================================================================================
name      point name (required on every row)
X, Y, Z   surveyed (world) coordinates in the target CRS units; required on the first row of a
          point, may be left empty on its further observation rows
role      ``control`` (used in the fit) or ``check`` (held out: only used to measure accuracy);
          default ``control``
sigma     optional standard deviation of the surveyed coordinates (same units); weighs a
          control point's ground coordinates in the bundle adjustment with GCP constraints
          (:mod:`workstation.photogrammetry.bundle`; when empty: σ_px × its mean GSD)
image     optional image name of an observation (as in the reconstruction)
u, v      pixel coordinates of the observation (OpenCV convention: origin at the centre of the
          top-left pixel)
mx,my,mz  alternatively: the point's position picked in the model (reconstruction) frame
========  ===================================================================================

A point needs either ≥ 2 image observations (it is then triangulated by space intersection
from the oriented images) or model coordinates mx, my, mz. Column order is free; names are
matched case-insensitively.

Examples
--------
>>> import tempfile, pathlib
>>> p = pathlib.Path(tempfile.mkdtemp()) / "gcp.csv"
>>> _ = p.write_text("name,X,Y,Z,role,mx,my,mz\\nA,10,20,30,control,1,2,3\\nB,11,21,31,check,2,3,4\\n")
>>> pts = read_gcp(p)
>>> [(g.name, g.role, g.model_xyz.tolist()) for g in pts]
[('A', 'control', [1.0, 2.0, 3.0]), ('B', 'check', [2.0, 3.0, 4.0])]
"""

from __future__ import annotations

import csv
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from workstation.core.errors import InvalidInputError

from .textfile import read_text

ROLES = ("control", "check")


@dataclass(frozen=True)
class GCP:
    """One ground control or check point.

    Attributes
    ----------
    name : str
    xyz : (3,) float
        Surveyed coordinates (target CRS units).
    role : str
        "control" or "check".
    sigma : float or None
        Standard deviation of the surveyed coordinates.
    observations : tuple of (image name, u, v)
        Pixel observations.
    model_xyz : (3,) float or None
        Position in the model frame when picked there.
    """

    name: str
    xyz: np.ndarray
    role: str = "control"
    sigma: float | None = None
    observations: tuple = field(default_factory=tuple)
    model_xyz: np.ndarray | None = None


def _num(row, key, path, lineno, required=False):
    v = (row.get(key) or "").strip()
    if not v:
        if required:
            raise InvalidInputError(f"line {lineno}: '{key}' is empty", path=path, field=key)
        return None
    try:
        x = float(v)
    except ValueError:
        raise InvalidInputError(f"line {lineno}: '{key}' = {v!r} is not a number", path=path, field=key) from None
    if not np.isfinite(x):
        raise InvalidInputError(f"line {lineno}: '{key}' = {v!r} is not finite", "give a finite number", path=path, field=key)
    return x


def read_gcp(path) -> list[GCP]:
    """Read a GCP CSV (format in the module docstring) into a list of :class:`GCP` in file order.

    Raises
    ------
    InvalidInputError
        Missing file or columns, bad numbers, unknown role, a point without coordinates.
    """
    p = Path(path)
    if not p.is_file():
        raise InvalidInputError("GCP file not found", path=p)
    lines = [ln for ln in read_text(p).splitlines() if ln.strip() and not ln.lstrip().startswith("#")]
    if not lines:
        raise InvalidInputError("empty GCP file", path=p)
    try:
        return _parse(lines, p)
    except csv.Error as e:
        raise InvalidInputError(f"not a readable CSV file: {e}", "see workstation.io.gcp for the format", path=p) from None


def _parse(lines: list[str], p: Path) -> list[GCP]:
    """The GCPs of the CSV ``lines`` (comments and blank lines removed) of file ``p``."""
    reader = csv.DictReader(lines)
    reader.fieldnames = [f.strip().lower() for f in (reader.fieldnames or [])]
    for k in ("name", "x", "y", "z"):
        if k not in reader.fieldnames:
            raise InvalidInputError(f"missing column '{k}' (have {reader.fieldnames})", "see workstation.io.gcp", path=p)
    pts: dict[str, dict] = {}
    for lineno, row in enumerate(reader, 2):
        row = {k: v for k, v in row.items() if k is not None}
        name = (row.get("name") or "").strip()
        if not name:
            raise InvalidInputError(f"line {lineno}: empty name", path=p, field="name")
        d = pts.setdefault(name, {"xyz": None, "role": None, "sigma": None, "obs": [], "model": None})
        xyz = [_num(row, k, p, lineno) for k in ("x", "y", "z")]
        if any(v is not None for v in xyz):
            if any(v is None for v in xyz):
                raise InvalidInputError(f"line {lineno}: X, Y and Z must all be given", path=p)
            if d["xyz"] is not None and not np.allclose(d["xyz"], xyz):
                raise InvalidInputError(f"line {lineno}: point {name} has two different coordinates", path=p)
            d["xyz"] = np.array(xyz)
        role = (row.get("role") or "").strip().lower()
        if role:
            if role not in ROLES:
                raise InvalidInputError(f"line {lineno}: role {role!r} is not control or check", path=p, field="role")
            d["role"] = role
        s = _num(row, "sigma", p, lineno) if "sigma" in row else None
        if s is not None:
            d["sigma"] = s
        img = (row.get("image") or "").strip()
        if img:
            d["obs"].append((img, _num(row, "u", p, lineno, True), _num(row, "v", p, lineno, True)))
        if all(k in row for k in ("mx", "my", "mz")):
            m = [_num(row, k, p, lineno) for k in ("mx", "my", "mz")]
            if all(v is not None for v in m):
                d["model"] = np.array(m)
    out = []
    for name, d in pts.items():
        if d["xyz"] is None:
            raise InvalidInputError(f"point {name} has no X, Y, Z", path=p)
        out.append(GCP(name, d["xyz"], d["role"] or "control", d["sigma"], tuple(d["obs"]), d["model"]))
    return out
