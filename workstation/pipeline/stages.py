"""The stages of a project run and their parameters, from the project file's ``[stages]``.

Point stages (noise, ground, classify, hag) run one after the other on each chunk and its
buffer, in one task per chunk, and write the chunk's own points once, to the folder of the
last point stage asked for (``OUT/ground/`` when ground is the last). Raster stages (dem,
density) grid each chunk on the project's one grid; the mosaic stage joins the tiles into one
Cloud-Optimized GeoTIFF per product, and hillshade and contours work on the DTM mosaic.
Each parameter table is the frozen dataclass the matching command uses.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from pathlib import Path

from workstation.core.errors import InvalidInputError

from .project import POINT_STAGES, Project, dataclass_from_table


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
        As ``ws classify`` (--no-water, --no-roof-test, --raised-patches).
    """

    model: str | None = None
    water: bool = True
    roof_test: bool = True
    raised_patches: bool = False


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


def parse_stages(project: Project, end_with: str | None = None) -> StagePlan:
    """The :class:`StagePlan` of ``project``, cut after ``end_with`` when given."""
    from workstation.ground.hag import HAGParams
    from workstation.ground.noise import NoiseParams
    from workstation.raster.contours import ContourParams
    from workstation.raster.terrain import HillshadeParams

    from .project import USER_STAGES

    t, path = project.stages, project.path
    if end_with is not None and end_with not in USER_STAGES:
        raise InvalidInputError(f"unknown stage '{end_with}'", "use one of " + ", ".join(USER_STAGES), field="end_with")
    wanted = [s for s in USER_STAGES if s in t]
    if end_with is not None:
        if end_with not in t:
            raise InvalidInputError(f"the project has no stage '{end_with}'", "use one of " + ", ".join(wanted),
                                    field="end_with")
        wanted = wanted[: wanted.index(end_with) + 1]
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
    }
    parsed = {s: parsers[s](t[s]) for s in wanted}
    if "hillshade" in parsed or "contours" in parsed:
        if "dem" not in parsed:
            raise InvalidInputError("hillshade and contours need [stages.dem] with kinds including dtm", path=path,
                                    field="stages.dem")
    return StagePlan(**parsed, ends_with=wanted[-1], stages=tuple(wanted))
