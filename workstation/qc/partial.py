"""``ws qc`` in parts: per-file partial states, per-block plane fits, one merge.

The checks of :mod:`workstation.qc.run` are accumulators; here each is run on one file of the
delivery at a time and its state saved, so that the files can be checked in parallel (the QC
stage of ``ws run``) and the merge gives the report of one ``ws qc`` over them all:

1. :func:`write_catalog` — the delivery's catalog from the headers (bounds, counts, CRS), the
   files' state folders and the blocks of step 4, in ``catalog.json``.
2. :func:`pass1_file` — pass 1 on one file: format validation, the single-swath density
   pieces, the classification histogram and ground cells on the window of the class grid the
   file covers (``pass1.npz``).
3. :func:`pass1_merge` — the pass-1 states added up: ANPS (hence the 2×ANPS grid of pass 2),
   the ground surface, bridge decks and water cells of the whole delivery (``surface.npz``,
   ``pass1.json``). The ground surface is one TIN over the delivery, so this step holds the
   class grid (as ``ws qc`` does); nothing else is held whole.
4. :func:`pass2_file` — pass 2 on one file: first returns and water per 2×ANPS cell of its
   window, its hull, the swath plane-fit sums per (swath, cell) of its points, the class
   surface counts and the ground points near checkpoints (``pass2.npz``, ``swath_keys.npy``,
   ``swath_sums.npy``).
5. :func:`fit_block` — the swath planes of the cells one block owns (:func:`cell_owner`),
   fitted on the sums of every file around them (the window of a cell reaches its
   neighbours), reduced to per-pair and per-swath figures that add up (``fit_<block>.npz``).
6. :func:`merge_report` — the report folder (``qc.json``, ``report.html``, the maps), from
   the states: coverage and voids on the whole 2×ANPS grid (a few bytes a cell), the swath
   figures from the blocks' fits, the class counts and checkpoint points added up.

Every state is a NumPy ``.npz`` (or ``.npy``) written atomically. Integer counts merge
exactly; sums of floating values (plane-fit sums of a cell fed by two files, the float32
ground-cell offsets, the swath areas) are added in another order than one pass adds them,
so figures made of them agree to rounding (about 1e-12 relative).
"""

from __future__ import annotations

import json
import math
import time
from pathlib import Path

import numpy as np

from workstation.core.errors import InvalidInputError, StageError
from workstation.io.registry import iter_chunks

from .run import QCParams

# ----------------------------------------------------------------------------- state files


def save_state(path: Path, meta: dict | None = None, **arrays) -> Path:
    """``arrays`` and the JSON-ready ``meta`` as one ``.npz``, atomically."""
    from workstation.io import atomic_path

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    with atomic_path(path, overwrite=True) as tmp, open(tmp, "wb") as f:
        np.savez(f, _meta=np.array(json.dumps(meta or {})), **arrays)
    return path


def load_state(path: Path) -> tuple[dict, dict]:
    """(meta, arrays) of a :func:`save_state` file; the arrays are read when used."""
    z = np.load(path, allow_pickle=False)
    return json.loads(str(z["_meta"])), z


def _save_npy(path: Path, a: np.ndarray) -> None:
    from workstation.io import atomic_path

    with atomic_path(path, overwrite=True) as tmp, open(tmp, "wb") as f:
        np.save(f, np.ascontiguousarray(a))


def _write_json(path: Path, doc: dict) -> Path:
    from workstation.core.jsonutil import dumps
    from workstation.io import atomic_path

    path.parent.mkdir(parents=True, exist_ok=True)
    with atomic_path(path, overwrite=True) as tmp:
        tmp.write_text(dumps(doc))
    return path


def _substate(z, prefix: str) -> dict:
    """The arrays of ``z`` named ``prefix`` + name, by name."""
    return {k[len(prefix):]: z[k] for k in z.files if k.startswith(prefix)}


def _prefixed(prefix: str, d: dict) -> dict:
    return {prefix + k: v for k, v in d.items()}


def _times(t0: float, c0: float) -> dict:
    """Wall and CPU seconds (this process, every thread) since ``t0``, ``c0``."""
    return {"seconds": round(time.perf_counter() - t0, 3), "cpu_s": round(time.process_time() - c0, 3)}


