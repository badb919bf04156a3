"""The error boundary of every command: an exception becomes a message, a hint and an exit code.

Expected failures (bad input, a full disk, a read-only folder, a library refusing the data)
print ``Error: ...`` naming the file, option or stage and ``Hint: ...`` saying what to do,
and exit 1. Anything else is a bug in workstation: it says so and how to report it. A
traceback is printed only with ``-v``. :func:`explain` is the classification; the CLI's
``main`` calls :func:`report`.
"""

from __future__ import annotations

import errno
import sys
from dataclasses import dataclass

import click

# Libraries whose exceptions mean "this data or this request cannot be processed", not a bug
# in workstation. Matched on the top-level module of the exception's class.
LIBRARIES = {
    "laspy": "laspy (LAS/LAZ)", "lazrs": "lazrs (LAZ)", "rasterio": "rasterio (GeoTIFF)",
    "pyproj": "pyproj (CRS)", "open3d": "Open3D", "pymeshlab": "PyMeshLab",
    "pycolmap": "pycolmap (COLMAP)", "torch": "PyTorch", "PIL": "Pillow (images)",
    "cv2": "OpenCV", "pye57": "pye57 (E57)", "scipy": "SciPy", "copclib": "copclib",
}

_OS_HINTS = {
    errno.ENOSPC: ("no space left on the device", "free some space or write the output to another disk"),
    errno.EDQUOT: ("disk quota exceeded", "free some space or write the output elsewhere"),
    errno.EROFS: ("the file system is read-only", "write the output to a writable folder"),
    errno.EACCES: ("permission denied", "check the file's permissions or write elsewhere"),
    errno.EPERM: ("operation not permitted", "check the file's permissions or write elsewhere"),
    errno.ENOENT: ("no such file or folder", "check the path"),
    errno.EISDIR: ("is a folder, a file was expected", "give a file path"),
    errno.ENOTDIR: ("a part of the path is not a folder", "check the path"),
    errno.EMFILE: ("too many open files", "raise the limit (ulimit -n) or process fewer files at once"),
    errno.ENAMETOOLONG: ("file name too long", "use a shorter path"),
}


@dataclass(frozen=True)
class Explained:
    """What the user is told about an exception."""

    message: str
    hint: str | None = None
    bug: bool = False


def _where(exc: BaseException) -> str:
    """' (while reading X)' from the innermost :func:`workstation.core.errors.doing` block."""
    doing = getattr(exc, "ws_doing", None)
    return f" (while {doing})" if doing else ""


def _os_error(exc: OSError) -> Explained:
    what, hint = _OS_HINTS.get(exc.errno, (exc.strerror or str(exc), None))
    name = exc.filename if exc.filename is not None else None
    prefix = f"{name}: " if name is not None else ""
    return Explained(f"{prefix}{what}{_where(exc) if name is None else ''}", hint)


def explain(exc: BaseException) -> Explained:
    """Classify ``exc``: a deliberate error, an expected failure class, or a bug."""
    from workstation.core.errors import WorkstationError

    if isinstance(exc, WorkstationError):
        return Explained(exc.message, exc.hint)
    if isinstance(exc, OSError):
        return _os_error(exc)
    if isinstance(exc, UnicodeError):
        return Explained(f"text is not valid UTF-8{_where(exc)}: {exc}", "save the file as UTF-8 text")
    if isinstance(exc, MemoryError):
        return Explained(f"out of memory{_where(exc)}",
                         "process smaller pieces (tiles, --chunk-size) or a coarser cell, or use a bigger machine")
    lib = LIBRARIES.get(type(exc).__module__.split(".")[0])
    if lib is not None:
        writing = str(getattr(exc, "ws_doing", "")).startswith("writing")
        return Explained(f"{lib} could not {'write' if writing else 'process'} the data{_where(exc)}: {exc}",
                         "check the free space and permissions of the output folder" if writing else
                         "check the input file; run with -v for the library's traceback")
    return Explained(
        f"internal error{_where(exc)}: {type(exc).__name__}: {exc}",
        "this is a bug in workstation, not in your data or options. Please report it on the "
        "project's issue tracker with the command line and the output of the same command run with -v",
        bug=True,
    )


def report(exc: BaseException, verbose: bool) -> int:
    """Print the explanation of ``exc`` on stderr (with the traceback if ``verbose``); exit code 1."""
    if verbose:
        import traceback

        traceback.print_exception(exc, file=sys.stderr)
    e = explain(exc)
    click.echo(f"Error: {e.message}", err=True)
    if e.hint:
        click.echo(f"Hint: {e.hint}", err=True)
    return 1
