"""Logging: the library logs to the ``workstation`` logger; the CLI decides where it goes."""

from __future__ import annotations

import logging

logger = logging.getLogger("workstation")
logger.addHandler(logging.NullHandler())

_quiet = False


def is_quiet() -> bool:
    """True after ``configure(quiet=True)`` (``ws -q``): no progress and no summary lines."""
    return _quiet


def get_logger(name: str) -> logging.Logger:
    """Child logger of ``workstation`` (pass ``__name__``)."""
    return logging.getLogger(name if name.startswith("workstation") else f"workstation.{name}")


def configure(verbosity: int = 0, quiet: bool = False) -> None:
    """Send package logs to stderr through rich: WARNING by default, INFO with -v, DEBUG with -vv."""
    global _quiet
    _quiet = bool(quiet)
    level = logging.ERROR if quiet else (logging.WARNING, logging.INFO, logging.DEBUG)[min(verbosity, 2)]
    try:
        from rich.logging import RichHandler

        from workstation.core.progress import stderr_console

        handler: logging.Handler = RichHandler(console=stderr_console(), show_path=False, show_time=False)
    except ImportError:  # pragma: no cover - rich is a dependency
        handler = logging.StreamHandler()
    for h in list(logger.handlers):
        if not isinstance(h, logging.NullHandler):
            logger.removeHandler(h)
    logger.addHandler(handler)
    logger.setLevel(level)
