"""The :class:`Cloud` type: the one thing stages pass around.

A cloud is absolute float64 coordinates plus named per-point attributes, a CRS, IO metadata
for faithful round trips, and a history of the stages that made it. It is immutable in
practice: stored arrays are read-only views, and every operation returns a new cloud.
"""

from __future__ import annotations

import datetime as _dt
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any, Iterable, Mapping

import numpy as np

from .dims import DIMS
from .errors import InvalidInputError


@dataclass(frozen=True)
class HistoryRecord:
    """One stage applied to a cloud: its name, parameters and when it ran (UTC ISO 8601)."""

    stage: str
    params: Mapping[str, Any] = field(default_factory=dict)
    time: str = ""
    seconds: float | None = None

    def to_dict(self) -> dict:
        return {"stage": self.stage, "params": dict(self.params), "time": self.time, "seconds": self.seconds}


def _readonly(a: np.ndarray) -> np.ndarray:
    if not a.flags.writeable:
        return a
    v = a.view()
    v.flags.writeable = False
    return v


def _coerce_attr(name: str, value, n: int) -> np.ndarray:
    arr = np.asarray(value)
    dim = DIMS.get(name)
    if arr.ndim == 0 or arr.shape[0] != n:
        raise InvalidInputError(
            f"has {0 if arr.ndim == 0 else arr.shape[0]} values for {n} points",
            "every attribute needs one value per point",
            field=name,
        )
    if dim is not None:
        if arr.shape[1:] != dim.shape:
            raise InvalidInputError(
                f"per-point shape {arr.shape[1:]} but {name} needs {dim.shape}", field=name
            )
        if arr.dtype != dim.dtype:
            arr = _cast_checked(name, arr, dim.dtype)
    elif arr.dtype == object:
        raise InvalidInputError("object arrays cannot be stored", "use a numeric dtype", field=name)
    return _readonly(arr)


def _cast_checked(name: str, arr: np.ndarray, dtype: np.dtype) -> np.ndarray:
    if np.issubdtype(dtype, np.integer):
        if arr.dtype.kind == "b":
            return arr.astype(dtype)
        if arr.dtype.kind == "f":
            if arr.size and not np.all(np.isfinite(arr)):
                raise InvalidInputError("has NaN or infinite values", f"{name} is {dtype}", field=name)
            if arr.size and not np.array_equal(arr, np.round(arr)):
                raise InvalidInputError("has fractional values", f"{name} is stored as {dtype}", field=name)
        elif arr.dtype.kind not in "iu":
            raise InvalidInputError(f"dtype {arr.dtype} cannot become {dtype}", field=name)
        if arr.size:
            info = np.iinfo(dtype)
            lo, hi = arr.min(), arr.max()
            if lo < info.min or hi > info.max:
                raise InvalidInputError(
                    f"values {lo}..{hi} do not fit {dtype} ({info.min}..{info.max})",
                    "rescale the values or store them under another name",
                    field=name,
                )
        return arr.astype(dtype)
    return arr.astype(dtype)


