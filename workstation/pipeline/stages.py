"""The stages of a project run and their parameters, from the project file's ``[stages]``.

Point stages (noise, ground, classify, hag) run one after the other on each chunk and its
buffer, in one task per chunk, and write the chunk's own points once, to the folder of the
last point stage asked for (``OUT/ground/`` when ground is the last). Raster stages (dem,
density) grid each chunk on the project's one grid; the mosaic stage joins the tiles into one
Cloud-Optimized GeoTIFF per product, and hillshade and contours work on the DTM mosaic.
Photo stages (sfm, dense, mesh) orient the project's photos as one block, densify and mesh
them; the register stage puts every scan in the frame of a reference. Each parameter table is
the frozen dataclass the matching command uses (a sub-table for a field that is itself a
dataclass, e.g. ``[stages.mesh.poisson]``).
"""

from __future__ import annotations

import dataclasses
import typing
from dataclasses import dataclass, field
from pathlib import Path

from workstation.core.errors import InvalidInputError

from .project import CLOUD_BRANCH, PHOTO_STAGES, POINT_STAGES, SCAN_STAGES, Project, dataclass_from_table


@dataclass(frozen=True)
class GroundStage:
    """``[stages.ground]``: ``method`` (smrf, csf, pmf, ptd, auto, lowest, local_min, ml),
    ``preset`` and the method's parameters (their dataclass, e.g. ``SMRFParams``)."""

    method: str = "smrf"
    params: object = None


@dataclass(frozen=True)
class ClassifyStage:
    """``[stages.classify]``: the point classifier.

    Attributes
    ----------
    model : str or None
        A model file (relative to the project file); None: the shipped model.
    water, roof_test, raised_patches : bool
        As ``ws classify`` (--no-water, --no-roof-test, --no-raised-patches).
    """

    model: str | None = None
    water: bool = True
    roof_test: bool = True
    raised_patches: bool = True


@dataclass(frozen=True)
class DemStage:
    """``[stages.dem]``: ``kinds`` (dtm, dsm, chm) and the :class:`DemParams` fields they share;
    ``resolution`` in metres (1.0)."""

    kinds: tuple = ("dtm",)
    params: object = None


@dataclass(frozen=True)
class DensityStage:
    """``[stages.density]``: ``cell`` in metres (1.0); the raster holds points per square metre
    of every non-noise return."""

    cell: float = 1.0

    def __post_init__(self):
        if not (isinstance(self.cell, (int, float)) and 0.05 <= self.cell <= 1000):
            raise InvalidInputError(f"cell {self.cell!r} m is outside 0.05-1000 m", field="cell")


@dataclass(frozen=True)
class QCStage:
    """``[stages.qc]``: check the run's point outputs (or its inputs, without point stages)
    and its DTM as ``ws qc`` does, into ``OUT/qc/``.

    Attributes
    ----------
    spec : str
        ``usgs-ql0``…``usgs-ql3`` or ``asprs-<X>cm``.
    checkpoints : str or None
        Checkpoint CSV, relative to the project file.
    checkpoint_rmse : float
        The checkpoints' own vertical RMSE (m).
    """

    spec: str = "usgs-ql2"
    checkpoints: str | None = None
    checkpoint_rmse: float = 0.0

    def __post_init__(self):
        from workstation.qc.specs import get_spec

        get_spec(self.spec)
        if not (isinstance(self.checkpoint_rmse, (int, float)) and 0 <= self.checkpoint_rmse < 100):
            raise InvalidInputError(f"checkpoint_rmse {self.checkpoint_rmse!r} m is outside 0-100 m",
                                    field="checkpoint_rmse")


@dataclass(frozen=True)
class SfMStage:
    """``[stages.sfm]``: the :class:`~workstation.photogrammetry.sfm.SfMParams` fields, and as
    ``ws sfm``: ``camera`` (a CAMERA.json of ``ws calibrate``, relative to the project file),
    ``upright``, ``scale_bars`` and ``scale_distances`` (lists of the --scale-bar /
    --scale-distance texts) and ``sigma_px``."""

    params: object = None
    camera: str | None = None
    upright: bool = True
    scale_bars: tuple = ()
    scale_distances: tuple = ()
    sigma_px: float = 1.0