# ----------------------------------------------------------------------------- catalog
def write_catalog(paths, names: list[str], state_root: Path, blocks: list, block_size: float) -> dict:
    """Catalog the delivery ``paths`` (headers only) into ``state_root/catalog.json``.

    ``names`` are the files' state folders under ``state_root``; ``blocks`` the (ix, iy) of the
    square blocks of side ``block_size`` (CRS units) whose swath planes :func:`fit_block` fits.
    """
    from workstation.io.crs import crs_units

    from .run import header_spacing_m, read_catalog

    cat = read_catalog([Path(p) for p in paths])
    units = crs_units(cat.crs)
    doc = {"crs": cat.crs, "bounds": [float(b) for b in cat.bounds], "points": int(cat.point_count),
           "files": [str(t.path) for t in cat.tiles],
           "file_bounds": {str(t.path): [float(t.bounds[i]) for i in (0, 1, 3, 4)] for t in cat.tiles},
           "names": dict(zip((str(Path(p)) for p in paths), names)), "units": units.to_dict(),
           "header_spacing_m": header_spacing_m(cat, units), "blocks": [list(b) for b in blocks],
           "block_size": float(block_size)}
    _write_json(Path(state_root) / "catalog.json", doc)
    return doc


def read_json(path: Path) -> dict:
    return json.loads(Path(path).read_text())


def _units(doc: dict):
    from workstation.io.crs import crs_units

    return crs_units(doc["crs"])


def _class_params(cat: dict, params: QCParams):
    from .classes import ClassParams

    return ClassParams(cell_m=params.surface_cell_m or max(1.0, 2.0 * cat["header_spacing_m"]))


def _class_grid(cat: dict, params: QCParams):
    from .classes import class_grid

    cp = _class_params(cat, params)
    return class_grid(cat["bounds"], _units(cat), cp), cp


# ----------------------------------------------------------------------------- pass 1
def _first_z(chunk) -> float | None:
    """Median height of a chunk's usable single returns (the swath sums' reference height)."""
    from workstation.core.classes import NOISE

    a, keep = chunk.attrs, np.ones(chunk.n, bool)
    if "number_of_returns" in a:
        keep &= a["number_of_returns"] == 1
    if "withheld" in a:
        keep &= a["withheld"] == 0
    if "classification" in a:
        keep &= ~np.isin(a["classification"], np.asarray(NOISE, np.uint8))
    return float(np.median(chunk.xyz[keep, 2])) if keep.any() else None


def pass1_file(state_root: Path, path: str, params: QCParams, cat: dict) -> dict:
    """Pass 1 of ``ws qc`` on one file of the catalog, into ``<its folder>/pass1.npz``;
    ``cat``: the catalog (``catalog.json``, read once by the caller for every file)."""
    from .coverage import DensityPass
    from .classes import ClassPass1
    from .validate import FormatCheck

    t0, c0 = time.perf_counter(), time.process_time()
    grid, cp = _class_grid(cat, params)
    fmt, dens = FormatCheck(Path(path)), DensityPass(_units(cat))
    cls1 = ClassPass1(grid.window_over(cat["file_bounds"][path], pad=1), cp)
    z0, unreadable, n = None, None, 0
    try:
        for chunk in iter_chunks(Path(path), params.chunk_size):
            fmt.add(chunk)
            dens.add(chunk, path)
            cls1.add(chunk, path)
            z0 = _first_z(chunk) if z0 is None else z0
            n += chunk.n
    except InvalidInputError as exc:
        unreadable = str(exc)
    meta = {"file": path, "format": fmt.result(), "format_findings": [f.to_dict() for f in fmt.findings()],
            "z0": z0, "unreadable": unreadable}
    out = save_state(Path(state_root) / cat["names"][path] / "pass1.npz", meta,
                     **_prefixed("d_", dens.state()), **_prefixed("c_", cls1.state()))
    return {"points": n, **_times(t0, c0), "outputs": [str(out)]}


