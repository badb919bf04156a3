"""``ws qc``: check a LiDAR delivery against a specification, in two streaming passes.

The delivery's catalog comes from the file headers (:func:`workstation.io.catalog.build_catalog`:
bounds, counts, one CRS). Pass 1 streams every file once through the checks that need nothing
measured beforehand; its aggregate nominal point spacing (ANPS) then sizes the grid of pass 2
(cells of 2×ANPS, as the USGS Lidar Base Specification grids density and swath separation).
The checks are accumulators (:mod:`workstation.qc.context`), so memory is bounded by the grids
and one chunk, whatever the number of points. :mod:`workstation.qc.partial` runs the same checks
file by file and merges their states into the same document (the QC stage of ``ws run``).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from workstation.core.errors import InvalidInputError
from workstation.core.log import get_logger
from workstation.io.crs import crs_units
from workstation.io.registry import check_selection, format_of, iter_chunks

from .context import QCGrid
from .specs import dig

log = get_logger(__name__)


@dataclass(frozen=True)
class QCParams:
    """What ``ws qc`` checks and against which specification.

    Attributes
    ----------
    spec : str
        Specification name (:func:`workstation.qc.specs.get_spec`): ``usgs-ql0``…``usgs-ql3`` or
        ``asprs-<X>cm``.
    checkpoints : Path or None
        Checkpoint CSV (id, x, y, z, land cover) in the delivery's CRS units.
    checkpoint_rmse_m : float
        The checkpoints' own vertical RMSE (m), combined into the Edition 2 accuracy.
    dem : Path or None
        A DEM GeoTIFF of the delivery to check against the checkpoints and the 3× rules.
    surface_cell_m : float or None
        Cell of the ground surface used by the classification checks (m); default the larger of
        1 m and twice the header's mean point spacing.
    chunk_size : int
        Points read at a time.
    read_opts : dict or None
        ``bounds``/``resolution``/``level`` (None = not given): check only the points they
        select (:func:`workstation.io.iter_chunks`); the coverage grid is then cut to ``bounds``.
    """

    spec: str = "usgs-ql2"
    checkpoints: Path | None = None
    checkpoint_rmse_m: float = 0.0
    dem: Path | None = None
    surface_cell_m: float | None = None
    chunk_size: int = 2_000_000
    read_opts: dict | None = None


def read_catalog(paths):
    from workstation.io.catalog import build_catalog

    for p in paths:
        if format_of(p)[0] not in ("las", "laz"):
            raise InvalidInputError("ws qc checks LAS/LAZ/COPC deliveries", "convert it first: ws convert IN OUT.laz",
                                    path=p, field="INPUT")
    return build_catalog(paths, inputs_hint="give the delivery's LAS/LAZ/COPC files")


def catalog_coverage_grid(cat, anps_m: float, units, bounds=None) -> QCGrid:
    """The 2×ANPS grid over the catalog (:func:`workstation.qc.coverage.coverage_grid`), cut to
    ``bounds`` (xmin, ymin, xmax, ymax[, ...]) when given, refused when it would not fit in memory
    (the extent is then too large for its spacing: check it in pieces)."""
    from workstation.core.budget import check_grid

    from .coverage import coverage_grid

    box = cat.bounds
    if bounds is not None:
        x0, y0, x1, y1 = cat.bounds
        box = (max(x0, bounds[0]), max(y0, bounds[1]), min(x1, bounds[2]), min(y1, bounds[3]))
    g = coverage_grid(box, anps_m, units)
    check_grid(g.rows, g.cols, what="2×ANPS coverage grid", option="INPUT extent", bytes_per_cell=64.0,
               path=", ".join(t.path.name for t in cat.tiles[:3]))
    return g


def header_spacing_m(cat, units) -> float:
    """Mean point spacing (m) over the catalog's extent, from the headers alone."""
    x0, y0, x1, y1 = cat.bounds
    area = max((x1 - x0) * (y1 - y0), 1e-12) * units.h**2
    return math.sqrt(area / max(cat.point_count, 1))


def _stream(cat, checks, chunk_size: int, advance, per_file=None, unreadable=None, read_opts=None) -> None:
    """Feed every chunk of every file to ``checks`` (``add(chunk, source)``) and to the file's
    own check in ``per_file`` ({path: check with ``add(chunk)``}). A file whose points cannot be
    read (a header count the data does not hold) is recorded in ``unreadable`` ({path: reason})
    and left out; the other files go on. ``read_opts`` selects the points read (chunks it leaves
    empty are skipped)."""
    unreadable = {} if unreadable is None else unreadable
    for t in cat.tiles:
        src = str(t.path)
        if src in unreadable:
            continue
        own = (per_file or {}).get(src)
        try:
            for chunk in iter_chunks(t.path, chunk_size, **(read_opts or {})):
                if chunk.n == 0:
                    continue
                if own is not None:
                    own.add(chunk)
                for c in checks:
                    c.add(chunk, src)
                advance(chunk.n)
        except InvalidInputError as exc:
            unreadable[src] = str(exc)


