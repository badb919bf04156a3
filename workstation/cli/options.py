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


def float_triple(ctx, param, value):
    """Click callback: ``"a,b,c"`` -> (a, b, c) floats (None stays None)."""
    if value is None:
        return None
    try:
        parts = tuple(float(v) for v in value.split(","))
    except ValueError:
        raise click.BadParameter("give three comma-separated numbers, e.g. 0.1,0,0.25") from None
    if len(parts) != 3:
        raise click.BadParameter("give three comma-separated numbers")
    return parts


def emit_json(obj) -> None:
    """Write one JSON document on stdout (NaN/inf become null)."""
    text = dumps(obj, indent=2)
    sys.stdout.write(text + "\n")
    sys.stdout.flush()


def _parse_bounds(ctx, param, value):
    """``--bounds "xmin,ymin,xmax,ymax[,zmin,zmax]"`` as a tuple of floats (usage error otherwise)."""
    if value is None:
        return None
    try:
        b = tuple(float(v) for v in value.replace(" ", "").strip("()[]").split(","))
    except ValueError:
        b = ()
    if len(b) not in (4, 6) or not all(math.isfinite(v) for v in b):
        raise click.BadParameter(f"{value!r} is not xmin,ymin,xmax,ymax or xmin,ymin,xmax,ymax,zmin,zmax", ctx, param)
    for lo, hi, axis in ((0, 2, "x"), (1, 3, "y"), (4, 5, "z"))[: len(b) // 2]:
        if b[lo] > b[hi]:
            raise click.BadParameter(f"{axis}min {b[lo]:g} is greater than {axis}max {b[hi]:g}", ctx, param)
    return b


def read_options(func=None, *, resolution_flag: str = "--resolution"):
    """Add ``--bounds``, ``--resolution`` and ``--level`` to a command that reads one point cloud
    and pass them on as one dict parameter ``read_opts`` for :func:`workstation.io.read_cloud`
    (``read_cloud(src, **read_opts)``). ``resolution_flag`` renames ``--resolution`` for a command
    that already has one (``ws dem --resolution`` is the cell size)."""
    import functools

    def decorate(f):
        @functools.wraps(f)
        def wrapper(*args, read_bounds=None, read_resolution=None, read_level=None, **kw):
            kw["read_opts"] = {"bounds": read_bounds, "resolution": read_resolution, "level": read_level}
            return f(*args, **kw)

        for opt in (
            click.option("--level", "read_level", type=nonneg_int, default=None,
                         help="COPC only: read octree levels 0..LEVEL (0 is the root), a coarser cloud."),
            click.option(resolution_flag, "read_resolution", type=positive_float, default=None,
                         help="COPC only: read the octree levels down to this point spacing (CRS units)."),
            click.option("--bounds", "read_bounds", default=None, callback=_parse_bounds,
                         metavar="XMIN,YMIN,XMAX,YMAX[,ZMIN,ZMAX]",
                         help="Read only the points inside this box (CRS units, inclusive): a COPC file is "
                              "queried through its octree, a LAS/LAZ file streamed and filtered."),
        ):
            wrapper = opt(wrapper)
        return wrapper

    return decorate(func) if func is not None else decorate


class Length(click.ParamType):
    """A length in metres, or with a unit suffix (``2.5``, ``1m``, ``3ft``, ``10cm``, ``2usft``):
    the value reaching the command is always metres (see :mod:`workstation.core.units`), which
    the stage converts to the CRS's unit. ``auto=True`` also lets ``auto`` through as None.
    Negative, zero (unless ``min_m=0`` and ``open_min=False``), NaN and infinite lengths are
    usage errors."""

    name = "length"

    def __init__(self, min_m: float = 0.0, open_min: bool = True, auto: bool = False):
        self.min_m, self.open_min, self.auto = min_m, open_min, auto

    def convert(self, value, param, ctx):
        from workstation.core.units import parse_length

        if value is None or (self.auto and isinstance(value, str) and value.strip().lower() == "auto"):
            return None
        try:
            m = parse_length(value)
        except ValueError as exc:
            self.fail(str(exc) + (" or 'auto'" if self.auto else ""), param, ctx)
        low = m <= self.min_m if self.open_min else m < self.min_m
        if not math.isfinite(m) or low:
            self.fail(f"{value!r} must be a finite length {'>' if self.open_min else '>='} {self.min_m:g} m", param, ctx)
        return m


#: A positive length (metres; ``3ft`` etc. accepted).
positive_length = Length()
#: A length that may be 0.
nonneg_length = Length(open_min=False)
