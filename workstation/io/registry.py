"""Format dispatch: one table from file extension to reader/writer module.

Each format module provides ``read(path, **opts) -> Cloud`` and
``write(cloud, path, **opts) -> None`` (writing to the exact path it is given; atomicity and
overwrite checks are done here), and optionally ``iter_chunks(path, chunk_size, **opts)``.
"""

from __future__ import annotations

import importlib
import inspect
import math
from pathlib import Path
from typing import Iterator

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, UnsupportedFormatError, WorkstationError, is_library_panic
from workstation.core.log import get_logger

from .atomic import atomic_path

#: Files whose CRS was already checked against their coordinates (path, mtime, size): the
#: warning of :func:`warn_crs` is shown once per file per process.
_CRS_CHECKED: set = set()

# extension -> (format name, module)
log = get_logger(__name__)

FORMATS: dict[str, tuple[str, str]] = {
    ".las": ("las", "workstation.io.las"),
    ".laz": ("laz", "workstation.io.las"),
    ".ply": ("ply", "workstation.io.ply"),
    ".pcd": ("pcd", "workstation.io.pcd"),
    ".xyz": ("xyz", "workstation.io.text"),
    ".txt": ("txt", "workstation.io.text"),
    ".csv": ("csv", "workstation.io.text"),
    ".pts": ("pts", "workstation.io.text"),
    ".e57": ("e57", "workstation.io.e57"),
}


def format_of(path) -> tuple[str, str]:
    """(format name, module) for a path, from its extension."""
    ext = Path(path).suffix.lower()
    if ext not in FORMATS:
        raise UnsupportedFormatError(
            f"unknown point cloud extension '{ext or '(none)'}'",
            "use one of " + ", ".join(sorted(FORMATS)),
            path=path,
        )
    return FORMATS[ext]


def _module(path):
    return importlib.import_module(format_of(path)[1])


def check_readable(path) -> Path:
    p = Path(path)
    if not p.exists():
        raise InvalidInputError("file not found", "check the path", path=p)
    if p.is_dir():
        raise InvalidInputError("is a folder, not a point cloud file", path=p)
    if p.stat().st_size == 0:
        raise InvalidInputError("file is empty (0 bytes)", "the file was not written completely; get it again", path=p)
    return p


