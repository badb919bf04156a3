"""The options of a command that set a stage's parameters read their defaults and choice lists
from the library (the parameter dataclass, the library's registry tuples), so the command line
never re-decides what the library decides: a default or a list written again in a command
fails here unless it is the command's own decision, listed below with its reason."""

import dataclasses
import importlib

import click
import pytest
from click.testing import CliRunner

from workstation.cli.main import COMMANDS
from workstation.cli.options import BoundOption, RegistryChoice, bound, field_default, field_option, param_group


def _command(path):
    """The command of ``path`` (``dem``, or a sub-command: ``calibrate zhang``)."""
    name, *sub = path.split()
    mod, attr = COMMANDS[name][0].split(":")
    cmd = getattr(importlib.import_module(mod), attr)
    for s in sub:
        cmd = cmd.commands[s]
    return cmd


def _bound_commands():
    """(path, command) of every command and sub-command (``calibrate zhang``) of each command
    with at least one option bound to a dataclass field or library function parameter."""
    out = []
    for name in sorted(COMMANDS):
        leaves, stack = [], [(name, _command(name))]
        while stack:
            path, cmd = stack.pop()
            if isinstance(cmd, click.Group):
                stack.extend((f"{path} {n}", c) for n, c in sorted(cmd.commands.items()))
            else:
                leaves.append((path, cmd))
        if any(isinstance(p, BoundOption) for _, cmd in leaves for p in cmd.params):
            out.extend(sorted(leaves, key=lambda pc: pc[0]))
    return out


def _default(p):
    """The option's default as ``--help`` knows it (None where it has none)."""
    return p.to_info_dict()["default"]


def _flag(p) -> str:
    return p.opts[-1] if p.opts[-1].startswith("-") else p.opts[0]


def _registries():
    """(command, option) -> the library registry its choices must be (plus the names the
    command itself handles)."""
    from workstation.ground.methods import METHOD_NAMES, PRESET_NAMES
    from workstation.lidar.planning import SOLVABLE
    from workstation.lidar.scanners import AIRBORNE_KINDS
    from workstation.lidar.survey import KINDS
    from workstation.mesh.chain import METHODS as MESH_METHODS
    from workstation.mesh.normals import ORIENTATIONS
    from workstation.mesh.reconstruct import POISSON_BACKENDS
    from workstation.mesh.simplify import SMOOTH_METHODS
    from workstation.ml.model import DEVICES as ML_DEVICES
    from workstation.photogrammetry import dense, georef, sfm
    from workstation.raster import dem
    from workstation.ops import merge, thin
    from workstation.raster import terrain
    from workstation.render.render import VIEWS
    from workstation.registration import icp, register

    return {
        ("ground", "--method"): (METHOD_NAMES, ("ml",)),
        ("ground", "--preset"): (PRESET_NAMES, ()),
        ("simulate", "kind"): (KINDS, ()),
        ("simulate", "--pattern"): (AIRBORNE_KINDS, ()),
        ("mesh", "--method"): (MESH_METHODS, ()),
        ("mesh", "--poisson-backend"): (POISSON_BACKENDS, ()),
        ("mesh", "--orient"): (ORIENTATIONS, ()),
        ("mesh", "--smooth"): (SMOOTH_METHODS, ("none",)),
        ("dem", "--kind"): (dem.KINDS, ()),
        ("dem", "--method"): (dem.METHODS, ()),
        ("dense", "--device"): (dense.DEVICES, ()),
        ("dense", "--method"): (dense.METHODS, ()),
        ("classify", "--device"): (ML_DEVICES, ()),
        ("sfm", "--device"): (dense.DEVICES, ()),
        ("sfm", "--matcher"): (sfm.MATCHERS, ()),
        ("sfm", "--mapper"): (sfm.MAPPERS, ()),
        ("sfm", "--cameras"): (sfm.CAMERA_SHARING, ()),
        ("sfm", "--gcp-adjustment"): (georef.ADJUSTMENTS, ()),
        ("plan-flight", "--pattern"): (AIRBORNE_KINDS, ()),
        ("plan-flight", "--solve-for"): (SOLVABLE, ()),
        ("register", "--method"): (register.METHODS, ("pairs",)),
        ("register", "--fine"): (icp.ICP_METHODS, ()),
        ("register", "--kernel"): (icp.KERNELS, ()),
        ("hillshade", "--product"): (terrain.PRODUCTS, ()),
        ("thin", "--keep"): (thin.KEEP, ()),
        ("merge", "--source-ids"): (merge.SOURCE_IDS, ()),
        ("render", "--view"): (VIEWS, ()),
    }


