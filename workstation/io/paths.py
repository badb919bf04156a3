"""Paths written inside files (image paths in a cameras JSON or a COLMAP model, input patterns
in a project TOML) are resolved inside the folder of the file that names them.

A file someone else made must not make the workstation read ``../../home/x/.ssh`` or
``/etc/passwd``: a path that leaves its folder is refused unless the user said it may,
with ``--allow-outside`` (which sets :data:`ALLOW_OUTSIDE` for the command).
"""

from __future__ import annotations

import contextvars
import os
from pathlib import Path

from workstation.core.errors import InvalidInputError

ALLOW_OUTSIDE: contextvars.ContextVar[bool] = contextvars.ContextVar("allow_outside", default=False)

HINT = "move the files into that folder, or pass --allow-outside if you trust this file"


def is_inside(path, folder) -> bool:
    """Whether ``path`` lies in ``folder`` once ``..`` is resolved. The test is on the names, not
    on links: a link put in the folder is the folder owner's choice, a ``..`` in a file is not."""
    try:
        Path(os.path.abspath(path)).relative_to(os.path.abspath(folder))
    except ValueError:
        return False
    return True


def resolve_inside(ref, folder, *, source, field: str) -> Path:
    """``folder / ref`` resolved; an error naming ``source`` and ``field`` if it leaves ``folder``.

    Parameters
    ----------
    ref : str or Path
        The path as written in the file (relative to ``folder``, or absolute).
    folder : Path
        The folder the path must stay in (usually the file's own folder).
    source : Path
        The file that holds ``ref``, named in the error.
    field : str
        Where in ``source`` the path is (``images.3.path``), named in the error.

    Examples
    --------
    >>> resolve_inside("img/a.jpg", "/data/job", source="/data/job/cameras.json", field="path").as_posix()
    '/data/job/img/a.jpg'
    >>> resolve_inside("../../etc/passwd", "/data/job", source="cameras.json", field="path")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    workstation.core.errors.InvalidInputError: cameras.json: field 'path': ...
    """
    p = Path(folder) / ref
    if ALLOW_OUTSIDE.get() or is_inside(p, folder):
        return Path(os.path.normpath(p))
    raise InvalidInputError(f"the path {str(ref)!r} leads outside {folder}", HINT, path=source, field=field)