def pass1_merge(state_root: Path, params: QCParams) -> dict:
    """The pass-1 states of every file added up (see the module doc): ``pass1.json`` and the
    ground surface, deck floor and water cells in ``surface.npz`` (whole class grid)."""
    from .classes import ClassPass1, pass1_result
    from .coverage import DensityPass

    t0, c0 = time.perf_counter(), time.process_time()
    root = Path(state_root)
    cat = read_json(root / "catalog.json")
    units = _units(cat)
    grid, cp = _class_grid(cat, params)
    dens_states, cls_states, fmt, unreadable, z0 = [], [], {}, {}, None
    for f in cat["files"]:  # catalog order, as ws qc streams them
        meta, z = load_state(root / cat["names"][f] / "pass1.npz")
        dens_states.append(_substate(z, "d_"))
        cls_states.append(_substate(z, "c_"))
        fmt[f] = (meta["format"], meta["format_findings"])
        if meta["unreadable"]:
            unreadable[f] = meta["unreadable"]
        z0 = meta["z0"] if z0 is None else z0
    dens = DensityPass.from_states(units, dens_states)
    density = dens.result()
    anps = density.get("anps")
    if not anps or not np.isfinite(anps):
        raise InvalidInputError("no first returns to measure the point spacing", "check the return numbers",
                                path=cat["files"][0], field="return_number")
    from .run import catalog_coverage_grid

    catalog_coverage_grid(_CatalogView(cat), anps, units)  # refuses a grid too large, as ws qc does
    cls1 = ClassPass1.from_states(grid, cp, cls_states)
    del cls_states
    surface = cls1.surface()
    out = root / "surface.npz"
    save_state(out, None, surface=surface, deck=cls1.deck_floor(), water=cls1.water_mask())
    doc = {"anps": anps, "density": density, "density_findings": [f.to_dict() for f in dens.findings()],
           "format": fmt, "unreadable": unreadable, "z0": z0 if z0 is not None else 0.0,
           "surface_any": bool(np.isfinite(surface).any()), "classes_pass1": pass1_result(cls1)}
    _write_json(root / "pass1.json", doc)
    return {"anps": anps, **_times(t0, c0), "outputs": [str(out), str(root / "pass1.json")]}


class _CatalogView:
    """The catalog fields :func:`workstation.qc.run.catalog_coverage_grid` reads, from catalog.json."""

    def __init__(self, cat: dict):
        from types import SimpleNamespace

        self.bounds = tuple(cat["bounds"])
        self.tiles = [SimpleNamespace(path=Path(f)) for f in cat["files"]]


# ----------------------------------------------------------------------------- pass 2
def _pass2_checks(cat: dict, p1: dict, path: str, params: QCParams, surf):
    """The pass-2 checks of one file: coverage on its window of the 2×ANPS grid, swath sums on
    the whole grid (sparse), class surface tests on its window of the class grid, checkpoints."""
    from .accuracy import CheckpointPass
    from .classes import ClassPass2
    from .coverage import CoverageParams, CoveragePass, coverage_grid
    from .run import qc_checkpoints, swath_params
    from .specs import get_spec
    from .swath import SwathPass

    spec, units, box = get_spec(params.spec), _units(cat), cat["file_bounds"][path]
    grid2 = coverage_grid(cat["bounds"], p1["anps"], units)
    cov = CoveragePass(grid2.window_over(box, pad=1), p1["anps"], CoverageParams(required_coverage=spec.coverage_min))
    sw = SwathPass(grid2, swath_params(spec), z0=p1["z0"])
    cgrid, cp = _class_grid(cat, params)
    win = cgrid.window_over(box, pad=2)  # bilinear sampling reaches the next cell centre
    cls2 = ClassPass2(win, surf["surface"][win.block], cp, deck_floor=surf["deck"][win.block],
                      water=surf["water"][win.block], any_surface=p1["surface_any"])
    cps = qc_checkpoints(params)
    return grid2, cov, sw, cls2, (CheckpointPass(cps, units) if cps is not None else None)


def _off_window(grid, win, xy: np.ndarray) -> int:
    """How many of the points ``xy`` fall in ``grid`` but outside its window ``win``: one
    cell index on the whole grid serves both tests, a window computing a point's cell as its
    grid does (:class:`~workstation.qc.context.QCGrid`)."""
    row, col, inside = grid.index(xy)  # clipped into the grid: exact for the points inside it
    r0, c0 = win.row0 - grid.row0, win.col0 - grid.col0  # the window's offsets in ``grid``
    in_win = (row >= r0) & (row < r0 + win.rows) & (col >= c0) & (col < c0 + win.cols)
    return int(np.count_nonzero(inside & ~in_win))


