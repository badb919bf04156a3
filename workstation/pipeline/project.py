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

    [inputs]
    clouds = ["tiles/*.laz"] # relative to this file; LAS, LAZ or COPC

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
USER_STAGES = POINT_STAGES + RASTER_STAGES + MOSAIC_STAGES + ("qc",)
CLOUD_SUFFIXES = (".las", ".laz")


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
        The input cloud files, sorted, from the ``[inputs] clouds`` patterns.
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

    @property
    def folder(self) -> Path:
        return self.path.parent


def _table(doc: dict, key: str, path: Path) -> dict:
    value = doc.get(key, {})
    if not isinstance(value, dict):
        raise InvalidInputError(f"[{key}] must be a table", f"write it as [{key}] with keys below it", path=path, field=key)
    return value


def _expand_clouds(patterns, folder: Path, path: Path) -> tuple:
    """The files matching ``patterns``; each must lie in the project folder (or --allow-outside)."""
    from workstation.io.paths import resolve_inside

    if isinstance(patterns, str):
        patterns = [patterns]
    if not isinstance(patterns, list) or not patterns or not all(isinstance(p, str) for p in patterns):
        raise InvalidInputError("[inputs] clouds must be a pattern or a list of patterns",
                                'for example clouds = ["tiles/*.laz"]', path=path, field="inputs.clouds")
    found: set[Path] = set()
    for pattern in patterns:
        full = Path(pattern) if Path(pattern).is_absolute() else folder / pattern
        hits = [Path(h) for h in glob.glob(str(full), recursive=True)]
        if full.is_dir():
            hits = [p for p in full.iterdir()]
        hits = [h for h in hits if h.is_file() and h.suffix.lower() in CLOUD_SUFFIXES]
        if not hits:
            raise InvalidInputError(f"no LAS/LAZ/COPC file matches '{pattern}' (looked in {full.parent})",
                                    "check the pattern; it is relative to the project file's folder",
                                    path=path, field="inputs.clouds")
        found.update(resolve_inside(h, folder, source=path, field="inputs.clouds").resolve() for h in hits)
    return tuple(sorted(found))


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
    extra = sorted(set(inputs) - {"clouds"})
    if extra:
        raise InvalidInputError(f"[inputs] {', '.join(extra)} is not processed by ws run yet",
                                "ws run processes clouds; run photos through ws sfm and scans through ws register",
                                path=path, field=f"inputs.{extra[0]}")
    if "clouds" not in inputs:
        raise InvalidInputError("[inputs] has no clouds", 'add clouds = ["tiles/*.laz"]', path=path, field="inputs.clouds")
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
    return Project(path.resolve(), str(meta.get("name", path.parent.name or "project")),
                   _expand_clouds(inputs["clouds"], path.resolve().parent, path), crs, spec,
                   {k: dict(v) for k, v in stages.items()}, dict(dask))


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
