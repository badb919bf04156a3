"""The project file (``project.toml``): inputs, chunking, the stages wanted and their parameters.

A project names its inputs relative to its own folder, the chunk size and buffer in metres,
and one table per stage under ``[stages]``. Stage tables hold the fields of the same frozen
dataclasses the commands use (``SMRFParams``, ``NoiseParams``, ``DemParams`` ...), so a key
means the same thing in ``ws ground --cell 2`` and in ``[stages.ground] cell = 2``. Unknown
keys are refused with the list of valid ones: a typo never silently falls back to a default.

Example
-------
.. code-block:: toml

    [project]
    name = "bcts"            # optional, shown in run.json and the summary
    crs = "EPSG:3005"        # optional: for tiles without a CRS; tiles with another CRS are refused

    [inputs]                 # relative to this file; at least one of the three
    clouds = ["tiles/*.laz"] # LAS, LAZ or COPC tiles
    photos = "photos/"       # a folder or glob of photos, oriented as one block by [stages.sfm]
    scans = ["scans/*.e57"]  # scanner stations (any cloud format), registered by [stages.register]

    [chunks]
    size = 250.0             # metres, square chunks aligned to multiples of the size
    buffer = 30.0            # metres of neighbouring points each chunk is processed with

    [stages.noise]           # any NoiseParams field
    [stages.ground]
    method = "smrf"          # smrf, csf, pmf, ptd, auto, lowest, local_min
    preset = "default"       # plus any field of the method's parameters
    [stages.classify]        # the point classifier (model = "path.pt" for another model)
    [stages.hag]             # height above ground
    [stages.dem]
    kinds = ["dtm", "dsm"]   # dtm, dsm, chm
    resolution = 1.0         # metres; plus any DemParams field
    [stages.hillshade]       # of the DTM (HillshadeParams)
    [stages.contours]        # of the DTM (ContourParams); interval in metres
    [stages.density]
    cell = 1.0               # metres; points per square metre, as a raster

    [stages.sfm]             # SfMParams fields; camera = "camera.json", upright, scale_bars
    [stages.dense]           # DenseParams fields (device, method, max_image_size ...)
    [stages.mesh]            # MeshChainParams: method, [stages.mesh.poisson] depth ...; format, textured
    [stages.register]        # RegisterParams fields; reference = "scan name" or to = "dense"
    [stages.register.merge]  # MergeParams of the merged cloud (duplicate_distance, voxel_size)

    [dask]                   # optional; the command line wins
    workers = 2              # local cluster size (default: one per core)
    scheduler = "tcp://host:8786"
"""

from __future__ import annotations

import dataclasses
import glob
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from workstation.core.errors import InvalidInputError

# the stages a project can ask for, in the order data flows through them
POINT_STAGES = ("noise", "ground", "classify", "hag")
RASTER_STAGES = ("dem", "density")
MOSAIC_STAGES = ("hillshade", "contours")
CLOUD_BRANCH = POINT_STAGES + RASTER_STAGES + MOSAIC_STAGES + ("qc",)
PHOTO_STAGES = ("sfm", "dense", "mesh")
SCAN_STAGES = ("register",)
USER_STAGES = CLOUD_BRANCH + PHOTO_STAGES + SCAN_STAGES
CLOUD_SUFFIXES = (".las", ".laz")
INPUT_KEYS = ("clouds", "photos", "scans")


@dataclass(frozen=True)
class ChunkSpec:
    """How the survey is cut for processing.

    Attributes
    ----------
    size : float
        Side of the square chunks in metres (converted to the CRS unit); chunks are aligned to
        multiples of it, so adjacent projects share chunk edges.
    buffer : float
        Metres of neighbouring points each chunk is processed with; only the chunk's own
        points are written. It should reach as far as the widest filter window (SMRF 18 m,
        ``auto`` 30 m) for results without seams.
    """

    size: float = 250.0
    buffer: float = 30.0

    def __post_init__(self):
        if not (isinstance(self.size, (int, float)) and 10.0 <= self.size <= 100_000.0):
            raise InvalidInputError(f"chunk size {self.size!r} m is outside 10-100,000 m",
                                    "set [chunks] size to a side in metres, e.g. 250", field="chunks.size")
        if not (isinstance(self.buffer, (int, float)) and 0.0 <= self.buffer <= self.size):
            raise InvalidInputError(f"chunk buffer {self.buffer!r} m is outside 0-{self.size:g} m (the chunk size)",
                                    "set [chunks] buffer to the widest filter window, e.g. 30", field="chunks.buffer")


