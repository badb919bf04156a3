"""Format dispatch: one table from file extension to reader/writer module.

Each format module provides ``read(path, **opts) -> Cloud`` and
``write(cloud, path, **opts) -> None`` (writing to the exact path it is given; atomicity and
overwrite checks are done here), and optionally ``iter_chunks(path, chunk_size, **opts)``.
"""

from __future__ import annotations

import importlib
import inspect
from pathlib import Path
from typing import Iterator

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, UnsupportedFormatError, WorkstationError

from .atomic import atomic_path

# extension -> (format name, module)
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


def _check_readable(path) -> Path:
    p = Path(path)
    if not p.exists():
        raise InvalidInputError("file not found", "check the path", path=p)
    if p.is_dir():
        raise InvalidInputError("is a folder, not a point cloud file", path=p)
    if p.stat().st_size == 0:
        raise InvalidInputError("file is empty (0 bytes)", "the file was not written completely; get it again", path=p)
    return p


def read_cloud(path, **opts) -> Cloud:
    """Read any supported point cloud file into a :class:`Cloud`.

    Parameters
    ----------
    path : path-like
        .las, .laz, .ply, .pcd, .xyz, .txt, .csv, .pts or .e57.
    **opts
        Format options (``columns="x,y,z,label"`` for text files, ``scans=[0]`` for E57, ...).
    """
    p = _check_readable(path)
    cloud = _guarded(p, _module(p).read, p, **opts)
    return cloud.with_meta(source=str(p), format=format_of(p)[0]) if "format" not in cloud.meta else cloud.with_meta(source=str(p))


def _reader_error(path: Path, exc: Exception) -> InvalidInputError:
    """The last safety net: an unexpected exception of a format reader, naming the file."""
    name = format_of(path)[0].upper()
    reason = f"{type(exc).__name__}: {exc}" if str(exc) else type(exc).__name__
    return InvalidInputError(f"cannot read as {name}: {reason}", "the file may be corrupt, truncated or not "
                             f"{name}; run with -v for the traceback", path=path)


def _guarded(path: Path, func, *args, **opts):
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


def write_cloud(cloud: Cloud, path, *, overwrite: bool = False, inputs=(), **opts) -> Path:
    """Write a cloud atomically; refuses to replace an existing file unless ``overwrite``."""
    mod = _module(path)
    with atomic_path(path, overwrite=overwrite, inputs=inputs) as tmp:
        mod.write(cloud, tmp, **opts)
    return Path(path)


def iter_chunks(path, chunk_size: int = 1_000_000, **opts) -> Iterator[Cloud]:
    """Stream a file as clouds of at most ``chunk_size`` points (true streaming for LAS/LAZ)."""
    p = _check_readable(path)
    mod = _module(p)
    if hasattr(mod, "iter_chunks"):
        chunks = _guarded(p, mod.iter_chunks, p, chunk_size, **opts)
        while True:
            chunk = _guarded(p, next, chunks, None)
            if chunk is None:
                return
            yield chunk
    cloud = _guarded(p, mod.read, p, **opts)
    for start in range(0, max(cloud.n, 1), chunk_size):
        yield cloud[start : start + chunk_size]
