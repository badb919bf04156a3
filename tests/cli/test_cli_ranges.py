"""Every numeric option of every command has a valid range, checked by click before any work."""

import importlib

import click
import pytest

from workstation.cli.main import COMMANDS, main
from workstation.cli.options import FiniteFloatRange

# option names (command path, option) allowed without a range type, each with its reason
ALLOWED: dict[tuple[str, str], str] = {}


def _commands():
    """(path, click.Command) of every command and sub-command in COMMANDS."""
    out = []
    for name, (target, _) in sorted(COMMANDS.items()):
        mod, attr = target.split(":")
        stack = [(name, getattr(importlib.import_module(mod), attr))]
        while stack:
            path, cmd = stack.pop()
            out.append((path, cmd))
            if isinstance(cmd, click.Group):
                stack.extend((f"{path} {n}", c) for n, c in cmd.commands.items())
    return out


def _numeric_types(t):
    """The int/float parameter types inside ``t`` (a tuple type's members too)."""
    inner = t.types if isinstance(t, click.Tuple) else [t]
    return [x for x in inner if isinstance(x, (click.types.IntParamType, click.types.FloatParamType))]


def _unranged(t) -> bool:
    """A numeric type without a range, or a float range that lets NaN/inf through."""
    if isinstance(t, click.types.FloatParamType):
        return not isinstance(t, FiniteFloatRange)
    return not isinstance(t, click.IntRange)


def test_every_numeric_option_has_a_range():
    bad = []
    for path, cmd in _commands():
        for p in cmd.params:
            if (path, p.name) in ALLOWED:
                continue
            if any(_unranged(t) for t in _numeric_types(p.type)):
                bad.append(f"ws {path} {p.opts[0]} ({p.type!r})")
    assert not bad, "numeric options without a range type (use workstation.cli.options): " + ", ".join(bad)


def test_allow_list_names_existing_options():
    params = {(path, p.name) for path, cmd in _commands() for p in cmd.params}
    assert set(ALLOWED) <= params


BAD = [
    ("ground", "--cell", ["0", "-1", "nan", "inf"]),
    ("ground", "--window", ["nan", "0", "-5"]),
    ("ground", "--iterations", ["0"]),
    ("ground", "--max-angle", ["0", "91", "nan"]),
    ("ground", "--tile-buffer", ["-1", "nan"]),
    ("dem", "--chunk-size", ["0", "-3"]),
    ("dem", "--resolution", ["0", "-1", "nan", "inf"]),
    ("dem", "--max-edge", ["0", "nan"]),
    ("dem", "--copc-resolution", ["0", "-1", "nan"]),
    ("dem", "--level", ["-1"]),
    ("render", "--level", ["-1"]),
    ("render", "--resolution", ["0", "inf"]),
    ("hillshade", "--altitude", ["-1", "91", "nan"]),
    ("hillshade", "--azimuth", ["361", "nan"]),
    ("hillshade", "--z-factor", ["0", "nan"]),
    ("contours", "--interval", ["0", "nan"]),
    ("contours", "--index-every", ["0"]),
    ("register", "--voxel-size", ["0", "nan"]),
    ("register", "--min-fitness", ["1.5", "-0.1", "nan"]),
    ("merge", "--voxel-size", ["0", "nan"]),
    ("mesh", "--samples-per-node", ["0", "nan"]),
    ("mesh", "--radius", ["-1", "inf"]),
    ("mesh", "--trim-quantile", ["1", "nan"]),
    ("mesh", "--refine-k", ["1", "2", "-1"]),
    ("render", "--point-size", ["-1", "nan"]),
    ("render", "--max-points", ["-1"]),
    ("info", "--density-cell", ["0", "nan"]),
    ("evaluate", "--tolerance", ["-1", "nan"]),
    ("plan-flight", "--overlap", ["1", "-0.1", "nan"]),
    ("plan-flight", "--fov", ["0", "180", "nan"]),
    ("plan-flight", "--altitude", ["0", "nan"]),
    ("simulate", "--max-returns", ["0", "16"]),
    ("simulate", "--overlap", ["1", "nan"]),
    ("simulate", "--seed", ["-1"]),
    ("ortho", "--resolution", ["0", "nan"]),
    ("dense", "--max-image-size", ["0", "-2"]),
    ("dense", "--min-ncc", ["1.5", "nan"]),
    ("sfm", "--max-image-size", ["0"]),
    ("sfm", "--sigma-px", ["0", "nan"]),
    ("colorize", "--max-views", ["0"]),
    ("calibrate zhang", "--outlier-factor", ["0.5", "nan"]),
    ("classify", "--roof-tolerance", ["0", "nan"]),
    ("report", "--max-points", ["0"]),
    ("demo", "--seed", ["-1"]),
]


@pytest.mark.parametrize("command, option, value",
                         [(c, o, v) for c, o, vs in BAD for v in vs],
                         ids=lambda x: str(x))
def test_bad_value_is_a_usage_error_naming_the_option(capsys, command, option, value):
    # the bad option comes first, so click checks it before any argument or required option
    rc = main([*command.split(), f"{option}={value}", "a.laz", "b.laz"])
    err = capsys.readouterr().err
    assert rc == 2, err
    assert option in err