def pass2_file(state_root: Path, path: str, params: QCParams, cat: dict) -> dict:
    """Pass 2 of ``ws qc`` on one file, into ``<its folder>/pass2.npz`` and the swath sums
    ``swath_keys.npy`` / ``swath_sums.npy`` (sorted (swath, cell) keys on the 2×ANPS grid);
    ``cat``: the catalog (``catalog.json``, read once by the caller for every file)."""
    t0, c0 = time.perf_counter(), time.process_time()
    root = Path(state_root)
    p1 = read_json(root / "pass1.json")
    folder = root / cat["names"][path]
    _, surf = load_state(root / "surface.npz")
    grid2, cov, sw, cls2, cpp = _pass2_checks(cat, p1, path, params, surf)
    n = off = 0
    if path not in p1["unreadable"]:
        try:
            for chunk in iter_chunks(Path(path), params.chunk_size):
                for c in (cov, sw, cls2, cpp):
                    if c is not None:
                        c.add(chunk, path)
                off += _off_window(grid2, cov.grid, chunk.xyz[:, :2])
                n += chunk.n
        except InvalidInputError as exc:
            raise StageError("qc", f"{path}: pass 2 cannot read what pass 1 read: {exc}", "check the file") from None
    keys, sums = sw.sums()
    _save_npy(folder / "swath_keys.npy", keys)
    _save_npy(folder / "swath_sums.npy", sums)
    cp = {} if cpp is None else cpp.state()
    out = save_state(folder / "pass2.npz", {"swath": sw.state(), "off_window": off},
                     **_prefixed("v_", cov.state()), **_prefixed("k_", cls2.state()), **_prefixed("p_", cp))
    return {"points": n, **_times(t0, c0),
            "outputs": [str(out), str(folder / "swath_keys.npy"), str(folder / "swath_sums.npy")]}


# ----------------------------------------------------------------------------- swath fits per block
def cell_owner(rows: np.ndarray, cols: np.ndarray, grid, size: float, blocks: np.ndarray) -> np.ndarray:
    """The index into ``blocks`` ((k, 2) block columns and rows, sorted by key) of the block
    owning each cell (row, col) of ``grid``: the block holding the cell's centre when it is one
    of ``blocks``, else the first of ``blocks`` holding one of the cell's corners (a cell with
    points meets a block, cells being smaller than blocks); -1 when none does."""
    keys = _block_key(blocks[:, 0], blocks[:, 1])
    x0, y1, c = grid.x0 + grid.col0 * grid.cell, grid.y1 - grid.row0 * grid.cell, grid.cell
    out = np.full(rows.shape, -1, np.int64)
    for fx, fy in ((0.5, 0.5), (0, 0), (1, 0), (0, 1), (1, 1)):  # centre first, then the corners
        ix = np.floor((x0 + (cols + fx) * c) / size).astype(np.int64)
        iy = np.floor((y1 - (rows + fy) * c) / size).astype(np.int64)
        k = _block_key(ix, iy)
        pos = np.clip(np.searchsorted(keys, k), 0, max(keys.size - 1, 0))
        hit = (out < 0) & (keys.size > 0) & (keys[pos] == k)
        out[hit] = pos[hit]
    return out


def _block_key(ix, iy) -> np.ndarray:
    return (np.asarray(ix, np.int64) + (1 << 30)) * (1 << 31) + (np.asarray(iy, np.int64) + (1 << 30))


def _sorted_blocks(cat: dict) -> np.ndarray:
    b = np.asarray(cat["blocks"], np.int64).reshape(-1, 2)
    return b[np.argsort(_block_key(b[:, 0], b[:, 1]))]


def _window_keys(folder: Path, grid2, r0: int, r1: int, c0: int, c1: int):
    """The swath keys and sums of one file whose cells lie in rows r0:r1, columns c0:c1."""
    keys = np.load(folder / "swath_keys.npy", mmap_mode="r")
    if keys.size == 0:
        return None
    row, col = np.divmod(np.asarray(keys) % (grid2.rows * grid2.cols), grid2.cols)
    sel = np.flatnonzero((row >= r0) & (row < r1) & (col >= c0) & (col < c1))
    if sel.size == 0:
        return None
    sums = np.load(folder / "swath_sums.npy", mmap_mode="r")
    return np.asarray(keys[sel]), np.asarray(sums[:, sel])


