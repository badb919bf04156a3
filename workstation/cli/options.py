"""Options, parameter types and helpers shared by every command (output, overwrite, json), and
the binding of a command's options to the fields of a stage's parameter dataclass (:func:`param_group`)."""

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

    def _describe_range(self) -> str:
        # click writes an unbounded range as "x<=None"; any finite number needs no note
        if self.min is None and self.max is None:
            return ""
        return super()._describe_range()


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


def read_options(func=None, *, resolution_flag: str = "--resolution", with_bounds: bool = True):
    """Add ``--bounds``, ``--resolution`` and ``--level`` to a command that reads one point cloud
    and pass them on as one dict parameter ``read_opts`` for :func:`workstation.io.read_cloud`
    (``read_cloud(src, **read_opts)``). ``resolution_flag`` renames ``--resolution`` for a command
    that already has one (``ws dem --resolution`` is the cell size); ``with_bounds=False`` leaves
    out ``--bounds`` for a command whose own ``--bounds`` means something else (``ws crop``), so
    ``read_opts["bounds"]`` is then None."""
    import functools

    def decorate(f):
        @functools.wraps(f)
        def wrapper(*args, read_bounds=None, read_resolution=None, read_level=None, **kw):
            kw["read_opts"] = {"bounds": read_bounds, "resolution": read_resolution, "level": read_level}
            return f(*args, **kw)

        opts = (
            click.option("--level", "read_level", type=nonneg_int, default=None,
                         help="COPC only: read octree levels 0..LEVEL (0 is the root), a coarser cloud."),
            click.option(resolution_flag, "read_resolution", type=positive_float, default=None,
                         help="COPC only: read the octree levels down to this point spacing (CRS units)."),
            click.option("--bounds", "read_bounds", default=None, callback=_parse_bounds,
                         metavar="XMIN,YMIN,XMAX,YMAX[,ZMIN,ZMAX]",
                         help="Read only the points inside this box (CRS units, inclusive): a COPC file is "
                              "queried through its octree, a LAS/LAZ file streamed and filtered."),
        )
        for opt in opts if with_bounds else opts[:2]:
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


# --- options bound to the fields of a stage's parameter dataclass --------------------------------
#
# A command's options that are parameters of a library stage are declared once, as ``bound``
# specs naming the dataclass field each one sets; ``param_group`` adds them to the command and
# hands their values over as one dict keyed by field name. Defaults and choice lists are read
# from the library (the dataclass's field default, a registry tuple), never written again here.

_FIELD_DEFAULT = object()


class BoundOption(click.Option):
    """A ``click.Option`` that records the parameter it sets: ``bind = (dataclass or None,
    field)`` (None where the class depends on another option, as the ground method's)."""

    def __init__(self, *args, bind: tuple = (None, None), **kw):
        super().__init__(*args, **kw)
        self.bind = bind


class RegistryChoice(click.Choice):
    """A ``click.Choice`` whose names are a library registry (a tuple of names, or a dict keyed
    by name) plus names the command itself handles (``first``, listed before, and ``extra``,
    after), so a name added to the library is offered by the command without touching it."""

    def __init__(self, registry, extra=(), first=(), case_sensitive: bool = True):
        self.registry, self.extra, self.first = registry, tuple(extra), tuple(first)
        super().__init__([*self.first, *registry, *self.extra], case_sensitive=case_sensitive)


def field_default(cls, field: str):
    """The default of ``field`` of the dataclass ``cls`` (its default factory called), or of the
    keyword parameter ``field`` where ``cls`` is a library function (``ground_filter``'s method)."""
    import dataclasses
    import inspect

    if not dataclasses.is_dataclass(cls):
        p = inspect.signature(cls).parameters.get(field)
        if p is None or p.default is inspect.Parameter.empty:
            raise TypeError(f"{cls.__name__} has no keyword parameter {field!r} with a default")
        return p.default
    for f in dataclasses.fields(cls):
        if f.name == field:
            if f.default is not dataclasses.MISSING:
                return f.default
            if f.default_factory is not dataclasses.MISSING:
                return f.default_factory()
            raise TypeError(f"{cls.__name__}.{field} has no default")
    raise TypeError(f"{cls.__name__} has no field {field!r}")


def bound(cls, field: str, *decls, default=_FIELD_DEFAULT, **attrs) -> dict:
    """The spec of one option of a :func:`param_group`: ``decls`` and ``attrs`` as for
    ``click.option``, setting ``field`` of the dataclass ``cls``. Without ``default`` the option's
    default is the dataclass's; ``default=None`` leaves the value to the library (a preset, a
    config file, a rule on the data)."""
    if default is _FIELD_DEFAULT:
        default = field_default(cls, field)
    return {"decls": decls, "attrs": {**attrs, "default": default}, "bind": (cls, field)}


def field_option(cls, field: str, *decls, default=_FIELD_DEFAULT, **attrs):
    """``click.option`` for one parameter passed to the command on its own, setting ``field`` of
    the dataclass ``cls`` (default as in :func:`bound`)."""
    spec = bound(cls, field, *decls, default=default, **attrs)
    return click.option(*spec["decls"], cls=BoundOption, bind=spec["bind"], **spec["attrs"])


def param_group(dest: str, *specs: dict, given_only: bool = False):
    """Add the options of ``specs`` (:func:`bound`, in the order listed, as they appear in
    ``--help``) to a command and pass their values on as one dict parameter ``dest``
    ``{field: value}`` in place of one parameter each. With ``given_only`` the options left at
    None are left out of the dict (the library decides those). Two groups with one ``dest``
    (options of one dataclass with another option between them in ``--help``) fill one dict."""
    import functools

    def decorate(f):
        names: dict[str, str] = {}

        @functools.wraps(f)
        def wrapper(*args, **kw):
            values = {field: kw.pop(name) for name, field in names.items()}
            if given_only:
                values = {k: v for k, v in values.items() if v is not None}
            kw[dest] = {**kw.get(dest, {}), **values}  # two groups may fill one dict
            return f(*args, **kw)

        for spec in reversed(specs):  # click lists the options last decorated first
            wrapper = click.option(*spec["decls"], cls=BoundOption, bind=spec["bind"], **spec["attrs"])(wrapper)
        added = wrapper.__click_params__[-len(specs):][::-1]
        names.update((opt.name, opt.bind[1]) for opt in added)  # in the order of ``specs``
        return wrapper

    return decorate


class IntTuple(click.ParamType):
    """Comma-separated integers (``2,9``) as a tuple; a tuple (a dataclass default) passes
    through, so ``--help`` shows it as ``2, 9``. A value that is not integers is the library's
    own invalid-input error naming ``field`` (exit 1), as the stage would report it, or with
    ``usage`` a usage error (exit 2)."""

    name = "text"

    def __init__(self, field: str, example: str = "2,9", usage: bool = False):
        self.field, self.example, self.usage = field, example, usage

    def convert(self, value, param, ctx):
        from workstation.core.errors import InvalidInputError

        if isinstance(value, tuple):
            return value
        try:
            return tuple(int(c) for c in str(value).split(",") if c.strip())
        except ValueError:
            flag = param.opts[0] if param is not None else self.field
            if self.usage:
                raise click.UsageError(f"{flag} must be integers, got {value!r}") from None
            raise InvalidInputError(f"{flag} must be integers like {self.example}", field=self.field) from None
