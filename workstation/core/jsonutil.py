"""Plain JSON from numpy-flavoured results: arrays to lists, NaN/inf to null; flat key paths."""

from __future__ import annotations

import json
import math

import numpy as np


def to_jsonable(o):
    """``json.dumps(default=...)`` hook for numpy scalars/arrays, paths and ``to_dict`` records."""
    if isinstance(o, np.ndarray):
        return o.tolist()
    if isinstance(o, np.integer):
        return int(o)
    if isinstance(o, np.floating):
        return None if not math.isfinite(float(o)) else float(o)
    if isinstance(o, np.bool_):
        return bool(o)
    if hasattr(o, "to_dict"):
        return o.to_dict()
    if hasattr(o, "__fspath__"):
        return str(o)
    raise TypeError(f"not JSON serialisable: {type(o).__name__}")


def json_clean(o):
    """NaN/inf floats -> None, keys -> str, recursively (what strict JSON can hold).

    Examples
    --------
    >>> json_clean({1: [float("nan"), 2.0]})
    {'1': [None, 2.0]}
    """
    if isinstance(o, float) and not math.isfinite(o):
        return None
    if isinstance(o, dict):
        return {str(k): json_clean(v) for k, v in o.items()}
    if isinstance(o, (list, tuple)):
        return [json_clean(v) for v in o]
    return o


def dumps(obj, **kwargs) -> str:
    """Strict JSON text of ``obj`` (numpy values converted, non-finite floats as null)."""
    return json.dumps(json_clean(json.loads(json.dumps(obj, default=to_jsonable))), allow_nan=False, **kwargs)


def flatten(d, limit: int = 60, prefix: str = "", out: list | None = None) -> list:
    """(dotted key path, leaf value) of a nested JSON object, depth first, at most ``limit``.

    >>> flatten({"a": 1, "b": {"c": [2], "d": "x"}})
    [('a', 1), ('b.c', [2]), ('b.d', 'x')]
    """
    out = [] if out is None else out
    if isinstance(d, dict):
        for k, v in d.items():
            if len(out) >= limit:
                break
            flatten(v, limit, f"{prefix}{k}.", out)
    elif prefix:
        out.append((prefix[:-1], d))
    return out