class Cloud:
    """A point cloud: coordinates, per-point attributes, CRS, IO metadata and history.

    Parameters
    ----------
    xyz : (n, 3) array_like of float
        Absolute coordinates in the units of ``crs``; stored as float64.
    attrs : mapping of str to (n, ...) arrays, optional
        Per-point attributes under canonical names (see :mod:`workstation.core.dims`).
        Known dimensions are cast to their table dtype when the values fit, else an
        :class:`InvalidInputError` names the field.
    crs : str, optional
        WKT or ``"EPSG:code"``; None when unknown.
    meta : mapping, optional
        IO details for faithful round trips (LAS version, point format, scales, offsets, VLRs).
    history : iterable of HistoryRecord, optional

    Examples
    --------
    >>> c = Cloud(np.zeros((3, 3)), {"intensity": [1, 2, 3]})
    >>> len(c), c.attrs["intensity"].dtype
    (3, dtype('uint16'))
    >>> c2 = c.with_attrs(classification=np.full(3, 2))
    >>> sorted(c2.attrs), sorted(c.attrs)
    (['classification', 'intensity'], ['intensity'])
    >>> c2[c2.attrs["intensity"] > 1].xyz.shape
    (2, 3)
    """

    __slots__ = ("_xyz", "_attrs", "crs", "_meta", "history")

    def __init__(
        self,
        xyz,
        attrs: Mapping[str, Any] | None = None,
        crs: str | None = None,
        meta: Mapping[str, Any] | None = None,
        history: Iterable[HistoryRecord] = (),
        *,
        _trusted: bool = False,
    ):
        if _trusted:
            self._xyz = xyz
            self._attrs = dict(attrs or {})
        else:
            xyz = np.asarray(xyz, dtype=np.float64)
            if xyz.ndim != 2 or xyz.shape[1] != 3:
                raise InvalidInputError(f"xyz must have shape (n, 3), got {xyz.shape}", field="xyz")
            finite = np.isfinite(xyz).all(axis=1)
            if not finite.all():
                bad = np.flatnonzero(~finite)
                raise InvalidInputError(
                    f"{bad.size} point(s) have NaN or infinite coordinates (first at index {bad[0]})",
                    "drop or repair those points before building a cloud",
                    field="xyz",
                )
            n = xyz.shape[0]
            self._xyz = _readonly(xyz)
            self._attrs = {str(k): _coerce_attr(str(k), v, n) for k, v in (attrs or {}).items()}
        if crs is not None and not isinstance(crs, str):
            raise InvalidInputError(f"crs must be a WKT or 'EPSG:code' string, got {type(crs).__name__}", field="crs")
        self.crs = crs or None
        self._meta = MappingProxyType(dict(meta or {}))
        self.history = tuple(history)

    @classmethod
    def from_owned_arrays(cls, xyz: np.ndarray, attrs: Mapping[str, np.ndarray], crs=None, meta=None, history=()) -> "Cloud":
        """Build a cloud from arrays an IO reader has just made and owns (no copy, no scan).

        For readers whose formats cannot hold NaN coordinates (integer LAS coordinates) and
        which allocate arrays with the table dtypes: skips the validation pass over every
        point, checks shapes, and marks the arrays read-only in place.
        """
        n = xyz.shape[0]
        if xyz.dtype != np.float64 or xyz.shape != (n, 3):
            raise InvalidInputError(f"xyz must be (n, 3) float64, got {xyz.shape} {xyz.dtype}", field="xyz")
        for k, a in attrs.items():
            if a.shape[0] != n:
                raise InvalidInputError(f"has {a.shape[0]} values for {n} points", field=k)
            a.flags.writeable = False
        xyz.flags.writeable = False
        return cls(xyz, attrs, crs=crs, meta=meta, history=history, _trusted=True)

    # -- access -------------------------------------------------------------------------
    @property
    def xyz(self) -> np.ndarray:
        """(n, 3) float64, read-only."""
        return self._xyz

    @property
    def attrs(self) -> Mapping[str, np.ndarray]:
        """Read-only mapping of attribute name to read-only array."""
        return MappingProxyType(self._attrs)

    @property
    def meta(self) -> Mapping[str, Any]:
        return self._meta

    @property
    def n(self) -> int:
        return self._xyz.shape[0]

    def __len__(self) -> int:
        return self._xyz.shape[0]

    def __contains__(self, name: str) -> bool:
        return name in self._attrs

    def __repr__(self) -> str:
        return f"Cloud(n={self.n}, attrs={sorted(self._attrs)}, crs={'set' if self.crs else None})"

    @property
    def dims(self) -> list[str]:
        """Attribute names in insertion order."""
        return list(self._attrs)

    def get(self, name: str, default=None):
        return self._attrs.get(name, default)

    @property
    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """(min, max) corners as two (3,) arrays; raises on an empty cloud."""
        if self.n == 0:
            raise InvalidInputError("an empty cloud has no bounds", field="xyz")
        return self._xyz.min(axis=0), self._xyz.max(axis=0)

    # -- new clouds ---------------------------------------------------------------------
    def _derive(self, xyz=None, attrs=None, crs=..., meta=None, history=None, trusted=True) -> "Cloud":
        return Cloud(
            self._xyz if xyz is None else xyz,
            self._attrs if attrs is None else attrs,
            crs=self.crs if crs is ... else crs,
            meta=self._meta if meta is None else meta,
            history=self.history if history is None else history,
            _trusted=trusted,
        )

    def with_attrs(self, **attrs) -> "Cloud":
        """A new cloud with attributes added or replaced (validated like the constructor)."""
        new = dict(self._attrs)
        for k, v in attrs.items():
            new[k] = _coerce_attr(k, v, self.n)
        return self._derive(attrs=new)

    def without_attrs(self, *names: str) -> "Cloud":
        """A new cloud without the named attributes (missing names are ignored)."""
        return self._derive(attrs={k: v for k, v in self._attrs.items() if k not in names})

    def with_xyz(self, xyz) -> "Cloud":
        """A new cloud with other coordinates for the same points (validated)."""
        c = Cloud(xyz, crs=self.crs)
        if c.n != self.n:
            raise InvalidInputError(f"{c.n} coordinates for {self.n} points", field="xyz")
        return self._derive(xyz=c._xyz)

    def with_crs(self, crs: str | None) -> "Cloud":
        """The same points labelled with another CRS (no reprojection)."""
        return self._derive(crs=crs)

    def with_meta(self, **meta) -> "Cloud":
        new = dict(self._meta)
        new.update(meta)
        return self._derive(meta=new)

    def with_history(self, stage: str, params: Mapping[str, Any] | None = None, seconds: float | None = None) -> "Cloud":
        """A new cloud with one more history record."""
        rec = HistoryRecord(
            stage,
            dict(params or {}),
            _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds"),
            seconds,
        )
        return self._derive(history=(*self.history, rec))

    def __getitem__(self, key) -> "Cloud":
        """Select points by boolean mask, integer indices or slice; every attribute follows."""
        if isinstance(key, str):
            raise TypeError("use cloud.attrs[name] or cloud.xyz to read a field")
        if isinstance(key, slice):
            sel = key
        else:
            sel = np.asarray(key)
            if sel.dtype == bool:
                if sel.shape != (self.n,):
                    raise InvalidInputError(f"mask of shape {sel.shape} for {self.n} points", field="mask")
            elif sel.dtype.kind in "iu":
                if sel.ndim != 1:
                    raise InvalidInputError("indices must be one-dimensional", field="index")
                if sel.size and (sel.max() >= self.n or sel.min() < -self.n):
                    raise InvalidInputError(f"index out of range for {self.n} points", field="index")
            else:
                raise InvalidInputError(f"cannot select points with a {sel.dtype} array", field="index")
        return self._derive(
            xyz=_readonly(np.ascontiguousarray(self._xyz[sel])),
            attrs={k: _readonly(np.ascontiguousarray(v[sel])) for k, v in self._attrs.items()},
        )

    def to_dict(self) -> dict:
        """Plain dict of arrays (copies), for interop."""
        d = {"xyz": np.array(self._xyz)}
        d.update({k: np.array(v) for k, v in self._attrs.items()})
        return d


