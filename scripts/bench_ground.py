"""Ground-filter benchmarks; one JSON line per result on stdout.

  python scripts/bench_ground.py isprs  [--data DIR] [--methods smrf,csf,...]   per-sample ISPRS errors
  python scripts/bench_ground.py tiles  [--data DIR] [--methods ...]           1 m TIN DTM RMSE vs the file's class 2,
                                        with the bias and where our extra ground lies above the file's TIN
  python scripts/bench_ground.py speed  [--points 5000000] [--methods ...]     points/s on a synthetic tile (method
                                                                             noise: ws noise)
  python scripts/bench_ground.py sim    --sim-dir DIR [--methods ...]          simulated ALS (ws simulate als --scene
                                        datasets_synth/{urban,rural,forest,mountain}.toml -o DIR/<name>.laz)
  python scripts/bench_ground.py memory [--sizes 1000000,2000000,4000000] [--methods ...] [--tile-points N]
                                        peak memory of each filter in a child process, above the tile's own
  python scripts/bench_ground.py bridges [--methods ...] [--with-ml] [--seeds 0,1]  bridge decks on the simulated gallery
                                        (tests/ground/gallery_scenes.py): deck points in ground (%), deck F1 as
                                        class 17, class-17 points on the earthworks; --with-ml adds ws classify
                                        and ws classify --crests (classify_crests)
  python scripts/bench_ground.py ridges [--methods ...] [--with-ml] [--seeds 0,1]   a steep ridge's top kept as ground
                                        and the total error on the gallery's ridge scene (samp61's failure mode)
  python scripts/bench_ground.py bounds [--data DIR] [--with-ml]              what any rule over auto's five member
                                        flags (and the point classifier's, --with-ml) could reach on the six ISPRS
                                        samples when the rule is picked with the reference labels

--set NAME=VALUE (repeatable) overrides a parameter of every method, e.g. ``--set threshold=0.3``.
DIR defaults to ../shared/data (or $WS_SHARED_DATA). Timings: wall and process (CPU) seconds.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from workstation.core.cloud import Cloud  # noqa: E402
from workstation.ground.evaluate import ground_errors, read_isprs_text  # noqa: E402
from workstation.ground.methods import ground_filter  # noqa: E402

SAMPLES = ["samp11", "samp21", "samp31", "samp42", "samp51", "samp61"]
PUBLISHED = {  # total error %, /work/shared/data/README.md
    "axelsson_ptd": {"samp11": 10.76, "samp21": 4.25, "samp31": 4.78, "samp42": 1.62, "samp51": 2.72, "samp61": 2.08},
    "csf_paper": {"samp11": 12.01, "samp21": 3.42, "samp31": 1.61, "samp42": 1.58, "samp51": 3.08, "samp61": 1.49},
    "smrf_tuned": {"samp11": 9.19, "samp21": 1.47, "samp31": 1.18, "samp42": 2.04, "samp51": 1.68, "samp61": 0.88},
}
OVERRIDES: dict = {}
TILES = ["Topography.laz", "bcts_1.laz", "bcts_2.laz", "autzen_trim.las", "MixedConifer.laz"]


def emit(d):
    print(json.dumps(d), flush=True)


def timed(fn):
    t, c = time.perf_counter(), time.process_time()
    out = fn()
    return out, time.perf_counter() - t, time.process_time() - c


def bench_isprs(data: Path, methods):
    for m in methods:
        tot = []
        for s in SAMPLES:
            ref = read_isprs_text(data / "isprs" / f"{s}.txt")
            cloud = Cloud(ref.xyz)
            out, wall, cpu = timed(lambda: ground_filter(cloud, m, **OVERRIDES))
            e = ground_errors(np.asarray(ref.attrs["label"]) == 0, np.asarray(out.attrs["classification"]) == 2)
            tot.append(e.total_error)
            emit({"bench": "isprs", "method": m, "sample": s, "type1": e.type1, "type2": e.type2,
                  "total_error": e.total_error, "kappa": e.kappa, "seconds": wall, "cpu_seconds": cpu})
        emit({"bench": "isprs", "method": m, "sample": "mean", "total_error": float(np.mean(tot))})


def _tin_at(xyz, sel, q, origin):
    """TIN of the points ``sel`` sampled at local ``q`` (xy minus ``origin``; NaN outside the hull)."""
    from workstation.ground.common import _one_blas_thread, delaunay, tin_eval

    tri = delaunay(xyz[sel, :2] - origin)
    with _one_blas_thread():
        return tin_eval(tri, xyz[sel, 2], q)


def dtm_rmse(xyz, ours, theirs, cell):
    """RMSE, cell count and mean difference (CRS z unit) between TIN DTMs of two ground sets on a
    ``cell`` grid inside both hulls."""
    lo, hi = xyz[:, :2].min(axis=0), xyz[:, :2].max(axis=0)
    gx, gy = np.meshgrid(np.arange(lo[0] + cell / 2, hi[0], cell), np.arange(lo[1] + cell / 2, hi[1], cell))
    q = np.column_stack([gx.ravel(), gy.ravel()]) - lo
    zs = [_tin_at(xyz, g, q, lo) for g in (ours, theirs)]
    ok = np.isfinite(zs[0]) & np.isfinite(zs[1])
    d = zs[0][ok] - zs[1][ok]
    return float(np.sqrt(np.mean(d * d))), int(ok.sum()), float(np.mean(d))


def height_above_tin(xyz, ground):
    """Height (CRS z unit) of every point above the TIN of ``ground`` (NaN outside its hull)."""
    lo = xyz[:, :2].min(axis=0)
    return xyz[:, 2] - _tin_at(xyz, ground, xyz[:, :2] - lo, lo)


def bench_tiles(data: Path, methods):
    from workstation.ground.common import crs_unit_factors
    from workstation.io import read_cloud

    for f in TILES:
        c = read_cloud(data / "lidar" / f)
        hf, vf = crs_unit_factors(c.crs)
        cls = np.asarray(c.attrs["classification"])
        ref = cls == 2
        # the file's ground as a surface: how many of its other last returns lie under it
        h = height_above_tin(c.xyz, ref) * vf
        last = np.asarray(c.attrs["return_number"]) == np.asarray(c.attrs["number_of_returns"])
        other = ~ref & last & np.isfinite(h) & (cls != 9)
        for m in methods:
            out, wall, cpu = timed(lambda: ground_filter(c, m, reclassify=True, **OVERRIDES))
            g = np.asarray(out.attrs["classification"]) == 2
            rmse, cells, bias = dtm_rmse(c.xyz, g, ref, 1.0 / hf)
            extra = g & ~ref & np.isfinite(h)
            emit({"bench": "tiles", "file": f, "method": m, "overrides": OVERRIDES, "dtm_rmse_m": rmse * vf,
                  "dtm_bias_m": bias * vf, "dtm_rmse_without_water_m": dtm_rmse(c.xyz, g & (cls != 9), ref, 1.0 / hf)[0] * vf,
                  "cells": cells, "ground_ours": int(g.sum()), "ground_file": int(ref.sum()), "points": c.n,
                  "file_other_last_returns_below_file_tin_0.1m": float(np.mean(h[other] < -0.1)),
                  "our_extra_ground_above_file_tin_p5_p50_p95_m": [round(float(x), 3) for x in np.percentile(h[extra], [5, 50, 95])] if extra.any() else None,
                  "seconds": wall, "cpu_seconds": cpu})


def synthetic_tile(n: int, data: Path):
    """A tile of ``n`` points: bcts_2 repeated on a grid of shifted copies with jitter."""
    from workstation.io import read_cloud

    c = read_cloud(data / "lidar" / "bcts_2.laz")
    xyz = c.xyz - c.xyz.min(axis=0)
    span = np.ptp(xyz[:, :2], axis=0)
    k = int(np.ceil(n / c.n))
    side = int(np.ceil(np.sqrt(k)))
    rng = np.random.default_rng(0)
    parts = []
    for i in range(k):
        sx, sy = (i % side) * span[0], (i // side) * span[1]
        p = xyz + [sx, sy, 0.0]
        parts.append(p + rng.normal(0, 0.02, p.shape))
    allp = np.concatenate(parts)[:n]
    rn = np.ones(n, np.uint8)
    return Cloud(allp + [500000.0, 5000000.0, 0.0], {"return_number": rn, "number_of_returns": rn})


def bench_speed(data: Path, methods, n: int):
    from workstation.ground.noise import classify_noise

    tile = synthetic_tile(n, data)
    for m in methods:  # "noise": ws noise (statistical and isolated-low outliers), not a ground filter
        out, wall, cpu = timed(lambda: classify_noise(tile) if m == "noise" else ground_filter(tile, m))
        emit({"bench": "speed", "method": m, "points": tile.n, "seconds": wall, "cpu_seconds": cpu,
              "points_per_s": tile.n / wall, "points_per_cpu_s": tile.n / cpu})
        if m == "csf":
            # the package alone at the same cloth resolution, same points
            import CSF

            from workstation.ground.csf import CSFParams, _StdoutToStderr

            p = CSFParams()
            xyz = np.ascontiguousarray(tile.xyz - tile.xyz.min(axis=0))

            def pkg():
                cs = CSF.CSF()
                cs.params.cloth_resolution = p.cloth_resolution
                cs.params.rigidness = p.rigidness
                cs.params.bSloopSmooth = p.slope_smooth
                cs.setPointCloud(xyz)
                g, ng = CSF.VecInt(), CSF.VecInt()
                with _StdoutToStderr():
                    cs.do_filtering(g, ng, False)

            _, wall2, cpu2 = timed(pkg)
            emit({"bench": "speed", "method": "csf_package", "points": tile.n, "seconds": wall2, "cpu_seconds": cpu2,
                  "points_per_s": tile.n / wall2, "points_per_cpu_s": tile.n / cpu2})


def _vm(field: str) -> float:
    """A ``/proc/self/status`` memory field (VmRSS, VmHWM) in MB."""
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith(field + ":"):
            return int(line.split()[1]) / 1024.0
    raise RuntimeError(f"no {field} in /proc/self/status")


def _memory_child(data: Path, method: str, n: int, tile_points: int):
    import gc

    from workstation.ground.tiles import TileParams

    tiles = TileParams(tile_points) if tile_points else None
    tile = synthetic_tile(n, data)
    gc.collect()
    Path("/proc/self/clear_refs").write_text("5")  # the peak (VmHWM) restarts from the current RSS
    base = _vm("VmRSS")
    _, wall, cpu = timed(lambda: ground_filter(tile, method, tiles=tiles))
    peak = _vm("VmHWM")
    emit({"bench": "memory", "method": method, "points": n, "tile_points": tile_points, "rss_before_mb": base, "peak_mb": peak,
          "filter_mb": peak - base, "filter_bytes_per_point": (peak - base) * 2**20 / n,
          "seconds": wall, "cpu_seconds": cpu})


def bench_memory(data: Path, methods, sizes, tile_points: int):
    """Peak resident memory of each filter above the tile it is given, in a fresh process per
    run (Linux: /proc/self/status, the peak reset after the tile is built)."""
    import subprocess

    for m in methods:
        for n in sizes:
            out = subprocess.run([sys.executable, __file__, "_memchild", "--data", str(data), "--methods", m,
                                  "--points", str(n), "--tile-points", str(tile_points)],
                                 capture_output=True, text=True, check=True)
            print(out.stdout.strip().splitlines()[-1], flush=True)


def bench_sim(sim_dir: Path, methods):
    """Ground/non-ground errors on simulated ALS against the simulator's classes (bare earth:
    ground 2, water 9, road 11)."""
    from workstation.ground.evaluate import evaluate_labels
    from workstation.io import read_cloud

    for name in ("urban", "rural", "forest", "mountain"):
        f = sim_dir / f"{name}.laz"
        if not f.exists():
            continue
        c = read_cloud(f)
        truth = np.asarray(c.attrs["classification"])
        for m in methods:
            out, wall, cpu = timed(lambda: ground_filter(c, m, **{"reclassify": True, **OVERRIDES}))
            pred = np.asarray(out.attrs["classification"])
            ev = evaluate_labels(truth, np.where(pred == 2, 2, 1), ground_classes=(2, 9, 11))
            emit({"bench": "sim", "scene": name, "method": m, "overrides": OVERRIDES, "points": c.n,
                  "type1": ev.type1, "type2": ev.type2,
                  "total_error": ev.total_error, "kappa": ev.kappa, "seconds": wall, "cpu_seconds": cpu})


def bench_bounds(data: Path, with_ml: bool):
    """Upper bounds of ``auto``'s vote: each point's pattern of member flags (32 patterns; 64
    with the point classifier's ground) is mapped to ground or object by a rule picked with the
    reference labels, once for all six samples (each weighted by 1/n, so the rule minimises the
    mean) and once per sample; then ``auto``'s steps after the vote. No rule over these flags
    with one setting for all terrain can score below the first bound."""
    from workstation.ground import auto as A
    from workstation.ground import common

    p = A.AutoParams()
    rows = {}
    for s in SAMPLES:
        ref = read_isprs_text(data / "isprs" / f"{s}.txt")
        cloud = Cloud(ref.xyz)
        prep = common.prepare(cloud, A.STAGE, p.reclassify, p.last_returns_only)
        truth = (np.asarray(ref.attrs["label"]) == 0)[prep.index]
        flags = list(A.member_votes(prep.xyz, p))
        votes = np.sum(flags, axis=0, dtype=np.int8)
        if with_ml:
            from workstation.ml.ground import MLGroundParams, ml_ground

            ml = np.asarray(ml_ground(cloud, MLGroundParams(raised_patches=False)).attrs["classification"]) == 2
            flags.append(ml[prep.index])
        code = np.sum([f.astype(np.int64) << i for i, f in enumerate(flags)], axis=0)
        rows[s] = (prep.xyz, votes, code, truth)
    size = 1 << (5 + with_ml)

    def picked(samples):
        g = np.zeros(size)
        o = np.zeros(size)
        for s in samples:
            _, _, code, truth = rows[s]
            g += np.bincount(code[truth], minlength=size) / len(truth)
            o += np.bincount(code[~truth], minlength=size) / len(truth)
        return g > o

    pooled = picked(SAMPLES)
    rules = {"vote_3_of_5": lambda s, v, code: v >= p.min_votes,
             "best_rule_for_all": lambda s, v, code: pooled[code],
             "best_rule_per_sample": lambda s, v, code: picked([s])[code]}
    for name, rule in rules.items():
        raw, refined = [], []
        for s in SAMPLES:
            xyz, votes, code, truth = rows[s]
            g = rule(s, votes, code)
            r = A.refine_vote(xyz, g, votes, p)
            raw.append(ground_errors(truth, g).total_error)
            refined.append(ground_errors(truth, r).total_error)
            emit({"bench": "bounds", "rule": name, "with_ml": with_ml, "sample": s,
                  "total_error_vote": raw[-1], "total_error": refined[-1]})
        emit({"bench": "bounds", "rule": name, "with_ml": with_ml, "sample": "mean",
              "total_error_vote": float(np.mean(raw)), "total_error": float(np.mean(refined))})


def bench_bridges(methods, with_ml: bool, seeds=(0,)):
    """Deck points in each method's ground (%) and deck F1 as class 17 on the gallery's bridge
    scenes: vertical abutments, spill-through ones (the tuning scenes ``spill_1.5`` and
    ``spill_dev``; ``spill_held`` and ``spill_held2`` are kept for validation) and the
    earthworks (no deck)."""
    sys.path.insert(0, str(REPO / "tests" / "ground"))
    from gallery_scenes import bridges, earthworks, spill_through

    scenes = {"vertical": lambda k: bridges(seed=k), "spill_1.5": lambda k: bridges(seed=k, abutment_slope=1.5),
              "spill_dev": lambda k: spill_through(seed=k, preset="dev"),
              "spill_held": lambda k: spill_through(seed=k, preset="held"),
              "spill_held2": lambda k: spill_through(seed=k, preset="held2"), "earthworks": lambda k: earthworks(seed=k)}
    runs = _runs(methods, with_ml)
    for seed in seeds:
        for name, make in scenes.items():
            _bridge_rows(name, seed, make(seed), runs)


def bench_ridges(methods, with_ml: bool, seeds=(0,)):
    """The share of a steep ridge's top each method keeps as ground, and its total error against
    the true terrain (points within 0.3 m of it), on the gallery's ridge scene
    (:func:`gallery_scenes.ridges`: the failure mode of ISPRS samp61's crests, sparse old ALS);
    at 0.16 and 4 points/m² and with 1:1 and 1:2 faces."""
    sys.path.insert(0, str(REPO / "tests" / "ground"))
    from gallery_scenes import ridges

    from workstation.ground.evaluate import ground_errors

    runs = _runs(methods, with_ml)
    for seed in seeds:
        for pulses, side in ((0.16, 1.0), (0.16, 2.0), (4.0, 1.0)):
            cloud, terrain, top, _ = ridges(seed=seed, pulses=pulses, side=side)
            truth = np.abs(cloud.xyz[:, 2] - terrain(cloud.xyz[:, :2])) < 0.3
            for m, run in runs:
                cls, wall, cpu = timed(lambda: run(cloud))
                g = cls == 2
                emit({"bench": "ridges", "seed": seed, "pulses_per_m2": pulses, "side": side, "method": m,
                      "top_points": int(top.sum()), "top_kept": float(np.mean(g[top])),
                      "total_error_pct": 100.0 * ground_errors(truth, g).total_error, "seconds": wall, "cpu_seconds": cpu})


def _runs(methods, with_ml: bool) -> list:
    """(name, cloud -> classes) of each ground method, and ``ws classify`` and ``ws classify
    --crests`` with ``with_ml``."""
    runs = [(m, lambda c, m=m: np.asarray(ground_filter(c, m, **OVERRIDES).attrs["classification"])) for m in methods]
    if with_ml:
        from workstation.ml.classifier import PointClassifier

        runs.append(("classify", PointClassifier.load(device="cpu").predict))
        crests = PointClassifier.load(device="cpu")
        crests.crests = True
        runs.append(("classify_crests", crests.predict))
    return runs


def _bridge_rows(name: str, seed: int, scene, runs):
    """One JSON line per run (method name, cloud -> classes) on one gallery scene."""
    cloud, _, is_deck, _ = scene
    for m, run in runs:
        cls, wall, cpu = timed(lambda: run(cloud))
        hit = cls == 17
        row = {"bench": "bridges", "scene": name, "seed": seed, "method": m, "deck_points": int(is_deck.sum()),
               "class17_points": int(hit.sum()), "seconds": wall, "cpu_seconds": cpu}
        if is_deck.any():
            row["deck_in_ground_pct"] = 100.0 * float(np.mean(cls[is_deck] == 2))
            row["deck_f1"] = 2.0 * float(np.sum(hit & is_deck)) / float(hit.sum() + is_deck.sum())
        emit(row)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("what", choices=["isprs", "tiles", "speed", "sim", "bounds", "bridges", "ridges", "memory", "_memchild"])
    ap.add_argument("--sim-dir", default="sim")
    ap.add_argument("--data", default=os.environ.get("WS_SHARED_DATA", str(REPO.parent / "shared" / "data")))
    ap.add_argument("--methods", default="smrf,csf,pmf,ptd,auto,lowest,local_min")
    ap.add_argument("--points", type=int, default=5_000_000)
    ap.add_argument("--sizes", default="1000000,2000000,4000000", help="memory: tile sizes (points)")
    ap.add_argument("--tile-points", type=int, default=0, help="memory: filter tile by tile (ws ground --tile-points); 0 = whole")
    ap.add_argument("--seeds", default="0", help="bridges, ridges: the scenes' seeds, e.g. 0,1,2,3")
    ap.add_argument("--with-ml", action="store_true", help="bounds: the point classifier's ground as a sixth flag; bridges, ridges: add ws classify")
    ap.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                    help="override a parameter of every method (isprs, tiles, sim), e.g. threshold=0.3")
    a = ap.parse_args(argv)
    for kv in a.set:
        k, v = kv.split("=", 1)
        OVERRIDES[k] = json.loads(v)
    methods = a.methods.split(",")
    data = Path(a.data)
    if a.what == "isprs":
        bench_isprs(data, methods)
    elif a.what == "tiles":
        bench_tiles(data, methods)
    elif a.what == "sim":
        bench_sim(Path(a.sim_dir), methods)
    elif a.what == "bounds":
        bench_bounds(data, a.with_ml)
    elif a.what == "bridges":
        bench_bridges(methods, a.with_ml, [int(k) for k in a.seeds.split(",")])
    elif a.what == "ridges":
        bench_ridges(methods, a.with_ml, [int(k) for k in a.seeds.split(",")])
    elif a.what == "memory":
        bench_memory(data, methods, [int(x) for x in a.sizes.split(",")], a.tile_points)
    elif a.what == "_memchild":
        _memory_child(data, methods[0], a.points, a.tile_points)
    else:
        bench_speed(data, methods, a.points)


if __name__ == "__main__":
    main()