@dataclass(frozen=True)
class Project:
    """A parsed project file.

    Attributes
    ----------
    path : Path
        The project file; relative paths in it are relative to its folder.
    name : str
    clouds : tuple of Path
        The input cloud files, sorted, from the ``[inputs] clouds`` patterns (may be empty).
    photos : tuple of Path
        The photos, in natural name order, from ``[inputs] photos`` (may be empty).
    scans : tuple of Path
        The scanner stations, sorted, from ``[inputs] scans`` (may be empty).
    crs : str or None
        The CRS the project declares (tiles without one get it; tiles with another are refused).
    chunks : ChunkSpec
    stages : dict
        Stage name -> its parameter table as written (validated by :mod:`.stages`).
    dask : dict
        ``workers`` and ``scheduler`` defaults for the cluster.
    """

    path: Path
    name: str
    clouds: tuple
    crs: str | None
    chunks: ChunkSpec
    stages: dict = field(default_factory=dict)
    dask: dict = field(default_factory=dict)
    photos: tuple = ()
    scans: tuple = ()

    @property
    def folder(self) -> Path:
        return self.path.parent


def _table(doc: dict, key: str, path: Path) -> dict:
    value = doc.get(key, {})
    if not isinstance(value, dict):
        raise InvalidInputError(f"[{key}] must be a table", f"write it as [{key}] with keys below it", path=path, field=key)
    return value


# what each [inputs] key reads: (suffixes, the files' description, an example pattern)
_INPUT_KINDS = {"clouds": (CLOUD_SUFFIXES, "LAS/LAZ/COPC file", '["tiles/*.laz"]'),
                "photos": (None, "photo (png, jpg, tif ...)", '"photos/"'),
                "scans": (None, "point cloud file (las, laz, e57, ply ...)", '["scans/*.e57"]')}


def _suffixes(key: str) -> tuple:
    if key == "photos":
        from workstation.photogrammetry.calibration import IMAGE_SUFFIXES

        return IMAGE_SUFFIXES
    if key == "scans":
        from workstation.io.registry import FORMATS

        return tuple(FORMATS)
    return CLOUD_SUFFIXES


def _expand_clouds(patterns, folder: Path, path: Path, key: str = "clouds") -> tuple:
    """The files of ``[inputs] key`` matching ``patterns`` (globs or folders), with the suffixes
    that key reads; each must lie in the project folder (or --allow-outside)."""
    from workstation.io.paths import resolve_inside

    _, what, example = _INPUT_KINDS[key]
    suffixes = _suffixes(key)
    if isinstance(patterns, str):
        patterns = [patterns]
    if not isinstance(patterns, list) or not patterns or not all(isinstance(p, str) for p in patterns):
        raise InvalidInputError(f"[inputs] {key} must be a pattern or a list of patterns",
                                f"for example {key} = {example}", path=path, field=f"inputs.{key}")
    found: set[Path] = set()
    for pattern in patterns:
        full = Path(pattern) if Path(pattern).is_absolute() else folder / pattern
        hits = [Path(h) for h in glob.glob(str(full), recursive=True)]
        if full.is_dir():
            hits = [p for p in full.iterdir()]
        hits = [h for h in hits if h.is_file() and h.suffix.lower() in suffixes]
        if not hits:
            raise InvalidInputError(f"no {what} matches '{pattern}' (looked in {full.parent})",
                                    "check the pattern; it is relative to the project file's folder",
                                    path=path, field=f"inputs.{key}")
        found.update(resolve_inside(h, folder, source=path, field=f"inputs.{key}").resolve() for h in hits)
    if key == "photos":
        from workstation.photogrammetry.calibration import natural_key

        return tuple(sorted(found, key=lambda p: (natural_key(p.name), str(p))))
    return tuple(sorted(found))


def _inputs(inputs: dict, folder: Path, path: Path) -> dict:
    """``[inputs]`` expanded: key -> the files of that key (an empty tuple when absent)."""
    extra = sorted(set(inputs) - set(INPUT_KEYS))
    if extra:
        raise InvalidInputError(f"[inputs] has no key '{extra[0]}'", "its keys are " + ", ".join(INPUT_KEYS),
                                path=path, field=f"inputs.{extra[0]}")
    if not inputs:
        raise InvalidInputError("[inputs] names no input", 'add clouds = ["tiles/*.laz"], photos = "photos/" or '
                                'scans = ["scans/*.e57"]', path=path, field="inputs")
    return {k: _expand_clouds(inputs[k], folder, path, k) if k in inputs else () for k in INPUT_KEYS}