def fit_block(state_root: Path, ix: int, iy: int, params: QCParams) -> dict:
    """The swath planes of the 2×ANPS cells block (ix, iy) owns (:func:`cell_owner`), fitted
    on the sums of every file reaching their windows, reduced by :func:`~.swath.fit_state`."""
    from .coverage import coverage_grid
    from .run import swath_params
    from .specs import get_spec
    from .swath import fit_state

    t0, c0 = time.perf_counter(), time.process_time()
    root = Path(state_root)
    cat, p1 = read_json(root / "catalog.json"), read_json(root / "pass1.json")
    sp, size = swath_params(get_spec(params.spec)), cat["block_size"]
    grid2 = coverage_grid(cat["bounds"], p1["anps"], _units(cat))
    r = sp.window // 2
    if (r + 2) * grid2.cell > size:
        raise StageError("qc", f"the swath window ({sp.window} cells of {grid2.cell_m:.3g} m) does not fit in a block",
                         "use larger chunks")
    box = (ix * size, iy * size, (ix + 1) * size, (iy + 1) * size)
    own = grid2.window_over(box, pad=1)  # every cell the block may own
    ctx = grid2.window(own.row0 - r, own.row0 + own.rows + r, own.col0 - r, own.col0 + own.cols + r)
    x0, y1 = grid2.x0 + ctx.col0 * grid2.cell, grid2.y1 - ctx.row0 * grid2.cell
    reach = (x0, y1 - ctx.rows * grid2.cell, x0 + ctx.cols * grid2.cell, y1)
    parts = [p for f in cat["files"] if boxes_meet(cat["file_bounds"][f], reach, grid2.cell)
             and (p := _window_keys(root / cat["names"][f], grid2, ctx.row0, ctx.row0 + ctx.rows,
                                    ctx.col0, ctx.col0 + ctx.cols)) is not None]
    keys, sums = _merged(parts)
    row, col = np.divmod(keys % (grid2.rows * grid2.cols), grid2.cols)
    blocks = _sorted_blocks(cat)
    mine = np.searchsorted(_block_key(blocks[:, 0], blocks[:, 1]), _block_key(ix, iy))
    sel = np.flatnonzero(cell_owner(row, col, grid2, size, blocks) == mine)
    fit = fit_state(keys, sums, grid2, sp, sel)
    out = save_state(root / "fits" / f"fit_{ix}_{iy}.npz", {"keys": int(sel.size)}, **fit)
    return {"points": 0, "cells": int(sel.size), **_times(t0, c0), "outputs": [str(out)]}


def boxes_meet(b, box, pad: float = 0.0) -> bool:
    """Whether the 2-D boxes ``b`` and ``box`` (xmin, ymin, xmax, ymax) meet once ``b`` grows
    by ``pad`` on every side."""
    return not (b[2] + pad < box[0] or b[0] - pad > box[2] or b[3] + pad < box[1] or b[1] - pad > box[3])


def _merged(parts) -> tuple[np.ndarray, np.ndarray]:
    """Keys and sums of several files joined: sorted, the sums of a repeated key added."""
    if not parts:
        return np.zeros(0, np.int64), np.zeros((10, 0))
    keys = np.concatenate([k for k, _ in parts])
    sums = np.concatenate([s for _, s in parts], axis=1)
    order = np.argsort(keys, kind="stable")
    keys = keys[order]
    start = np.flatnonzero(np.r_[True, keys[1:] != keys[:-1]])
    return keys[start], np.add.reduceat(sums[:, order], start, axis=1)


# ----------------------------------------------------------------------------- merge
def _checkpoints(states: list[dict], params: QCParams, units):
    """The checkpoint pass of the whole delivery from the files' states (None without checkpoints)."""
    from .accuracy import CheckpointPass
    from .run import qc_checkpoints

    cps = qc_checkpoints(params)
    if cps is None:
        return None, None
    return CheckpointPass.from_states(cps, units, [s for s in states if "idx" in s]), cps


def merge_report(state_root: Path, params: QCParams, out_dir: Path, overwrite: bool = True) -> dict:
    """The report folder ``out_dir`` (``qc.json``, ``report.html``, maps) of the delivery from
    the states of :func:`pass1_merge`, :func:`pass2_file` and :func:`fit_block`."""
    from workstation.core.jsonutil import dumps
    from workstation.io.atomic import atomic_dir

    from .report import write_html

    t0 = time.perf_counter()
    with atomic_dir(out_dir, overwrite=overwrite) as tmp:
        doc = merged_document(state_root, params, tmp, t0)
        (tmp / "qc.json").write_text(dumps(doc, indent=1))
        write_html(doc, tmp / "report.html", tmp)
    return doc