def _bindings():
    """(command, option) -> (dataclass or function, field) of options whose default the
    library owns."""
    from workstation.ground.evaluate import evaluate_clouds
    from workstation.ground.methods import ground_filter
    from workstation.ground.tiles import TileParams
    from workstation.mesh import NormalParams, PoissonParams, SmoothParams, TextureParams
    from workstation.adjust import AdjustParams
    from workstation.buildings.pipeline import BuildingsParams
    from workstation.buildings.solar import SolarParams
    from workstation.lidar.planning import FlightParams, solve_for_density
    from workstation.ml.model import resolve_device
    from workstation.photogrammetry.calibration import ZhangParams
    from workstation.photogrammetry.dense import DenseParams
    from workstation.photogrammetry.georef import georeference
    from workstation.photogrammetry.sfm import SfMParams
    from workstation.ops.thin import VoxelParams
    from workstation.ops.merge import merge_files
    from workstation.ops.tile import TileParams as CutParams
    from workstation.raster.contours import ContourParams
    from workstation.raster.ortho import OrthoParams
    from workstation.registration.colorize import ColorizeParams
    from workstation.render.render import RenderParams
    from workstation.render.report import ReportParams
    from workstation.raster.terrain import HillshadeParams
    from workstation.registration.icp import ICPParams
    from workstation.registration.register import RegisterParams
    from workstation.raster.dem import DemParams, build_dem

    return {
        ("ground", "--method"): (ground_filter, "method"),
        ("ground", "--preset"): (ground_filter, "preset"),
        ("ground", "--tile-points"): (TileParams, "tile_points"),
        ("ground", "--tile-buffer"): (TileParams, "buffer"),
        ("ground", "--tile-workers"): (TileParams, "workers"),
        ("mesh", "--depth"): (PoissonParams, "depth"),
        ("mesh", "--samples-per-node"): (PoissonParams, "samples_per_node"),
        ("mesh", "--trim-quantile"): (PoissonParams, "trim_quantile"),
        ("mesh", "--threads"): (PoissonParams, "threads"),
        ("mesh", "--k-normals"): (NormalParams, "k"),
        ("mesh", "--smooth-iterations"): (SmoothParams, "iterations"),
        ("mesh", "--texture-size"): (TextureParams, "max_texture_size"),
        ("mesh", "--texture-views"): (TextureParams, "max_views"),
        ("dem", "--kind"): (DemParams, "kind"),
        ("dem", "--ground-classes"): (DemParams, "ground_classes"),
        ("dem", "--chunk-size"): (build_dem, "chunk_size"),
        ("dense", "--device"): (DenseParams, "device"),
        ("dense", "--method"): (DenseParams, "method"),
        ("dense", "--max-image-size"): (DenseParams, "max_image_size"),
        ("dense", "--min-ncc"): (DenseParams, "min_ncc"),
        ("dense", "--min-consistent"): (DenseParams, "min_consistent"),
        ("dense", "--fusion-cache-gb"): (DenseParams, "fusion_cache_gb"),
        ("classify", "--device"): (resolve_device, "device"),
        ("buildings", "--building-class"): (BuildingsParams, "building_class"),
        ("buildings", "--ground-class"): (BuildingsParams, "ground_class"),
        ("buildings", "--linke-turbidity"): (SolarParams, "linke_turbidity"),
        ("sfm", "--matcher"): (SfMParams, "matcher"),
        ("sfm", "--max-image-size"): (SfMParams, "max_image_size"),
        ("sfm", "--max-features"): (SfMParams, "max_features"),
        ("sfm", "--camera-model"): (SfMParams, "camera_model"),
        ("sfm", "--cameras"): (SfMParams, "cameras"),
        ("sfm", "--seed"): (SfMParams, "seed"),
        ("sfm", "--sigma-px"): (georeference, "sigma_px"),
        ("sfm", "--gcp-adjustment"): (georeference, "adjustment"),
        ("sfm", "--device"): (DenseParams, "device"),
        ("plan-flight", "--altitude"): (FlightParams, "altitude"),
        ("plan-flight", "--scan-rate"): (FlightParams, "scan_frequency"),
        ("plan-flight", "--bank"): (FlightParams, "bank_deg"),
        ("plan-flight", "--pattern"): (FlightParams, "pattern"),
        ("plan-flight", "--solve-for"): (solve_for_density, "solve"),
        ("register", "--method"): (RegisterParams, "method"),
        ("register", "--min-fitness"): (RegisterParams, "min_fitness"),
        ("register", "--fine"): (ICPParams, "method"),
        ("register", "--kernel"): (ICPParams, "kernel"),
        ("hillshade", "--azimuth"): (HillshadeParams, "azimuth"),
        ("hillshade", "--altitude"): (HillshadeParams, "altitude"),
        ("hillshade", "--z-factor"): (HillshadeParams, "z_factor"),
        ("thin", "--keep"): (VoxelParams, "keep"),
        ("contours", "--base"): (ContourParams, "base"),
        ("evaluate", "--tolerance"): (evaluate_clouds, "tolerance"),
        ("evaluate", "--min-matched"): (evaluate_clouds, "min_matched"),
        ("evaluate", "--ground-classes"): (evaluate_clouds, "ground_classes"),
        ("colorize", "--max-views"): (ColorizeParams, "max_views"),
        ("ortho", "--blend-angle"): (OrthoParams, "blend_angle"),
        ("merge", "--source-ids"): (merge_files, "source_ids"),
        ("tile", "--buffer"): (CutParams, "buffer"),
        ("render", "--size"): (RenderParams, "size"),
        ("render", "--view"): (RenderParams, "view"),
        ("render", "--color"): (RenderParams, "color"),
        ("render", "--max-points"): (RenderParams, "max_points"),
        ("strip-adjust", "--lever-arm"): (AdjustParams, "lever_arm"),
        ("report", "--render-size"): (ReportParams, "render_size"),
        ("calibrate zhang", "--outlier-factor"): (ZhangParams, "outlier_factor"),
        ("report", "--max-points"): (ReportParams, "max_points"),
        ("strip-adjust", "--boresight"): (AdjustParams, "boresight_deg"),
        ("contours", "--index-every"): (ContourParams, "index_every"),
        ("contours", "--smooth"): (ContourParams, "smooth"),
    }


