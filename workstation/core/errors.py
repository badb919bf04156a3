"""The error hierarchy.

Every error the package raises on purpose is a :class:`WorkstationError` and also the
built-in a Python user would catch (``ValueError``, ``ImportError``, ``RuntimeError``,
``FileExistsError``), so ``except ValueError`` keeps working. Each says what went wrong,
where (file, field, stage) and what to do (``hint``).
"""

from __future__ import annotations

import contextlib
from typing import Iterator


class WorkstationError(Exception):
    """Base class of every deliberate error of the package.

    Parameters
    ----------
    message : str
        What went wrong, naming the file, field or stage.
    hint : str, optional
        What the user can do about it.
    """

    def __init__(self, message: str, hint: str | None = None):
        self.message = message
        self.hint = hint
        super().__init__(message if not hint else f"{message} (hint: {hint})")


class InvalidInputError(WorkstationError, ValueError):
    """Input data or arguments that cannot be used as given."""

    def __init__(self, message: str, hint: str | None = None, *, path=None, field: str | None = None):
        self.path = None if path is None else str(path)
        self.field = field
        prefix = ""
        if self.path is not None:
            prefix += f"{self.path}: "
        if field is not None:
            prefix += f"field '{field}': "
        super().__init__(prefix + message, hint)


class UnsupportedFormatError(InvalidInputError):
    """A file extension or format variant the IO layer does not handle."""


class OutputExistsError(WorkstationError, FileExistsError):
    """An output file exists and ``overwrite`` was not given."""

    def __init__(self, path, hint: str = "pass --overwrite (overwrite=True) to replace it"):
        self.path = str(path)
        super().__init__(f"{path}: output exists", hint)


class MissingDependencyError(WorkstationError, ImportError):
    """An optional heavy library is not installed; the hint is the install command."""

    def __init__(self, package: str, purpose: str, install: str | None = None):
        self.package = package
        super().__init__(
            f"{package} is needed for {purpose} but is not installed",
            install or f"pip install {package}",
        )


class StageError(WorkstationError, RuntimeError):
    """A stage ran but its result fails a post-condition (empty, not converged, ...)."""

    def __init__(self, stage: str, message: str, hint: str | None = None):
        self.stage = stage
        super().__init__(f"{stage}: {message}", hint)


class NotFittedError(WorkstationError, ValueError, AttributeError):
    """A model was used before ``fit`` or ``load``."""


@contextlib.contextmanager
def doing(what: str) -> Iterator[None]:
    """Label the work of the block (``"reading a.laz"``) on any exception escaping it.

    The CLI's error boundary adds the innermost label to messages that would not name the
    file otherwise (a library error, a full disk, text that is not UTF-8).

    Examples
    --------
    >>> try:
    ...     with doing("reading a.laz"):
    ...         raise ValueError("bad")
    ... except ValueError as e:
    ...     e.ws_doing
    'reading a.laz'
    """
    try:
        yield
    except Exception as exc:
        if getattr(exc, "ws_doing", None) is None:
            with contextlib.suppress(AttributeError, TypeError):
                exc.ws_doing = what
        raise


def is_library_panic(exc: BaseException) -> bool:
    """Whether ``exc`` is a Rust library's panic surfacing in Python (pyo3's ``PanicException``,
    raised by lazrs on some damaged LAZ files). It derives from ``BaseException``, so
    ``except Exception`` does not see it."""
    return type(exc).__name__ == "PanicException"