def merged_document(state_root: Path, params: QCParams, maps_dir: Path, t0: float) -> dict:
    """The QC document of :func:`workstation.qc.run.run_qc`, from the saved states."""
    from .classes import class_result, pass2_merged
    from .coverage import CoverageParams, CoveragePass, coverage_grid
    from .run import document, finish, swath_params
    from .specs import get_spec
    from .swath import SwathPass

    root = Path(state_root)
    cat, p1 = read_json(root / "catalog.json"), read_json(root / "pass1.json")
    spec, units = get_spec(params.spec), _units(cat)
    grid2 = coverage_grid(cat["bounds"], p1["anps"], units)
    cov_st, cls_st, cp_st, sw_st, off = [], [], [], [], 0
    for f in cat["files"]:
        meta, z = load_state(root / cat["names"][f] / "pass2.npz")
        cov_st.append(_substate(z, "v_"))
        cls_st.append(_substate(z, "k_"))
        cp_st.append(_substate(z, "p_"))
        sw_st.append(meta["swath"])
        off += int(meta["off_window"])
    cov = CoveragePass.from_states(grid2, p1["anps"], CoverageParams(required_coverage=spec.coverage_min), cov_st)
    fits = [dict(load_state(root / "fits" / f"fit_{ix}_{iy}.npz")[1]) for ix, iy in cat["blocks"]
            if (root / "fits" / f"fit_{ix}_{iy}.npz").exists()]
    sw = SwathPass.from_fits(grid2, swath_params(spec), fits, sw_st)
    classes = class_result(p1["classes_pass1"], pass2_merged(cls_st), _class_params(cat, params))
    cpp, cps = _checkpoints(cp_st, params, units)
    fmt = {k: (r, found) for k, (r, found) in p1["format"].items()}
    doc = document(cat["files"], cat["points"], cat["crs"], units, fmt, p1["density"], p1["density_findings"], cov,
                   sw, classes, cpp, cps, params)
    if off:
        doc["findings"].append({"check": "coverage", "severity": "warning", "file": None, "field": "bounds",
                                "expected": "points inside their file's header bounds", "found": f"{off} outside",
                                "message": "points outside their file's header bounds were not counted"})
    return finish(doc, maps_dir, cat["crs"], cov, sw, spec, p1["unreadable"], t0)


def block_side(bounds, files: int) -> float:
    """The side of the square blocks of swath fits when the files are not chunks: the side of
    a square holding the delivery's area shared out evenly between its files."""
    x0, y0, x1, y1 = bounds
    return max(math.sqrt(max((x1 - x0) * (y1 - y0), 1.0) / max(files, 1)), 1.0)


def blocks_over(bounds_list, size: float) -> list[tuple[int, int]]:
    """The (ix, iy) of the blocks of side ``size`` that the boxes (xmin, ymin, xmax, ymax) meet."""
    return sorted({(ix, iy) for x0, y0, x1, y1 in bounds_list
                   for ix in range(math.floor(x0 / size), math.floor(x1 / size) + 1)
                   for iy in range(math.floor(y0 / size), math.floor(y1 / size) + 1)})


def qc_in_parts(paths, out_dir: Path, params: QCParams, work: Path, block_size: float | None = None) -> dict:
    """Every step of the module doc one after the other in this process, states in ``work``:
    what ``ws run``'s QC tasks do in parallel, for a delivery checked without a cluster."""
    from workstation.io.catalog import read_tile_info

    paths = [str(Path(p)) for p in paths]
    boxes = [(b[0], b[1], b[3], b[4]) for b in (read_tile_info(Path(p)).bounds for p in paths)]
    size = block_size or block_side((min(b[0] for b in boxes), min(b[1] for b in boxes),
                                     max(b[2] for b in boxes), max(b[3] for b in boxes)), len(paths))
    blocks = blocks_over(boxes, size)
    write_catalog(paths, [f"f{i}" for i in range(len(paths))], work, blocks, size)
    cat = read_json(Path(work) / "catalog.json")  # as the tasks read it, once for every file
    for p in paths:
        pass1_file(work, p, params, cat)
    pass1_merge(work, params)
    for p in paths:
        pass2_file(work, p, params, cat)
    for ix, iy in blocks:
        fit_block(work, ix, iy, params)
    return merge_report(work, params, Path(out_dir))