# commands with no option bound to a library parameter, each with its reason
UNBOUND = {
    "convert": "format, CRS and attribute choices of the writers, no stage parameters",
    "crop": "a box or polygon file, no stage parameters",
    "demo": "an output folder and a seed",
    "filter": "an expression",
    "info": "what to print",
    "publish": "owned by another change (site layout options)",
    "qc": "owned by another change (specification choices)",
    "run": "a project file",
    "train": "a recipe file",
}

# (command, option) -> why the command has a choice list of its own
OWN_CHOICES = {
    ("simulate", "--point-format"): "what the command writes: LAS 1.4 formats without colour, with RGB, with RGB + NIR",
    ("tile", "--format"): "the tile file formats the command writes",
    ("calibrate dlt", "--distortion"): "left to do: text names of DLTParams.distortion's term counts (0, 2, 5)",
}

# (command, option) -> why its default is the command's, not its dataclass's
OWN_DEFAULTS = {
    ("simulate", "--point-format"): "the command writes colour (format 7) unless asked",
    ("mesh", "--min-piece-fraction"): "a scan meshed from the command line is cleaned of small floating pieces",
    ("mesh", "--smooth"): "no smoothing unless asked ('none' is the command's own choice)",
    ("tile", "--format"): "compressed tiles unless asked",
    ("calibrate dlt", "--distortion"): "left to do: the text of DLTParams.distortion's default 0",
    ("render", "--turntable"): "0: a still picture unless frames are asked",
    ("hillshade", "--product"): "the shaded relief unless another product is asked",
    ("dem", "--resolution"): "'auto': the cell size from the point spacing (DemParams' 1.0 is for a caller giving none)",
}


@pytest.mark.parametrize("name,cmd", _bound_commands(), ids=[n for n, _ in _bound_commands()])
def test_bound_defaults_are_the_dataclass_defaults(name, cmd):
    """A bound option's default, as the command receives it (a length text '0' as 0.0 m, a size
    text '1024x768' as (1024, 768)), is
    its field's default, or None (the library decides later)."""
    n = 0
    for p in cmd.params:
        if not isinstance(p, BoundOption) or p.bind[0] is None or _default(p) is None:
            continue
        if (name, _flag(p)) in OWN_DEFAULTS:
            continue
        value = p.process_value(click.Context(cmd), p.default)  # what the command receives
        assert value == field_default(*p.bind), f"ws {name} {_flag(p)}"
        n += 1
    assert n or name in ("simulate", "calibrate dlt")  # simulate's are left to the survey config

@pytest.mark.parametrize("name,cmd", _bound_commands(), ids=[n for n, _ in _bound_commands()])
def test_no_default_written_in_the_command(name, cmd):
    """Every option with a value default (not a flag, not None) of a command with a parameter
    dataclass takes it from the dataclass, or is listed with its reason."""
    bad = [_flag(p) for p in cmd.params
           if isinstance(p, click.Option) and not p.is_flag and _default(p) is not None and not p.multiple
           and not isinstance(p, BoundOption) and (name, _flag(p)) not in OWN_DEFAULTS]
    assert not bad, f"ws {name}: defaults written in the command: {bad} (bind them to the dataclass field)"