def _fill_value(name: str, dtype: np.dtype):
    if name not in DIMS and dtype.kind == "f":
        return np.nan
    return 0


def concatenate(clouds: Iterable[Cloud], check_crs: bool = True) -> Cloud:
    """Concatenate clouds; the attribute set is the union, missing values are filled.

    Missing known dimensions are filled with 0, missing free float attributes with NaN and
    missing free integer attributes with 0. The CRS must agree (None joins anything) unless
    ``check_crs`` is False. Metadata is taken from the first cloud.

    Examples
    --------
    >>> a = Cloud(np.zeros((2, 3)), {"intensity": [5, 6]})
    >>> b = Cloud(np.ones((1, 3)), {"classification": [2]})
    >>> c = concatenate([a, b])
    >>> c.attrs["intensity"].tolist(), c.attrs["classification"].tolist()
    ([5, 6, 0], [0, 0, 2])
    """
    clouds = list(clouds)
    if not clouds:
        raise InvalidInputError("nothing to concatenate", "pass at least one cloud")
    crs_set = {c.crs for c in clouds if c.crs}
    if check_crs and len(crs_set) > 1:
        raise InvalidInputError(
            f"clouds have {len(crs_set)} different CRSs", "reproject them to one CRS first (ws convert --to-crs)", field="crs"
        )
    names: dict[str, tuple[np.dtype, tuple]] = {}
    for c in clouds:
        for k, v in c.attrs.items():
            if k in names:
                dt, shp = names[k]
                if shp != v.shape[1:]:
                    raise InvalidInputError(f"per-point shapes {shp} and {v.shape[1:]} disagree", field=k)
                names[k] = (np.promote_types(dt, v.dtype), shp)
            else:
                names[k] = (v.dtype, v.shape[1:])
    xyz = np.concatenate([c.xyz for c in clouds], axis=0)
    attrs = {}
    for k, (dt, shp) in names.items():
        if k in DIMS:
            dt = DIMS[k].dtype
        parts = []
        for c in clouds:
            if k in c.attrs:
                parts.append(c.attrs[k].astype(dt, copy=False))
            else:
                parts.append(np.full((c.n, *shp), _fill_value(k, dt), dtype=dt))
        attrs[k] = np.concatenate(parts, axis=0)
    return Cloud(xyz, attrs, crs=next(iter(crs_set), None), meta=clouds[0].meta,
                 history=clouds[0].history)
