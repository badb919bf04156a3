"""Safe outputs: refuse to overwrite without permission, write to a temporary file, rename.

Every product writer goes through :func:`atomic_path`, so a failure never leaves a
half-written file and an existing output is replaced only when asked.
"""

from __future__ import annotations

import contextlib
import errno
import os
import tempfile
from pathlib import Path
from typing import Iterator

from workstation.core.errors import InvalidInputError, OutputExistsError, doing


def check_output(path, overwrite: bool = False, inputs=()) -> Path:
    """Validate an output path: not an input, not existing unless ``overwrite``, folder exists.

    Raises
    ------
    OutputExistsError
        When the file exists and ``overwrite`` is False.
    InvalidInputError
        When the output is one of the inputs or its folder does not exist.
    """
    p = Path(path)
    from .copc import refuse_copc_output

    refuse_copc_output(p)
    for i in inputs:
        try:
            same = Path(i).exists() and p.exists() and os.path.samefile(i, p)
        except OSError:
            same = False
        if same or Path(i).resolve() == p.resolve():
            raise InvalidInputError(
                "output is the same file as an input", "write to a new file; inputs are never modified", path=p
            )
    if p.exists() and not overwrite:
        raise OutputExistsError(p)
    if p.exists() and p.is_dir():
        raise InvalidInputError("output is a folder", "give a file name", path=p)
    if p.exists() and not p.is_file():
        raise InvalidInputError("output exists and is not a regular file (a device or a pipe)",
                                "give a file name", path=p)
    if not p.parent.exists():
        raise InvalidInputError(f"folder {p.parent} does not exist", "create it first", path=p)
    return p


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def _disk_full(folder: Path, margin: int = 1 << 20) -> bool:
    """Whether the file system of ``folder`` has less than ``margin`` bytes left."""
    try:
        st = os.statvfs(folder)
    except OSError:
        return False
    return st.f_bavail * st.f_frsize < margin


def _publish(tmp: Path, final: Path, overwrite: bool) -> None:
    """Give the finished temporary file normal permissions (mkstemp makes it 0600) and move it
    onto ``final``. Without ``overwrite`` the move is a hard link, which fails if ``final``
    exists, so of two processes writing the same new output exactly one wins."""
    os.chmod(tmp, 0o666 & ~_umask())
    if overwrite:
        os.replace(tmp, final)
        return
    try:
        os.link(tmp, final)
    except FileExistsError:
        raise OutputExistsError(final, "another process wrote it meanwhile; pass --overwrite to replace it") from None
    except OSError as exc:  # a file system without hard links: check, then rename
        if exc.errno not in (errno.EPERM, errno.EOPNOTSUPP, errno.EXDEV, errno.EMLINK):
            raise
        if final.exists():
            raise OutputExistsError(final) from None
        os.replace(tmp, final)
        return
    tmp.unlink()


def check_outputs(paths, overwrite: bool = False, inputs=()) -> list[Path]:
    """:func:`check_output` for every output of a command (``None`` entries skipped), and
    no two of them the same file: run it before any work so a bad ``--png`` path fails first."""
    checked = [check_output(p, overwrite, inputs) for p in paths if p is not None]
    seen: dict[Path, Path] = {}
    for p in checked:
        key = p.resolve()
        if key in seen:
            raise InvalidInputError("the same file is given for two outputs", "give each output its own name", path=p)
        seen[key] = p
    return checked


@contextlib.contextmanager
def atomic_path(path, overwrite: bool = False, inputs=()) -> Iterator[Path]:
    """Yield a temporary path beside ``path``; rename it onto ``path`` if the block succeeds.

    The temporary file keeps the output's suffix so writers that dispatch on it work.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> d = pathlib.Path(tempfile.mkdtemp())
    >>> with atomic_path(d / "a.txt") as tmp:
    ...     _ = tmp.write_text("hello")
    >>> (d / "a.txt").read_text()
    'hello'
    """
    p = check_output(path, overwrite, inputs)
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{p.stem}.", suffix="".join(p.suffixes) or ".tmp", dir=p.parent)
    except OSError as exc:  # a read-only or full folder: name the output, not the temporary file
        raise OSError(exc.errno, exc.strerror, str(p)) from None
    os.close(fd)
    tmp_path = Path(tmp)
    try:
        with doing(f"writing {p}"):
            try:
                yield tmp_path
            except OSError as exc:
                if exc.filename is None:  # e.g. a full disk seen by a library's writer: name the output
                    raise OSError(exc.errno, exc.strerror or str(exc), str(p)) from exc
                raise
            except Exception as exc:
                if _disk_full(p.parent):  # a library's own I/O error (lazrs, GDAL) on a full disk
                    raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(p)) from exc
                raise
            _publish(tmp_path, p, overwrite)
    finally:
        if tmp_path.exists():
            tmp_path.unlink()


@contextlib.contextmanager
def atomic_paths(paths, overwrite: bool = False, inputs=()) -> Iterator[list[Path]]:
    """:func:`atomic_path` for several outputs written together (a GeoTIFF and its PNG):
    all are checked first and published only when the whole block succeeds."""
    check_outputs(paths, overwrite, inputs)
    with contextlib.ExitStack() as stack:
        yield [stack.enter_context(atomic_path(p, overwrite, inputs)) for p in paths]


@contextlib.contextmanager
def atomic_dir(path, overwrite: bool = False) -> Iterator[Path]:
    """Like :func:`atomic_path` for an output folder: build it beside, then swap it in."""
    import shutil

    p = Path(path)
    if p.exists() and not overwrite:
        raise OutputExistsError(p)
    p.parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{p.name}.", dir=p.parent))
    try:
        yield tmp
        if p.exists():
            shutil.rmtree(p) if p.is_dir() else p.unlink()
        os.chmod(tmp, 0o777 & ~_umask())
        os.replace(tmp, p)
    finally:
        if tmp.exists():
            shutil.rmtree(tmp, ignore_errors=True)


@contextlib.contextmanager
def work_folder(path) -> Iterator[Path]:
    """Make the output folder ``path`` (and missing parents) for the block. If the block fails
    or is interrupted, what it created is removed: the folders this call made, or else the
    entries that appeared in an existing folder during the block. So a failed run leaves the
    folder as it was, and a re-run does not stop at "output exists"."""
    import shutil

    p = Path(path)
    if p.exists() and not p.is_dir():
        raise InvalidInputError("exists and is not a folder", "give a folder path", path=p)
    top = next((q for q in [p, *p.parents][::-1] if not q.exists()), None)  # outermost folder made here
    before = set(p.iterdir()) if top is None else set()
    p.mkdir(parents=True, exist_ok=True)
    try:
        yield p
    except BaseException:
        if top is not None:
            shutil.rmtree(top, ignore_errors=True)
        elif p.is_dir():
            for q in set(p.iterdir()) - before:
                shutil.rmtree(q, ignore_errors=True) if q.is_dir() and not q.is_symlink() else q.unlink(missing_ok=True)
        raise
