"""Safe outputs: refuse to overwrite without permission, write to a temporary file, rename.

Every product writer goes through :func:`atomic_path`, so a failure never leaves a
half-written file and an existing output is replaced only when asked.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path
from typing import Iterator

from workstation.core.errors import InvalidInputError, OutputExistsError


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
    if not p.parent.exists():
        raise InvalidInputError(f"folder {p.parent} does not exist", "create it first", path=p)
    return p


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def _publish(tmp: Path, final: Path) -> None:
    """Give the finished temporary file normal permissions (mkstemp makes it 0600) and rename."""
    os.chmod(tmp, 0o666 & ~_umask())
    os.replace(tmp, final)


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
    fd, tmp = tempfile.mkstemp(prefix=f".{p.stem}.", suffix="".join(p.suffixes) or ".tmp", dir=p.parent)
    os.close(fd)
    tmp_path = Path(tmp)
    try:
        yield tmp_path
        _publish(tmp_path, p)
    finally:
        if tmp_path.exists():
            tmp_path.unlink()


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
