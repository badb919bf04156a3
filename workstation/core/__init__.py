"""Core types (numpy only): Cloud, the dimension table, ASPRS classes, products, errors."""

from .classes import ASPRSClass, class_name
from .cloud import Cloud, HistoryRecord, concatenate
from .dims import DIMS, Dim, canonical_name
from .errors import (
    InvalidInputError,
    MissingDependencyError,
    NotFittedError,
    OutputExistsError,
    StageError,
    UnsupportedFormatError,
    WorkstationError,
)

__all__ = [
    "ASPRSClass", "class_name", "Cloud", "HistoryRecord", "concatenate", "DIMS", "Dim",
    "canonical_name", "InvalidInputError", "MissingDependencyError", "NotFittedError",
    "OutputExistsError", "StageError", "UnsupportedFormatError", "WorkstationError",
]