@dataclass(frozen=True)
class MeshStage:
    """``[stages.mesh]``: the :class:`~workstation.mesh.MeshChainParams` of the dense cloud's
    mesh (``method`` and a sub-table per step: ``[stages.mesh.poisson] depth = 9``; ``false``
    skips an optional step), the file ``format`` (ply, obj, glb) and ``textured`` (from the
    oriented photos; obj or glb)."""

    params: object = None
    format: str = "ply"
    textured: bool = False

    def __post_init__(self):
        if self.format not in ("ply", "obj", "glb"):
            raise InvalidInputError(f"format {self.format!r}: use ply, obj or glb", field="format")
        if self.textured and self.format == "ply":
            raise InvalidInputError("a textured mesh is written as obj or glb", 'set format = "obj"', field="format")


@dataclass(frozen=True)
class RegisterStage:
    """``[stages.register]``: every scan registered onto a reference.

    Attributes
    ----------
    reference : str or None
        The reference scan, by file name or stem; None: the first scan in name order.
    to : str
        "scan" (the reference scan) or "dense" (the photos' dense cloud, ``[stages.dense]``;
        with ``method = "similarity"`` when the photos are not scaled).
    params : RegisterParams
        As ``ws register`` (``method``, ``voxel_size``, ``min_fitness``,
        ``[stages.register.fine]`` ICPParams, ``[stages.register.coarse]`` CoarseParams ...).
    merge : MergeParams
        Of the merged cloud (``[stages.register.merge]`` duplicate_distance, voxel_size).
    """

    reference: str | None = None
    to: str = "scan"
    params: object = None
    merge: object = None

    def __post_init__(self):
        if self.to not in ("scan", "dense"):
            raise InvalidInputError(f"to {self.to!r}: use \"scan\" or \"dense\"", field="to")
        if self.to == "dense" and self.reference is not None:
            raise InvalidInputError("reference names a scan; with to = \"dense\" the reference is the dense cloud",
                                    field="reference")


@dataclass(frozen=True)
class StagePlan:
    """Every stage a project asks for, parsed; None for a stage it does not ask for."""

    noise: object = None
    ground: GroundStage | None = None
    classify: ClassifyStage | None = None
    hag: object = None
    dem: DemStage | None = None
    density: DensityStage | None = None
    hillshade: object = None
    contours: object = None
    qc: QCStage | None = None
    sfm: SfMStage | None = None
    dense: object = None
    mesh: MeshStage | None = None
    register: RegisterStage | None = None
    ends_with: str | None = None
    stages: tuple = field(default_factory=tuple)

    @property
    def point_stages(self) -> tuple:
        return tuple(s for s in POINT_STAGES if getattr(self, s) is not None)

    def params_of(self, stage: str) -> dict:
        """The parameters of ``stage`` as plain data (for run.json and task keys)."""
        v = getattr(self, stage)
        return {} if v is None else _plain(v)


def _plain(v):
    if dataclasses.is_dataclass(v) and not isinstance(v, type):
        return {"type": type(v).__name__, **{f.name: _plain(getattr(v, f.name)) for f in dataclasses.fields(v)}}
    if isinstance(v, (list, tuple)):
        return [_plain(x) for x in v]
    if isinstance(v, dict):
        return {k: _plain(x) for k, x in v.items()}
    return v


def _ground_stage(table: dict, path: Path) -> GroundStage:
    from workstation.ground.methods import METHOD_NAMES, make_params

    table = dict(table)
    method = table.pop("method", "smrf")
    preset = table.pop("preset", "default")
    if method == "ml":
        from workstation.ml.ground import MLGroundParams

        return GroundStage("ml", dataclass_from_table(MLGroundParams, table, "stages.ground", path))
    if method not in METHOD_NAMES:
        raise InvalidInputError(f"unknown ground method '{method}'", "use one of " + ", ".join(METHOD_NAMES + ("ml",)),
                                path=path, field="stages.ground.method")
    try:
        params = make_params(method, preset, **{k: tuple(v) if isinstance(v, list) else v for k, v in table.items()})
    except (InvalidInputError, TypeError, ValueError) as e:
        raise InvalidInputError(str(getattr(e, "message", e)), getattr(e, "hint", None), path=path,
                                field="stages.ground") from None
    return GroundStage(method, params)