KNOWN_TOP = {"project", "inputs", "chunks", "stages", "dask"}


def load_project(path) -> Project:
    """Read and check a project file (the inputs must exist; stage tables are checked by
    :func:`workstation.pipeline.stages.stage_params`).

    Raises
    ------
    InvalidInputError
        Naming the file and the key: unreadable TOML, unknown tables, no inputs, bad chunks.
    """
    path = Path(path)
    if not path.is_file():
        raise InvalidInputError("project file not found", "give the path of a project.toml", path=path)
    try:
        doc = tomllib.loads(path.read_bytes().decode("utf-8"))
    except UnicodeDecodeError as e:
        raise InvalidInputError(f"not UTF-8 text ({e.reason} at byte {e.start})", "save the project file as UTF-8",
                                path=path) from None
    except tomllib.TOMLDecodeError as e:
        raise InvalidInputError(f"not valid TOML: {e}", "fix the line it names", path=path) from None
    unknown = sorted(set(doc) - KNOWN_TOP)
    if unknown:
        raise InvalidInputError(f"unknown table(s) {', '.join(unknown)}", "the tables are " + ", ".join(sorted(KNOWN_TOP)),
                                path=path, field=unknown[0])
    meta, inputs, chunks, stages, dask = (_table(doc, k, path) for k in ("project", "inputs", "chunks", "stages", "dask"))
    files = _inputs(inputs, path.resolve().parent, path)
    bad_chunk = sorted(set(chunks) - {"size", "buffer"})
    if bad_chunk:
        raise InvalidInputError(f"[chunks] has no key {bad_chunk[0]}", "its keys are size and buffer (metres)",
                                path=path, field=f"chunks.{bad_chunk[0]}")
    try:
        spec = ChunkSpec(**chunks)
    except InvalidInputError as e:
        raise InvalidInputError(e.message, e.hint, path=path, field=e.field) from None
    unknown_stages = sorted(set(stages) - set(USER_STAGES))
    if unknown_stages:
        raise InvalidInputError(f"unknown stage '{unknown_stages[0]}'",
                                "the stages are " + ", ".join(USER_STAGES),
                                path=path, field=f"stages.{unknown_stages[0]}")
    for name, table in stages.items():
        if not isinstance(table, dict):
            raise InvalidInputError(f"[stages.{name}] must be a table", path=path, field=f"stages.{name}")
    bad_dask = sorted(set(dask) - {"workers", "scheduler", "memory_limit"})
    if bad_dask:
        raise InvalidInputError(f"[dask] has no key {bad_dask[0]}", "its keys are workers, scheduler, memory_limit",
                                path=path, field=f"dask.{bad_dask[0]}")
    crs = meta.get("crs")
    if crs is not None and not isinstance(crs, str):
        raise InvalidInputError("[project] crs must be a string such as EPSG:2950", path=path, field="project.crs")
    return Project(path.resolve(), str(meta.get("name", path.parent.name or "project")), files["clouds"], crs, spec,
                   {k: dict(v) for k, v in stages.items()}, dict(dask), files["photos"], files["scans"])


def dataclass_from_table(cls, table: dict[str, Any], where: str, path: Path, skip=()):
    """``cls(**table)`` with lists made tuples; an unknown key or a refused value names the
    project file and the ``[stages.x] key``."""
    names = {f.name for f in dataclasses.fields(cls)} - set(skip)
    bad = sorted(set(table) - names)
    if bad:
        raise InvalidInputError(f"[{where}] has no key '{bad[0]}'", "its keys: " + ", ".join(sorted(names)),
                                path=path, field=f"{where}.{bad[0]}")
    values = {k: tuple(v) if isinstance(v, list) else v for k, v in table.items()}
    try:
        return cls(**values)
    except InvalidInputError as e:
        raise InvalidInputError(e.message, e.hint, path=path, field=f"{where}.{e.field or ''}".rstrip(".")) from None
    except (TypeError, ValueError) as e:
        raise InvalidInputError(f"[{where}]: {e}", "check the values' types against the docs", path=path,
                                field=where) from None