def _check_bounds(bounds) -> tuple[float, ...]:
    """``bounds`` as (xmin, ymin, xmax, ymax[, zmin, zmax]) floats, each min <= its max."""
    try:
        b = tuple(float(v) for v in bounds)
    except (TypeError, ValueError):
        b = ()
    if len(b) not in (4, 6) or not all(math.isfinite(v) for v in b):
        raise InvalidInputError(f"bounds {bounds!r} are not 4 or 6 finite numbers",
                                "give xmin,ymin,xmax,ymax or xmin,ymin,xmax,ymax,zmin,zmax", field="--bounds")
    pairs = [(0, 2), (1, 3), (4, 5)][: len(b) // 2]
    for (lo, hi), axis in zip(pairs, "xyz"):
        if b[lo] > b[hi]:
            raise InvalidInputError(f"bounds {axis}min {b[lo]:g} is greater than {axis}max {b[hi]:g}",
                                    "give xmin,ymin,xmax,ymax[,zmin,zmax] with each min first", field="--bounds")
    return b


def check_selection(path, bounds=None, resolution=None, level=None) -> dict | None:
    """The reading options ``--bounds``/``--resolution``/``--level`` checked against ``path``:
    None when none is given, else {copc, bounds, resolution, level}.

    Resolution and level pick levels of a COPC octree; other files have none to pick from.
    """
    if bounds is None and resolution is None and level is None:
        return None
    from . import copc

    copc_file = format_of(path)[0] == "laz" and copc.is_copc(path)
    if (resolution is not None or level is not None) and not copc_file:
        flag = "--resolution" if resolution is not None else "--level"
        raise InvalidInputError(f"{flag} reads a level of detail of a COPC file; this file is not COPC (it has no octree)",
                                "use --bounds alone (any file), or read a .copc.laz (`ws convert IN OUT.copc.laz`, PDAL writers.copc, untwine)",
                                path=path, field=flag)
    if resolution is not None and not (math.isfinite(resolution) and resolution > 0):
        raise InvalidInputError(f"resolution {resolution!r} must be a positive length", field="--resolution")
    if level is not None and int(level) < 0:
        raise InvalidInputError(f"level {level!r} must be 0 (the root) or more", field="--level")
    return {"copc": copc_file, "bounds": None if bounds is None else _check_bounds(bounds),
            "resolution": resolution, "level": level}


def inside_bounds(cloud: Cloud, bounds) -> Cloud:
    """The points of ``cloud`` inside ``bounds`` (inclusive on floats; formats without integer
    coordinates)."""
    b = np.asarray(bounds)
    half = len(b) // 2
    lo, hi = b[[0, 1, 4][:half]], b[[2, 3, 5][:half]]
    xyz = cloud.xyz[:, :half]
    return cloud[np.all((xyz >= lo) & (xyz <= hi), axis=1)]


def _read_selected(path: Path, sel: dict, **opts) -> Cloud:
    """Read what ``sel`` (:func:`check_selection`) asks: a COPC query, a streamed bounds filter
    of a LAS/LAZ file, or a whole read then a bounds filter for the other formats."""
    if sel["copc"]:
        from . import copc

        return copc.read(path, sel["bounds"], sel["resolution"], sel["level"])
    mod = _module(path)
    if mod.__name__ == "workstation.io.las":
        return mod.read(path, bounds=sel["bounds"], **opts)
    return inside_bounds(mod.read(path, **opts), sel["bounds"])


def read_cloud(path, *, bounds=None, resolution=None, level=None, **opts) -> Cloud:
    """Read any supported point cloud file into a :class:`Cloud`.

    Parameters
    ----------
    path : path-like
        .las, .laz, .ply, .pcd, .xyz, .txt, .csv, .pts or .e57.
    bounds : (4,) or (6,) floats, optional
        Only the points inside (xmin, ymin, xmax, ymax[, zmin, zmax]), inclusive: a COPC file is
        queried through its octree, a LAS/LAZ file streamed and filtered chunk by chunk.
    resolution : float, optional
        COPC only: the octree levels down to this point spacing (CRS units).
    level : int, optional
        COPC only: octree levels 0..level (0 is the root).
    **opts
        Format options (``columns="x,y,z,label"`` for text files, ``scans=[0]`` for E57, ...).
    """
    p = check_readable(path)
    sel = check_selection(p, bounds, resolution, level)
    if sel is None:
        cloud = guarded(p, _module(p).read, p, **opts)
    else:
        cloud = guarded(p, _read_selected, p, sel, **opts)
        if cloud.n == 0 and sel["bounds"] is not None:
            raise InvalidInputError(f"no points inside --bounds {','.join(f'{v:g}' for v in sel['bounds'])}",
                                    "compare the box with the file's bounds (ws info --summary FILE)", path=p,
                                    field="--bounds")
    warn_crs(p, cloud)
    return cloud.with_meta(source=str(p), format=format_of(p)[0]) if "format" not in cloud.meta else cloud.with_meta(source=str(p))


def _crs_key(path: Path) -> tuple:
    st = path.stat()
    return str(path.resolve()), st.st_mtime_ns, st.st_size


def crs_checked(path) -> None:
    """Mark ``path`` as having its CRS warnings shown by the caller (``ws info`` prints them in
    its report), so reading it does not repeat them on stderr. A missing file is left to the reader."""
    try:
        _CRS_CHECKED.add(_crs_key(Path(path)))
    except OSError:
        pass


def _file_extent(path: Path, cloud: Cloud):
    """(min, max) of the file's coordinates in CRS units: its LAS/LAZ header's (the whole file,
    no point read), else the points of ``cloud``."""
    if format_of(path)[0] in ("las", "laz"):
        import laspy

        with laspy.open(str(path)) as r:
            return np.asarray(r.header.mins, float), np.asarray(r.header.maxs, float)
    return cloud.xyz.min(axis=0), cloud.xyz.max(axis=0)


def warn_crs(path: Path, cloud: Cloud) -> None:
    """Log, once per file, why its CRS does not fit its coordinates
    (:func:`workstation.io.crs.crs_warnings`: degrees on 1e6 coordinates, a geocentric CRS on
    eastings ...). A warning only: a failure of the check itself is logged at debug level."""
    if not cloud.crs or cloud.n == 0:
        return
    try:
        key = _crs_key(path)
        if key in _CRS_CHECKED:
            return
        _CRS_CHECKED.add(key)
        from .crs import crs_warnings

        msgs = crs_warnings(cloud.crs, _file_extent(path, cloud))
    except Exception as exc:  # noqa: BLE001 - a plausibility check must never stop a read
        log.debug("CRS check of %s skipped: %s", path, exc)
        return
    for m in msgs:
        log.warning("%s: %s", path.name, m)


def _reader_error(path: Path, exc: Exception) -> InvalidInputError:
    """The last safety net: an unexpected exception of a format reader, naming the file."""
    name = format_of(path)[0].upper()
    reason = f"{type(exc).__name__}: {exc}" if str(exc) else type(exc).__name__
    return InvalidInputError(f"cannot read as {name}: {reason}", "the file may be corrupt, truncated or not "
                             f"{name}; run with -v for the traceback", path=path)


def guarded(path: Path, func, *args, **opts):
    """``func(*args, **opts)`` with any exception that is not one of ours wrapped by :func:`_reader_error`.

    Options a reader does not take still raise ``TypeError`` (a caller's mistake, not the file's).
    """
    if func is not next:
        inspect.signature(func).bind(*args, **opts)
    try:
        return func(*args, **opts)
    except WorkstationError:
        raise
    except Exception as exc:  # noqa: BLE001 - a reader bug or a library error on a malformed file
        raise _reader_error(path, exc) from exc
    except BaseException as exc:  # a Rust panic in lazrs (pyo3 PanicException) on a damaged LAZ
        if not is_library_panic(exc):
            raise
        raise _reader_error(path, exc) from exc


def write_cloud(cloud: Cloud, path, *, overwrite: bool = False, inputs=(), **opts) -> Path:
    """Write a cloud atomically; refuses to replace an existing file unless ``overwrite``, and
    refuses ``.copc.laz`` names (a plain LAZ would claim an octree; COPC is written by
    :func:`workstation.publish.copc.save_copc`; checked by :func:`~workstation.io.atomic.check_output`)."""
    mod = _module(path)
    with atomic_path(path, overwrite=overwrite, inputs=inputs) as tmp:
        mod.write(cloud, tmp, **opts)
    return Path(path)


def iter_chunks(path, chunk_size: int = 1_000_000, *, bounds=None, resolution=None, level=None,
                **opts) -> Iterator[Cloud]:
    """Stream a file as clouds of at most ``chunk_size`` points (true streaming for LAS/LAZ).

    ``bounds``/``resolution``/``level`` select points as in :func:`read_cloud` (chunks may then
    be empty; a COPC query's result is held, then cut into chunks).
    """
    p = check_readable(path)
    sel = check_selection(p, bounds, resolution, level)
    checked = False
    for chunk in _chunks(p, sel, chunk_size, **opts):
        if not checked and chunk.n:
            warn_crs(p, chunk)
            checked = True
        yield chunk


def _chunks(p: Path, sel: dict | None, chunk_size: int, **opts) -> Iterator[Cloud]:
    """The chunks of :func:`iter_chunks` (``sel`` from :func:`check_selection`)."""
    mod = _module(p)
    if sel is not None and not sel["copc"] and mod.__name__ == "workstation.io.las":
        opts["bounds"] = sel["bounds"]
    elif sel is not None:
        cloud = guarded(p, _read_selected, p, sel, **opts)
        for start in range(0, max(cloud.n, 1), chunk_size):
            yield cloud[start : start + chunk_size]
        return
    if hasattr(mod, "iter_chunks"):
        chunks = guarded(p, mod.iter_chunks, p, chunk_size, **opts)
        while True:
            chunk = guarded(p, next, chunks, None)
            if chunk is None:
                return
            yield chunk
    cloud = guarded(p, mod.read, p, **opts)
    for start in range(0, max(cloud.n, 1), chunk_size):
        yield cloud[start : start + chunk_size]
