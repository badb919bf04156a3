"""Options, parameter types and helpers shared by every command (output, overwrite, json)."""

from __future__ import annotations

import math
import sys

import click

from workstation.core.jsonutil import dumps

output_option = click.option(
    "-o", "--output", "output", required=True, type=click.Path(dir_okay=False), help="Output file."
)
overwrite_option = click.option("--overwrite", is_flag=True, help="Replace the output if it exists.")
json_option = click.option("--json", "as_json", is_flag=True, help="Print a machine-readable result on stdout.")


def _set_allow_outside(ctx, param, value):
    from workstation.io.paths import ALLOW_OUTSIDE

    ALLOW_OUTSIDE.set(bool(value))


allow_outside_option = click.option(
    "--allow-outside", is_flag=True, expose_value=False, callback=_set_allow_outside,
    help="Follow paths written in the input files (image paths of a cameras JSON or COLMAP model, "
         "project inputs) even when they lead outside the file's folder.")


class FiniteFloatRange(click.FloatRange):
    """``click.FloatRange`` that also refuses NaN and ±inf (click lets ``nan`` through every
    range, since every comparison with NaN is false), so ``--cell nan`` is a usage error."""

    name = "finite float range"

    def convert(self, value, param, ctx):
        rv = super().convert(value, param, ctx)
        if not math.isfinite(rv):
            self.fail(f"{value!r} is not a finite number.", param, ctx)
        return rv


class SentinelIntRange(click.IntRange):
    """``click.IntRange`` that also accepts one out-of-range ``sentinel`` with a meaning of its
    own (``--max-image-size -1`` = full size, ``--seed -1`` = random)."""

    def __init__(self, sentinel: int, min=None, max=None, **kw):
        super().__init__(min, max, **kw)
        self.sentinel = sentinel

    def convert(self, value, param, ctx):
        try:
            if int(value) == self.sentinel:
                return self.sentinel
        except (TypeError, ValueError):
            pass
        return super().convert(value, param, ctx)

    def _describe_range(self) -> str:
        return f"{super()._describe_range()} or {self.sentinel}"


GEOTIFF = (".tif", ".tiff")


def require_suffix(path, suffixes, option: str = "--output", what: str = "") -> None:
    """Usage error (exit 2) unless ``path`` ends with one of ``suffixes``: a writer that makes
    GeoTIFF must not write one under a name that says PNG."""
    from pathlib import Path

    if path is not None and Path(path).suffix.lower() not in suffixes:
        kind = f"{what} " if what else ""
        raise click.BadParameter(f"{path}: writes a {kind}file ending {' or '.join(suffixes)}, "
                                 f"not {Path(path).suffix or 'no extension'}", param_hint=f"'{option}'")


#: A length, size, rate or factor that must be > 0.
positive_float = FiniteFloatRange(min=0.0, min_open=True)
#: A tolerance or distance that may be 0.
nonneg_float = FiniteFloatRange(min=0.0)
#: A fraction in [0, 1].
fraction = FiniteFloatRange(0.0, 1.0)
#: Any finite number (offsets, biases, signed factors).
finite_float = FiniteFloatRange()
#: A count of at least one.
positive_int = click.IntRange(min=1)
#: A count that may be 0.
nonneg_int = click.IntRange(min=0)


def emit_json(obj) -> None:
    """Write one JSON document on stdout (NaN/inf become null)."""
    text = dumps(obj, indent=2)
    sys.stdout.write(text + "\n")
    sys.stdout.flush()