def _unreadable_findings(unreadable: dict) -> list[dict]:
    from .context import Finding

    return [Finding("format", "error", f, "points", "readable point records", "unreadable",
                    f"the points could not be read, so the file is left out of every other check: {why}").to_dict()
            for f, why in unreadable.items()]


def run_qc(paths, out_dir: Path, params: QCParams = QCParams()) -> dict:
    """Check the delivery ``paths`` and write its maps into ``out_dir`` (an existing folder).

    Returns
    -------
    dict
        The QC document: ``points``, ``anpd`` (pts/m²), ``anps`` (m), ``coverage``, ``voids``,
        ``swaths``, ``nva``, ``vva`` (m or None), ``verdict``, ``findings`` and one section per
        check; every length in metres.
    """
    from workstation.core.progress import progress_bar

    from .specs import get_spec

    spec = get_spec(params.spec)
    t0 = time.perf_counter()
    paths = [Path(p) for p in paths]
    cat = read_catalog(paths)
    units = crs_units(cat.crs)
    cps = qc_checkpoints(params)
    surface_cell = params.surface_cell_m or max(1.0, 2.0 * header_spacing_m(cat, units))
    fmt, dens, cls1 = _pass1_checks(cat, units, surface_cell)
    unreadable: dict = {}
    sel = {k: v for k, v in (params.read_opts or {}).items() if v is not None}
    for p in paths:  # a --level on a non-COPC file is a usage mistake, not an unreadable file
        check_selection(p, **sel)
    read = []  # points of each chunk read in pass 1 (the selection's count when one is given)
    with progress_bar("qc pass 1 of 2", cat.point_count, "points") as advance:
        _stream(cat, [dens, cls1], params.chunk_size, lambda n: (read.append(n), advance(n)), per_file=fmt,
                unreadable=unreadable, read_opts=sel)
    if sel.get("bounds") is not None and sum(read) == 0:
        raise InvalidInputError(f"no points inside --bounds {','.join(f'{v:g}' for v in sel['bounds'])}",
                                "compare the box with the files' bounds (ws info --summary FILE)", field="--bounds")
    density = dens.result()
    anps = density.get("anps")
    if not anps or not np.isfinite(anps):
        raise InvalidInputError("no first returns to measure the point spacing", "check the return numbers",
                                path=paths[0], field="return_number")
    grid2 = catalog_coverage_grid(cat, anps, units, sel.get("bounds"))
    cov, sw, cls2, cpp = _pass2_checks(grid2, anps, cls1, cps, units, spec)
    with progress_bar("qc pass 2 of 2", cat.point_count, "points") as advance:
        _stream(cat, [c for c in (cov, sw, cls2, cpp) if c is not None], params.chunk_size, advance,
                unreadable=unreadable, read_opts=sel)
    doc = _document(cat, units, fmt, dens, density, cov, sw, cls1, cls2, cpp, cps, params,
                    points=sum(read) if sel else None)
    return finish(doc, out_dir, cat.crs, cov, sw, spec, unreadable, t0)


def finish(doc: dict, out_dir: Path, crs, cov, sw, spec, unreadable: dict, t0: float) -> dict:
    """The QC document completed: unreadable files' findings first, the maps written into
    ``out_dir``, the verdict against ``spec`` and the seconds since ``t0``."""
    from .specs import verdict

    doc["findings"] = _unreadable_findings(unreadable) + doc["findings"]
    doc["maps"] = _write_maps(out_dir, crs, cov, sw)
    doc["verdict"] = verdict(spec, doc)
    doc["seconds"] = round(time.perf_counter() - t0, 2)
    return doc


def qc_checkpoints(params: QCParams):
    if params.checkpoints is None:
        return None
    from .accuracy import read_checkpoints

    return read_checkpoints(params.checkpoints)


def _pass1_checks(cat, units, surface_cell_m: float):
    from .classes import ClassParams, ClassPass1, class_grid
    from .coverage import DensityPass
    from .validate import FormatCheck

    fmt = {str(t.path): FormatCheck(t.path) for t in cat.tiles}
    cp = ClassParams(cell_m=surface_cell_m)
    return fmt, DensityPass(units), ClassPass1(class_grid(cat.bounds, units, cp), cp)


def swath_params(spec):
    """The swath check's parameters, its limits taken from the specification."""
    from .swath import SwathParams

    return SwathParams(**{k: v for k, v in (("rmsdz_limit_m", spec.rmsdz_max), ("max_dz_limit_m", spec.max_dz),
                                            ("precision_limit_m", spec.intraswath_max)) if v is not None})


