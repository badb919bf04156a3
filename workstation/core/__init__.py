"""Core types (numpy only): Cloud, the dimension table, ASPRS classes, products, errors.

The names below load their module on first use (PEP 562), so that importing a light submodule
(``workstation.core.signals``, ``workstation.core.errors``) does not import numpy: ``ws --help``
stays fast.
"""

import importlib

_EXPORTS = {
    "ASPRSClass": "classes", "class_name": "classes",
    "Cloud": "cloud", "HistoryRecord": "cloud", "concatenate": "cloud",
    "DIMS": "dims", "Dim": "dims", "canonical_name": "dims",
    "InvalidInputError": "errors", "MissingDependencyError": "errors", "NotFittedError": "errors",
    "OutputExistsError": "errors", "StageError": "errors", "UnsupportedFormatError": "errors",
    "WorkstationError": "errors",
}

__all__ = list(_EXPORTS)


def __getattr__(name: str):
    if name in _EXPORTS:
        return getattr(importlib.import_module(f"{__name__}.{_EXPORTS[name]}"), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
