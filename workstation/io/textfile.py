"""Reading a user's small text file (JSON, TOML, CSV of pairs or control points) as UTF-8."""

from __future__ import annotations

from pathlib import Path

from ._fields import check_utf8


def read_text(path) -> str:
    """The text of ``path``; an :class:`~workstation.core.errors.InvalidInputError` naming the
    file, line and byte when it is not UTF-8 (a byte-order mark is allowed and dropped)."""
    data = Path(path).read_bytes()
    check_utf8(data, path)
    return data.decode("utf-8-sig")
