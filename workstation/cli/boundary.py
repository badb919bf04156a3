"""The error boundary of every command: an exception becomes a message, a hint and an exit code.

Expected failures (bad input, a full disk, a read-only folder, a library refusing the data)
print ``Error: ...`` naming the file, option or stage and ``Hint: ...`` saying what to do,
and exit 1. Anything else is a bug in workstation: it says so and how to report it. A
traceback is printed only with ``-v``. :func:`explain` is the classification; the CLI's
``main`` calls :func:`report`.
"""

from __future__ import annotations

import contextlib
import errno
import sys
from dataclasses import dataclass
from pathlib import Path

import click

# Libraries whose exceptions mean "this data or this request cannot be processed", not a bug
# in workstation. Matched on the top-level module of the exception's class.
LIBRARIES = {
    "laspy": "laspy (LAS/LAZ)", "lazrs": "lazrs (LAZ)", "rasterio": "rasterio (GeoTIFF)",
    "pyproj": "pyproj (CRS)", "open3d": "Open3D", "pymeshlab": "PyMeshLab",
    "pycolmap": "pycolmap (COLMAP)", "torch": "PyTorch", "PIL": "Pillow (images)",
    "cv2": "OpenCV", "pye57": "pye57 (E57)", "scipy": "SciPy", "copclib": "copclib",
    "pyo3_runtime": "a Rust library (lazrs, LAZ)",
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

    if isinstance(exc, WorkstationError):  # it names its file, or the block it came from does
        named = getattr(exc, "path", None) is not None
        return Explained(exc.message + ("" if named else _where(exc)), exc.hint)
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
        "project's issue tracker with the command line and the output of the same command run with -v"
    )


def command_inputs(argv) -> str | None:
    """``"ws ground on a.laz"``: the command and the existing files of its command line that
    are not output options' values, to label an error that names no file."""
    words = [a for a in argv if not a.startswith("-")]
    outputs = {argv[i + 1] for i, a in enumerate(argv[:-1])
               if a.startswith("-") and (a == "-o" or "out" in a or a in ("--png", "--plot-dir", "--save-scene"))}
    files = [a for a in words[1:] if a not in outputs and Path(a).exists()]
    if not words or not files:
        return None
    return f"running ws {words[0]} on {', '.join(files[:4])}"


def report(exc: BaseException, verbose: bool, argv=()) -> int:
    """Print the explanation of ``exc`` on stderr (with the traceback if ``verbose``); exit code 1.
    An error that names no file is labelled with the command's input files (``argv``)."""
    if getattr(exc, "ws_doing", None) is None and argv:
        with contextlib.suppress(AttributeError, TypeError):
            exc.ws_doing = command_inputs(list(argv))
    if verbose:
        import traceback

        traceback.print_exception(exc, file=sys.stderr)
    e = explain(exc)
    click.echo(f"Error: {e.message}", err=True)
    if e.hint:
        click.echo(f"Hint: {e.hint}", err=True)
    return 1