def _pass2_checks(grid2, anps, cls1, cps, units, spec):
    """The pass-2 checks, their limits taken from the specification."""
    from .accuracy import CheckpointPass
    from .coverage import CoverageParams, CoveragePass
    from .swath import SwathPass

    cpp = CheckpointPass(cps, units) if cps is not None else None
    return (CoveragePass(grid2, anps, CoverageParams(required_coverage=spec.coverage_min)),
            SwathPass(grid2, swath_params(spec)), cls1.second_pass(), cpp)


def _document(cat, units, fmt, dens, density, cov, sw, cls1, cls2, cpp, cps, params, points=None) -> dict:
    """Assemble the QC document from the checks (lengths in metres); ``points`` replaces the
    headers' point count when a selection was read."""
    from .classes import class_checks

    points = cat.point_count if points is None else points
    return document([str(t.path) for t in cat.tiles], int(points), cat.crs, units,
                    {k: (c.result(), [f.to_dict() for f in c.findings()]) for k, c in fmt.items()},
                    density, [f.to_dict() for f in dens.findings()], cov, sw, class_checks(cls1, cls2), cpp, cps,
                    params)


def document(files, points, crs, units, fmt: dict, density: dict, density_findings: list, cov, sw, classes: dict,
             cpp, cps, params) -> dict:
    """The QC document from the checks' results: ``fmt`` {file: (result, findings)} and the
    density's result and findings as dicts, the coverage and swath checks, the classification
    result, the checkpoint pass (or None). Shared by ``ws qc`` and the chunked QC of ``ws run``."""
    from .classes import class_findings

    coverage, swath = cov.result(), sw.result()
    accuracy = _accuracy(cpp, params) if cpp is not None else None
    dem = _dem_accuracy(params, cps, density) if params.dem is not None else None
    findings = [f for _, found in fmt.values() for f in found] + list(density_findings)
    for c in (cov, sw):
        findings += [f.to_dict() for f in c.findings()]
    findings += [f.to_dict() for f in class_findings(classes)]
    if cpp is not None:
        findings += [f.to_dict() for f in getattr(cpp, "findings", lambda: [])()]
    return {
        "files": list(files), "points": int(points), "crs": crs,
        "units": units.to_dict(), "anpd": density.get("anpd"), "anps": density.get("anps"),
        "coverage": coverage.get("coverage"), "voids": coverage.get("voids"),
        "swaths": swath.get("swaths", []),
        "nva": dig(accuracy, "asprs2014", "nva"), "vva": dig(accuracy, "asprs2014", "vva"),
        "format": {k: r for k, (r, _) in fmt.items()},
        "density": density, "coverage_detail": coverage, "swath": swath, "classes": classes,
        "accuracy": accuracy, "dem_accuracy": dem, "findings": findings,
    }


def _accuracy(cpp, params: QCParams) -> dict:
    from .accuracy import vertical_accuracy

    table = cpp.result()
    rows = [r for r in table["checkpoints"] if r.get("dz") is not None]
    dz = np.array([r["dz"] for r in rows], float)
    veg = np.array([bool(r["vegetated"]) for r in rows], bool)
    acc = vertical_accuracy(dz, veg, checkpoint_rmse_m=params.checkpoint_rmse_m, ids=[r["id"] for r in rows])
    return {**acc, "checkpoints": table["checkpoints"], "unmatched": table.get("unmatched", [])}


def _dem_accuracy(params: QCParams, cps, density) -> dict:
    from .accuracy import dem_accuracy, three_x_rule

    d = dem_accuracy(params.dem, cps, checkpoint_rmse_m=params.checkpoint_rmse_m) if cps is not None else {}
    cell_m = d.get("cell_m") if d else None
    if cell_m is None:
        from workstation.io.crs import raster_units
        from workstation.io.geotiff import read_raster

        r = read_raster(params.dem, band=1)
        cell_m = abs(r.transform[0]) * raster_units(r).h
        d = {**d, "cell_m": cell_m}
    d["rules"] = three_x_rule(cell_m, dig(d, "rmsez"), density.get("anps"),
                              checkpoint_rmse_m=params.checkpoint_rmse_m or None)
    return d


def _write_maps(out_dir: Path, crs, cov, sw) -> dict:
    """The maps of the checks (density, voids, DZ) in ``out_dir``; names relative to it."""
    maps = {}
    for check in (cov, sw):
        for name, path in check.write(Path(out_dir), crs).items():
            maps[name] = Path(path).name
    return maps


def write_qc(paths, out_dir, params: QCParams = QCParams(), overwrite: bool = False) -> dict:
    """:func:`run_qc` into the report folder ``out_dir``: ``report.html``, ``qc.json`` and the
    maps, built beside it and swapped in whole (nothing half-written is ever left)."""
    from workstation.core.jsonutil import dumps
    from workstation.io.atomic import atomic_dir

    from .report import write_html

    with atomic_dir(out_dir, overwrite=overwrite) as tmp:
        doc = run_qc(paths, tmp, params)
        (tmp / "qc.json").write_text(dumps(doc, indent=1))
        write_html(doc, tmp / "report.html", tmp)
    return doc