@pytest.mark.parametrize("name,cmd", _bound_commands(), ids=[n for n, _ in _bound_commands()])
def test_choices_are_library_registries(name, cmd):
    """A choice list of a command with a parameter dataclass is a library registry."""
    expected = _registries()
    for p in cmd.params:
        if not isinstance(p.type, click.Choice) or (name, _flag(p)) in OWN_CHOICES:
            continue
        where = f"ws {name} {_flag(p)}"
        assert isinstance(p.type, RegistryChoice), f"{where}: a choice list written in the command"
        assert (name, _flag(p)) in expected, f"{where}: add its registry to _registries()"
        registry, own = expected[name, _flag(p)]
        assert p.type.registry is registry, f"{where}: not the library's registry"
        assert set(p.type.choices) == set(registry) | set(own)


def test_every_command_is_bound_or_says_why():
    """A command either binds its stage parameters to the library or is listed in UNBOUND, so a
    new command with its own copies of the library's defaults does not go unchecked."""
    bound_names = {n.split()[0] for n, _ in _bound_commands()}
    assert bound_names | set(UNBOUND) == set(COMMANDS), sorted(set(COMMANDS) - bound_names - set(UNBOUND))
    assert not bound_names & set(UNBOUND), "bound now: take it out of UNBOUND"


def test_pinned_bindings():
    """The options whose default the library owns are bound to their field, and show it."""
    for (name, flag), (cls, field) in _bindings().items():
        p = next(p for p in _command(name).params if flag in p.opts)
        assert isinstance(p, BoundOption) and p.bind == (cls, field), f"ws {name} {flag}"
        assert p.process_value(click.Context(_command(name)), p.default) == field_default(cls, field)


def test_pinned_registries():
    """The choice lists the library owns are its registries (a list written again in the
    command, even with the same names, fails)."""
    for (name, flag), (registry, own) in _registries().items():
        p = next(p for p in _command(name).params if flag in p.opts)
        assert isinstance(p.type, RegistryChoice) and p.type.registry is registry, f"ws {name} {flag}"
        assert set(p.type.choices) == set(registry) | set(own)


def test_ground_filter_options_name_their_methods():
    """Each ground filter option sets a field of at least one method's parameter dataclass and
    its help names exactly the methods that have it."""
    from workstation.ground.methods import methods
    from workstation.ml.ground import MLGroundParams

    n = 0
    for p in _command("ground").params:
        if isinstance(p, BoundOption) and p.bind[0] is None:
            field = p.bind[1]
            has = [m for m, spec in methods().items() if field in {f.name for f in dataclasses.fields(spec.params)}]
            has += ["ml"] if field in {f.name for f in dataclasses.fields(MLGroundParams)} else []
            assert has, f"--{field}: no ground method has it"
            assert p.help.startswith(f"[{', '.join(has)}] "), p.help
            n += 1
    assert n >= 18


def _demo_command():
    from workstation.ground.tiles import TileParams

    seen = {}

    @click.command()
    @param_group("tiles", bound(TileParams, "tile_points", "--tile-points", type=int),
                 bound(TileParams, "buffer", "--tile-buffer", type=float))
    @click.option("--x", type=int, default=None)
    @param_group("tiles", bound(TileParams, "workers", "--tile-workers", type=int, default=None), given_only=True)
    @field_option(TileParams, "buffer", "--own-buffer", type=float)
    def cmd(tiles, x, own_buffer):
        seen.update(tiles=tiles, x=x, own_buffer=own_buffer)

    return cmd, seen


def test_param_group_passes_one_dict_by_field():
    """The options reach the command as one dict keyed by field, with the dataclass defaults;
    two groups of one name fill one dict; ``given_only`` leaves out what was not given."""
    cmd, seen = _demo_command()
    res = CliRunner().invoke(cmd, ["--tile-buffer", "5", "--x", "3"])
    assert res.exit_code == 0, res.output
    assert seen == {"tiles": {"tile_points": 10_000_000, "buffer": 5.0}, "x": 3, "own_buffer": 60.0}
    res = CliRunner().invoke(cmd, ["--tile-workers", "4"])
    assert seen["tiles"] == {"tile_points": 10_000_000, "buffer": 60.0, "workers": 4}
    help_text = CliRunner().invoke(cmd, ["--help"]).output
    assert help_text.index("--tile-points") < help_text.index("--tile-buffer") < help_text.index("--x") \
        < help_text.index("--tile-workers") < help_text.index("--own-buffer")


def test_field_default_errors():
    from workstation.ground.tiles import TileParams

    with pytest.raises(TypeError, match="no field"):
        field_default(TileParams, "nope")