def _dem_stage(table: dict, path: Path) -> DemStage:
    from workstation.raster.dem import KINDS, DemParams

    table = dict(table)
    kinds = table.pop("kinds", ["dtm"])
    if isinstance(kinds, str):
        kinds = [kinds]
    if not kinds or any(k not in KINDS for k in kinds) or len(set(kinds)) != len(kinds):
        raise InvalidInputError(f"[stages.dem] kinds {kinds!r}: each of dtm, dsm, chm at most once", path=path,
                                field="stages.dem.kinds")
    if table.get("resolution", 1.0) in (None, "auto"):
        raise InvalidInputError("[stages.dem] resolution must be a number of metres in a project",
                                "one grid is shared by every chunk; e.g. resolution = 1.0", path=path,
                                field="stages.dem.resolution")
    params = dataclass_from_table(DemParams, table, "stages.dem", path, skip=("kind", "tile"))
    if params.pit_free:
        raise InvalidInputError("[stages.dem] pit_free CHMs are made by ws dem, not per chunk yet", path=path,
                                field="stages.dem.pit_free")
    return DemStage(tuple(kinds), params)


def _qc_stage(table: dict, path: Path) -> QCStage:
    """``[stages.qc]`` with its checkpoint file resolved against the project file's folder (and
    kept inside it unless ``--allow-outside``)."""
    from workstation.io.paths import resolve_inside

    stage = dataclass_from_table(QCStage, table, "stages.qc", path)
    if stage.checkpoints is None:
        return stage
    cps = resolve_inside(stage.checkpoints, Path(path).parent, source=path, field="stages.qc.checkpoints")
    if not cps.is_file():
        raise InvalidInputError(f"checkpoint file {stage.checkpoints} not found", path=path,
                                field="stages.qc.checkpoints")
    return dataclasses.replace(stage, checkpoints=str(cps))


def _dataclass_of(hint):
    """The dataclass a field's type names (``X`` or ``X | None``), else None."""
    if dataclasses.is_dataclass(hint) and isinstance(hint, type):
        return hint
    found = [a for a in typing.get_args(hint) if dataclasses.is_dataclass(a) and isinstance(a, type)]
    return found[0] if len(found) == 1 else None


def nested_from_table(cls, table: dict, where: str, path: Path):
    """:func:`dataclass_from_table` where a field whose type is a dataclass takes a sub-table
    (``[stages.mesh.poisson]``), ``false`` (the step skipped: None) or ``true`` (its defaults)."""
    try:
        hints = typing.get_type_hints(cls)
    except (NameError, TypeError):
        hints = {}
    flat, sub = {}, {}
    for k, v in table.items():
        inner = _dataclass_of(hints.get(k))
        if inner is None:
            flat[k] = v
        elif isinstance(v, dict):
            sub[k] = nested_from_table(inner, v, f"{where}.{k}", path)
        elif v is True or v is False:
            sub[k] = dataclass_from_table(inner, {}, f"{where}.{k}", path) if v else None
        else:
            raise InvalidInputError(f"[{where}] {k} must be a table of {inner.__name__} fields, true or false",
                                    path=path, field=f"{where}.{k}")
    obj = dataclass_from_table(cls, flat, where, path)
    if not sub:
        return obj
    try:
        return dataclasses.replace(obj, **sub)
    except InvalidInputError as e:
        raise InvalidInputError(e.message, e.hint, path=path, field=f"{where}.{e.field or ''}".rstrip(".")) from None


def _split(table: dict, cls, where: str, path: Path, inner):
    """``cls`` from the keys of ``table`` that are its own fields (but ``params``), with
    ``params`` built by ``inner`` from the other keys."""
    own = {f.name for f in dataclasses.fields(cls)} - {"params"}
    mine = {k: v for k, v in table.items() if k in own}
    return dataclass_from_table(cls, {**mine, "params": inner({k: v for k, v in table.items() if k not in own})},
                                where, path)


def _sfm_stage(table: dict, path: Path) -> SfMStage:
    """``[stages.sfm]``, its camera file resolved and read and its scale bars parsed (a bad one
    fails before any work)."""
    from workstation.io.paths import resolve_inside
    from workstation.photogrammetry.scale import parse_scale_bar, parse_scale_distance
    from workstation.photogrammetry.sfm import SfMParams

    stage = _split(table, SfMStage, "stages.sfm", path,
                   lambda t: dataclass_from_table(SfMParams, t, "stages.sfm", path))
    try:
        for text in stage.scale_bars:
            parse_scale_bar(text)
        for text in stage.scale_distances:
            parse_scale_distance(text)
    except InvalidInputError as e:
        raise InvalidInputError(e.message, e.hint, path=path, field="stages.sfm.scale_bars") from None
    if stage.camera is None:
        return stage
    cam = resolve_inside(stage.camera, Path(path).parent, source=path, field="stages.sfm.camera")
    if not cam.is_file():
        raise InvalidInputError(f"camera file {stage.camera} not found", path=path, field="stages.sfm.camera")
    from workstation.io.camera import read_camera

    read_camera(cam)
    return dataclasses.replace(stage, camera=str(cam))


def _photo_parsers(path: Path) -> dict:
    from workstation.mesh import MeshChainParams
    from workstation.photogrammetry.dense import DenseParams

    return {
        "sfm": lambda tb: _sfm_stage(tb, path),
        "dense": lambda tb: nested_from_table(DenseParams, tb, "stages.dense", path),
        "mesh": lambda tb: _split(tb, MeshStage, "stages.mesh", path,
                                  lambda t: nested_from_table(MeshChainParams, t, "stages.mesh", path)),
        "register": lambda tb: _register_stage(tb, path),
    }


def _register_stage(table: dict, path: Path) -> RegisterStage:
    from workstation.registration.merge import MergeParams
    from workstation.registration.register import RegisterParams

    table = dict(table)
    merge = table.pop("merge", {})
    if not isinstance(merge, dict):
        raise InvalidInputError("[stages.register] merge must be a table of MergeParams fields", path=path,
                                field="stages.register.merge")
    merge = dataclass_from_table(MergeParams, merge, "stages.register.merge", path, skip=("source_ids",))
    stage = _split(table, RegisterStage, "stages.register", path,
                   lambda t: nested_from_table(RegisterParams, t, "stages.register", path))
    return dataclasses.replace(stage, merge=merge)


def _wanted(project: Project, end_with: str | None) -> list:
    """The stages to run: those the project asks for, or with ``end_with`` that stage and the
    stages before it on its branch (clouds, photos, scans), plus what it reads (the photos'
    sfm and dense for a registration to the dense cloud)."""
    from .project import USER_STAGES

    t, path = project.stages, project.path
    wanted = [s for s in USER_STAGES if s in t]
    if end_with is None:
        return wanted
    if end_with not in USER_STAGES:
        raise InvalidInputError(f"unknown stage '{end_with}'", "use one of " + ", ".join(USER_STAGES), field="end_with")
    if end_with not in t:
        raise InvalidInputError(f"the project has no stage '{end_with}'", "use one of " + ", ".join(wanted),
                                field="end_with")
    branch = next(b for b in (CLOUD_BRANCH, PHOTO_STAGES, SCAN_STAGES) if end_with in b)
    keep = [s for s in wanted if s in branch]
    keep = keep[: keep.index(end_with) + 1]
    if end_with == "register" and t["register"].get("to") == "dense":
        keep = [s for s in wanted if s in ("sfm", "dense")] + keep
    return keep


def _check_inputs(project: Project, wanted: list, t: dict) -> None:
    """Each stage's inputs are in the project: clouds for the cloud stages, photos for sfm,
    scans for register; dense after sfm, mesh after dense."""
    path = project.path
    cloud = [s for s in wanted if s in CLOUD_BRANCH]
    if cloud and not project.clouds:
        raise InvalidInputError(f"[stages.{cloud[0]}] processes clouds and [inputs] has none",
                                'add clouds = ["tiles/*.laz"] to [inputs]', path=path, field=f"stages.{cloud[0]}")
    if any(s in PHOTO_STAGES for s in t) and not project.photos:
        raise InvalidInputError("[stages.sfm/dense/mesh] process photos and [inputs] has none",
                                'add photos = "photos/" to [inputs]', path=path, field="inputs.photos")
    if "register" in t and not project.scans:
        raise InvalidInputError("[stages.register] registers scans and [inputs] has none",
                                'add scans = ["scans/*.e57"] to [inputs]', path=path, field="inputs.scans")
    for stage, before in (("dense", "sfm"), ("mesh", "dense")):
        if stage in t and before not in t:
            raise InvalidInputError(f"[stages.{stage}] needs [stages.{before}]", f"add [stages.{before}]", path=path,
                                    field=f"stages.{stage}")
    if "register" in t and t["register"].get("to") == "dense" and "dense" not in t:
        raise InvalidInputError('[stages.register] to = "dense" needs [stages.dense]', "add [stages.sfm] and "
                                "[stages.dense], or register to a scan", path=path, field="stages.register.to")
    unused = [k for k, files, stages in (("photos", project.photos, PHOTO_STAGES), ("scans", project.scans, SCAN_STAGES))
              if files and not any(s in t for s in stages)]
    if unused:
        need = {"photos": "[stages.sfm]", "scans": "[stages.register]"}[unused[0]]
        raise InvalidInputError(f"[inputs] {unused[0]} are given but no stage processes them", f"add {need}",
                                path=path, field=f"inputs.{unused[0]}")


def parse_stages(project: Project, end_with: str | None = None) -> StagePlan:
    """The :class:`StagePlan` of ``project``, cut after ``end_with`` when given."""
    from workstation.ground.hag import HAGParams
    from workstation.ground.noise import NoiseParams
    from workstation.raster.contours import ContourParams
    from workstation.raster.terrain import HillshadeParams

    t, path = project.stages, project.path
    _check_inputs(project, list(t), t)
    wanted = _wanted(project, end_with)
    if not wanted:
        raise InvalidInputError("the project asks for no stage", "add e.g. [stages.ground] and [stages.dem]", path=path,
                                field="stages")
    if ("hillshade" in wanted or "contours" in wanted) and "dtm" not in (t.get("dem", {}).get("kinds", ["dtm"])):
        raise InvalidInputError("hillshade and contours are made from the DTM", 'add "dtm" to [stages.dem] kinds',
                                path=path, field="stages.dem.kinds")
    parsers = {
        "noise": lambda tb: dataclass_from_table(NoiseParams, tb, "stages.noise", path),
        "ground": lambda tb: _ground_stage(tb, path),
        "classify": lambda tb: dataclass_from_table(ClassifyStage, tb, "stages.classify", path),
        "hag": lambda tb: dataclass_from_table(HAGParams, tb, "stages.hag", path),
        "dem": lambda tb: _dem_stage(tb, path),
        "density": lambda tb: dataclass_from_table(DensityStage, tb, "stages.density", path),
        "hillshade": lambda tb: dataclass_from_table(HillshadeParams, tb, "stages.hillshade", path),
        "contours": lambda tb: dataclass_from_table(ContourParams, tb, "stages.contours", path),
        "qc": lambda tb: _qc_stage(tb, path),
        **_photo_parsers(path),
    }
    parsed = {s: parsers[s](t[s]) for s in wanted}
    if "sfm" in parsed:
        from .photos import check_photo_names

        check_photo_names(project.photos, path)
    if "register" in parsed:
        from .scans import reference_of, scan_names

        reference_of(scan_names(project.scans, path), parsed["register"], path)
    if "hillshade" in parsed or "contours" in parsed:
        if "dem" not in parsed:
            raise InvalidInputError("hillshade and contours need [stages.dem] with kinds including dtm", path=path,
                                    field="stages.dem")
    return StagePlan(**parsed, ends_with=wanted[-1], stages=tuple(wanted))
