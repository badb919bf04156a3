"""Benchmark of the point classifier: speed and the issue's real-data goals.

Prints one JSON line per result. Usage::

    PYTHONPATH=. python scripts/bench_classify.py speed [--points N] [--crests] # inference points/s
    PYTHONPATH=. python scripts/bench_classify.py phases [--points N] # where speed's time goes (wall / CPU per phase)
    PYTHONPATH=. python scripts/bench_classify.py goals [--model M]  # ISPRS + real tiles
    PYTHONPATH=. python scripts/bench_classify.py isprs [--model M] [--with-auto] [--without-patches] [--with-crests]  # per-sample ISPRS, the paths
    PYTHONPATH=. python scripts/bench_classify.py crests [--model M]  # what ws classify --crests moves on real data, and why
    PYTHONPATH=. python scripts/bench_classify.py gatediag [--model M] [--samples samp11,...]  # ISPRS Type I: gate or chain
    PYTHONPATH=. python scripts/bench_classify.py baseline           # RF on the same simulated rows
    PYTHONPATH=. python scripts/bench_classify.py sim                # sim test scenes (sim-to-real gap)
    PYTHONPATH=. python scripts/bench_classify.py simtiles           # whole sim validation tiles, roof test on/off
    PYTHONPATH=. python scripts/bench_classify.py simwater           # water on the sim validation tiles, step on/off
    PYTHONPATH=. python scripts/bench_classify.py vegdiag            # real tiles: confusion, steps off one at a time
    PYTHONPATH=. python scripts/bench_classify.py simroof            # sim tiles: what the roof test and understorey step move
    PYTHONPATH=. python scripts/bench_classify.py tiles [--tile-points N] [--points N] [--only whole|tiled|layout]
                                                  # tiled vs one-tile codes (default 400 k per tile)

Real data come from ../shared/data (or $WS_SHARED_DATA) and are never copied.
"""

from __future__ import annotations

import json
import os
import sys
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
DATA = Path(os.environ.get("WS_SHARED_DATA", REPO.parent / "shared" / "data"))


def emit(**kw):
    print(json.dumps(kw, default=float), flush=True)


def speed(model=None, points=None, crests=False):
    """Inference rate (`ws classify`'s whole path) on bcts_1 + bcts_2 (1.36 M points), or with
    ``points`` on the ground benchmark's synthetic tile of that many points (bcts_2 repeated on
    a grid of shifted copies with jitter: ``bench_ground.py speed``'s tile); with ``crests``
    that of ``ws classify --crests``."""
    clf, cloud = _warmed(model, points)
    clf.crests = crests
    best = None
    for _ in range(2):
        t0, c0 = time.perf_counter(), time.process_time()
        clf.classify(cloud)
        wall, cpu = time.perf_counter() - t0, time.process_time() - c0
        if best is None or wall < best[0]:
            best = (wall, cpu)
    wall, cpu = best
    emit(bench="classify_speed", points=cloud.n, crests=crests, seconds=wall, points_per_s=cloud.n / wall, cpu_seconds=cpu,
         cpu_points_per_core_s=cloud.n / cpu, load_avg=os.getloadavg()[0], cores=os.cpu_count())


def phases(model=None, points=None):
    """Wall and CPU seconds (CPU: all threads of the process) of the phases of one
    ``classify`` on :func:`speed`'s cloud, each phase timed by wrapping its function: the
    feature pass and, inside it, the grid columns and the tiled kNN scales (which run side by
    side), the network, the refine chain's ground steps (started beside the roof test), the
    raised-patch test inside them, the wait for the roof test, and the bridge step (searched
    beside the roof test's end, then updated for the noise it made; searched afresh where that
    search does not stand). Phases that overlap each other add up to more than the total."""
    import functools

    import workstation.ground.bridges as bridges
    import workstation.ground.patches as patches
    import workstation.ml.classifier as classifier
    import workstation.ml.features as features
    from workstation.ml.classifier import PointClassifier

    spent = {}

    def timed(owner, name, label):
        real = getattr(owner, name)

        @functools.wraps(real)
        def wrapper(*a, **k):
            t0, c0 = time.perf_counter(), time.process_time()
            try:
                return real(*a, **k)
            finally:
                w, c = spent.get(label, (0.0, 0.0))
                spent[label] = (w + time.perf_counter() - t0, c + time.process_time() - c0)

        setattr(owner, name, wrapper)

    for owner, name, label in ((classifier, "features_and_segments", "features"), (features, "_grid_columns", "grid_columns"),
                               (features, "_tiled_eigen_columns", "knn_scales_tiled"), (features, "_voxel_eigen", "knn_scales_whole"),
                               (PointClassifier, "predict_proba_features", "network"), (PointClassifier, "_ground_chain", "ground_steps"),
                               (patches, "raised_patches", "raised_patches"), (PointClassifier, "_nonplanar", "roof_test_wait"),
                               (classifier, "deck_search", "bridges_beside_roof_test"),
                               (bridges.DeckSearch, "without", "bridges_after_roof_test"),
                               (bridges, "bridge_decks", "bridges_fresh"), (PointClassifier, "_codes", "codes")):
        timed(owner, name, label)
    clf, cloud = _warmed(model, points)
    spent.clear()
    t0, c0 = time.perf_counter(), time.process_time()
    clf.classify(cloud)
    emit(bench="classify_phases", points=cloud.n, seconds=time.perf_counter() - t0, cpu_seconds=time.process_time() - c0,
         phases={k: {"seconds": round(w, 2), "cpu_seconds": round(c, 2)} for k, (w, c) in spent.items()},
         load_avg=os.getloadavg()[0])


def _warmed(model, points):
    """The classifier and :func:`speed`'s cloud, after one classify of 20,000 points (imports)."""
    from workstation.ml.classifier import PointClassifier

    clf = PointClassifier.load(model, device="cpu")
    cloud = _tiles_cloud(points)
    clf.classify(cloud[:20000])
    return clf, cloud


def _tiles_cloud(points=None):
    """bcts_1 + bcts_2 (with their own classes), or the ground benchmark's synthetic tile."""
    from workstation.core.cloud import concatenate
    from workstation.io import read_cloud

    if points:
        sys.path.insert(0, str(REPO / "scripts"))
        from bench_ground import synthetic_tile

        return synthetic_tile(int(points), DATA)
    return concatenate([read_cloud(DATA / "lidar" / "bcts_1.laz"), read_cloud(DATA / "lidar" / "bcts_2.laz")])


def _border_distance(clf, cloud) -> np.ndarray:
    """Each point's horizontal distance (m) to the nearest border between the cores of the
    classifier's tiles (inf for a single tile): the cores' bounding boxes' inner edges."""
    from workstation.ml.features import metric_xyz

    xy = metric_xyz(cloud)[0][:, :2]
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    d = np.full(cloud.n, np.inf)
    for core, _sel in clf._tiles(cloud):
        a, b = xy[core].min(axis=0), xy[core].max(axis=0)
        for ax in (0, 1):
            if a[ax] > lo[ax]:
                d[core] = np.minimum(d[core], xy[core, ax] - a[ax])
            if b[ax] < hi[ax]:
                d[core] = np.minimum(d[core], b[ax] - xy[core, ax])
    return d


def tiles(model=None, tile_points=400_000, points=None, only=None):
    """Whether the classes depend on how the cloud is cut: the codes of one tile against those
    of tiles of ``tile_points`` (bcts_1 + bcts_2, or with ``points`` the synthetic tile): the
    share that differ, by distance to the nearest tile border, the probabilities' largest
    difference, CPU and wall seconds of each (twice), and ground / building / vegetation F1
    against the files' classes. ``only`` ("whole" or "tiled") runs that one alone and reports
    the process's peak RSS (run it in a fresh process); "layout" only prints the sizes of the
    classifier's tiles with their buffers (``PointClassifier._tiles``), which every run prints
    first."""
    import resource

    from workstation.ml.classifier import PointClassifier
    from workstation.ml.realdata import VEG, f1

    cloud = _tiles_cloud(points)
    ref = np.asarray(cloud.attrs["classification"]) if "classification" in cloud.attrs else None
    if ref is not None:
        cloud = cloud.without_attrs("classification")
    clf = PointClassifier.load(model, device="cpu")
    clf.tile_points = int(tile_points)
    sizes = [len(sel) for _core, sel in clf._tiles(cloud)]
    emit(bench="tiles_layout", points=cloud.n, tile_points=int(tile_points), tiles=len(sizes),
         points_in_tiles=int(sum(sizes)), buffer_share=sum(sizes) / cloud.n - 1, largest_tile=max(sizes))
    if only == "layout":
        return
    clf.predict(cloud[:20000])  # warm-up (imports)
    runs = {"whole": cloud.n + 1, "tiled": int(tile_points)}
    out = {}
    for name, tp in runs.items():
        if only and name != only:
            continue
        clf.tile_points = tp
        for rep in range(1 if only else 2):
            t0, c0 = time.perf_counter(), time.process_time()
            pred = clf.predict_codes(cloud)
            wall, cpu = time.perf_counter() - t0, time.process_time() - c0
            emit(bench="tiles_run", run=name, tile_points=tp, points=cloud.n, repeat=rep, seconds=wall, cpu_seconds=cpu,
                 peak_rss_mb=resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024 if only else None,
                 load_avg=os.getloadavg()[0])
        out[name] = pred
        if ref is not None:
            c = pred.codes
            emit(bench="tiles_f1", run=name, ground_f1=f1(ref == 2, c == 2), building_f1=f1(ref == 6, c == 6),
                 vegetation_f1=f1(np.isin(ref, VEG), np.isin(c, VEG)))
    if only:
        return
    clf.tile_points = int(tile_points)
    d = _border_distance(clf, cloud)
    diff = out["whole"].codes != out["tiled"].codes
    edges = [0, 5, 20, 50, 110, 200, np.inf]
    band = {f"{a}-{b}m": [int(diff[(d >= a) & (d < b)].sum()), int(((d >= a) & (d < b)).sum())]
            for a, b in zip(edges[:-1], edges[1:])}
    emit(bench="tiles_diff", points=cloud.n, tile_points=int(tile_points), tiles=sum(1 for _ in clf._tiles(cloud)),
         changed=int(diff.sum()), changed_pct=100.0 * diff.mean(),
         changed_by_border_distance=band,
         max_abs_proba_diff=float(np.abs(out["whole"].proba - out["tiled"].proba).max()),
         changed_pairs=_pairs(out["whole"].codes[diff], out["tiled"].codes[diff]))


def _pairs(a: np.ndarray, b: np.ndarray) -> dict:
    """{"a->b": count} of paired codes."""
    u, n = np.unique(np.stack([a, b]), axis=1, return_counts=True) if len(a) else (np.zeros((2, 0), int), [])
    return {f"{x}->{y}": int(k) for (x, y), k in zip(u.T, n)}


def goals(clf, label):
    from workstation.core.classes import ASPRSClass as C
    from workstation.ml.realdata import (
        BUILDING_FILES,
        DTM_FILES,
        VEGETATION_FILES,
        isprs_scores,
        tile_scores,
    )

    s = isprs_scores(lambda c: clf.predict(c) == C.GROUND, DATA / "isprs")
    emit(bench="isprs", model=label, **{k: (v if not isinstance(v, dict) else {a: round(b, 2) for a, b in v.items()})
                                         for k, v in s.items()})
    for f in DTM_FILES + BUILDING_FILES + VEGETATION_FILES:
        t0 = time.perf_counter()
        r = tile_scores(clf.predict, DATA / "lidar" / f)
        emit(bench="real_tile", model=label, file=f, seconds=time.perf_counter() - t0, **r)


def isprs(model=None, with_auto=False, without_patches=False, with_crests=False):
    """Per-sample ISPRS Type I / Type II / total error (%) of the classifier's ground paths:
    ``ws classify`` (:meth:`PointClassifier.predict`, the model's own step switches), ``ws
    ground --method ml`` (:func:`workstation.ml.ground.ml_ground`) and the same with
    ``member_vote`` (the gate as a sixth voter of ``auto``'s members), with ``with_auto``
    ``ws ground --method auto`` beside them, with ``without_patches`` ``ws classify
    --no-raised-patches``, with ``with_crests`` ``ws classify --crests``; then each path's mean."""
    from workstation.core.classes import ASPRSClass as C
    from workstation.core.cloud import Cloud
    from workstation.ml.classifier import PointClassifier
    from workstation.ml.ground import MLGroundParams, ml_ground
    from workstation.ml.realdata import isprs_scores

    clf = PointClassifier.load(model, device="cpu")
    def ground_ml(**kw):
        p = MLGroundParams(model=model, device="cpu", **kw)
        return lambda c: np.asarray(ml_ground(c, p).attrs["classification"]) == C.GROUND

    paths = {"classify": lambda c: clf.predict(c) == C.GROUND, "ground_ml": ground_ml(),
             "ground_ml_member_vote": ground_ml(member_vote=True)}
    if without_patches:
        plain = PointClassifier.load(model, device="cpu")
        plain.raised_patches = False
        paths["classify_no_raised_patches"] = lambda c: plain.predict(c) == C.GROUND
    if with_crests:
        crests = PointClassifier.load(model, device="cpu")
        crests.crests = True
        paths["classify_crests"] = lambda c: crests.predict(c) == C.GROUND
    if with_auto:
        from workstation.ground.methods import ground_filter

        paths["auto"] = lambda c: np.asarray(ground_filter(Cloud(c.xyz), "auto").attrs["classification"]) == C.GROUND
    for k, fn in paths.items():
        times = []  # (wall, cpu) seconds of each sample's run, in isprs_scores' order

        def timed(c, fn=fn, times=times):
            t0, c0 = time.perf_counter(), time.process_time()
            out = fn(c)
            times.append((time.perf_counter() - t0, time.process_time() - c0))
            return out

        scores = isprs_scores(timed, DATA / "isprs")
        samples = [s for s in scores if s != "mean_total"]
        for s, (wall, cpu) in zip(samples, times):
            e = scores[s]
            emit(bench="isprs_sample", path=k, sample=s, type1=round(e["type1"], 2), type2=round(e["type2"], 2),
                 total=round(e["total"], 2), seconds=wall, cpu_seconds=cpu)
        emit(bench="isprs_mean", path=k, samples=len(samples),
             mean_total=round(float(scores["mean_total"]), 3) if samples else None)


def crests(model=None, tiles=("bcts_1.laz", "MixedConifer.laz", "autzen_trim.las", "bcts_2.laz", "Topography.laz",
                                "lidarhd_extra_bytes.laz", "warsaw_small.las", "sample_c.las", "vegetation_1_3.las")):
    """What ``ws classify --crests`` moves on the six ISPRS samples and the real tiles (the
    reference: ISPRS labels, the vendors' class 2): the points it puts in the ground and how
    many of them the reference calls ground; on the ISPRS samples also the total error off and
    on, and why it leaves Type I points out (:func:`_crest_diagnosis`)."""
    from workstation.ground.crests import CrestParams
    from workstation.ground.evaluate import ground_errors, read_isprs_text
    from workstation.io import read_cloud
    from workstation.ml.classifier import PointClassifier, StepSwitches

    clf = PointClassifier.load(model, device="cpu")
    on = StepSwitches(crests=True)
    head = []  # the chain's steps before the crest step
    for q in clf.chain(on):
        if isinstance(q, CrestParams):
            break
        head.append(q)
    for name in ["samp11", "samp21", "samp31", "samp42", "samp51", "samp61", *tiles]:
        isprs = not name.endswith((".las", ".laz"))
        if isprs:
            ref = read_isprs_text(DATA / "isprs" / f"{name}.txt")
            truth = np.asarray(ref.attrs["label"]) == 0
            cloud = ref.without_attrs("label", "classification")
        else:
            ref = read_cloud(DATA / "lidar" / name)
            truth = np.asarray(ref.attrs["classification"]) == 2
            cloud = ref.without_attrs("classification")
        pred = clf.predict_codes(cloud)
        with_crests = clf.predict_codes(cloud, on).codes == 2
        off = pred.codes == 2
        added = with_crests & ~off
        row = {"bench": "crests", "sample": name, "joined": int(added.sum()),
               "joined_reference_ground": int((added & truth).sum())}
        if isprs:
            row.update(total_error_off_pct=100 * ground_errors(truth, off).total_error,
                       total_error_on_pct=100 * ground_errors(truth, with_crests).total_error)
            row.update(_crest_diagnosis(head, cloud, pred.gate, truth, off))
        emit(**row)


def _crest_diagnosis(head, cloud, gate, truth, off) -> dict:
    """Why the crest step leaves Type I points (reference ground ``truth`` not in the ground
    ``off``) out: how many are candidates of a tall cut feature, how many of those a
    steeper-than-terrain point vetoes, and the steepest slope of the points found steep, split
    by the reference. The test runs on the gate's ground after the chain's steps ``head``,
    every point taken as possible terrain (the classifier leaves its noise out)."""
    from workstation.ground.crests import crest_test
    from workstation.ground.refine import Refine, run_chain
    from workstation.ml.features import metric_xyz

    xyz = metric_xyz(cloud)[0]
    test = crest_test(xyz, run_chain(Refine(xyz, gate), tuple(head)).ground)
    if test is None:
        return {}
    missed = truth & ~off
    tall = test.tall[test.feature]
    steep = tall & test.steep
    vetoed = tall & ~test.crests[test.feature]
    row = {"type1": int(missed.sum()), "type1_tall_candidates": int((missed[test.candidates] & tall).sum()),
           "type1_vetoed": int((missed[test.candidates] & vetoed).sum())}
    for label, m in (("reference_ground", truth[test.candidates]), ("reference_object", ~truth[test.candidates])):
        if (steep & m).any():
            row[f"steep_{label}"] = int((steep & m).sum())
            near = steep & m & np.isfinite(test.slope) & (test.slope > test.max_slope)
            if near.any():  # the steepest slope of those found steep near them
                row[f"steep_{label}_slope_q10_50_90"] = np.quantile(test.slope[near], [0.1, 0.5, 0.9]).round(2).tolist()
    return row


def gatediag(model=None, samples=("samp11", "samp31", "samp51"), heights=(1.5, 3.0, 5.0)):
    """Where ``ws classify``'s Type I errors (reference ground called non-ground) on ISPRS
    samples come from: the gate (outside SMRF's band of the provisional surface and not
    promoted) or the refine chain after it; of the gate's, how many lie beyond the promotion
    height, their height above the provisional surface and ground probability (quantiles 10,
    25, 50, 75, 90 %); then the total error with the promotion height at each of ``heights``."""
    from workstation.core.classes import ASPRSClass as C
    from workstation.ground.evaluate import ground_errors, read_isprs_text
    from workstation.ml.classifier import PointClassifier

    clf = PointClassifier.load(model, device="cpu")
    q = [0.1, 0.25, 0.5, 0.75, 0.9]
    for s in samples:
        ref = read_isprs_text(DATA / "isprs" / f"{s}.txt")
        ref_g = np.asarray(ref.attrs["label"]) == 0
        cloud = ref.without_attrs("label", "classification")
        P, hs, _ = clf._infer(cloud)
        gate = clf._gate(P, hs)
        t1 = ref_g & (clf.codes_from_proba(P, hs, cloud)[0] != C.GROUND)
        rej = t1 & ~gate
        far = rej & (np.abs(hs[:, 0]) > clf.gate_promote_height)
        emit(bench="gate_type1", sample=s, type1=int(t1.sum()), gate_rejected=int(rej.sum()), chain_removed=int((t1 & gate).sum()),
             beyond_promote_height=int(far.sum()), hag_quantiles=np.round(np.quantile(hs[rej, 0], q), 2).tolist() if rej.any() else None,
             p_ground_quantiles=np.round(np.quantile(P[rej, 0], q), 3).tolist() if rej.any() else None)
        h0 = clf.gate_promote_height
        for h in heights:
            clf.gate_promote_height = h
            e = ground_errors(ref_g, clf.codes_from_proba(P, hs, cloud)[0] == C.GROUND)
            emit(bench="gate_promote_height", sample=s, height=h, type1=round(100 * e.type1, 2), type2=round(100 * e.type2, 2),
                 total=round(100 * e.total_error, 2))
        clf.gate_promote_height = h0


def _tileset():
    import pickle

    from workstation.ml.dataset import build_tileset, load_dataset_recipe

    import hashlib

    from workstation.ml.features import FeatureParams

    path = REPO / "datasets_synth" / "ml_train.toml"
    # the cache is keyed on the recipe and the feature settings: a stale one would score a
    # model on features it was not trained on
    key = hashlib.sha1((path.read_text() + json.dumps(FeatureParams().to_dict())).encode()).hexdigest()[:12]
    cache = Path(os.environ.get("WS_ML_TILESET_CACHE", f"/tmp/ws_ml_tileset_{key}.pkl"))
    recipe = load_dataset_recipe(path)
    if cache.exists():
        ts = pickle.loads(cache.read_bytes())
        if ts.info and len(ts.info) == len(recipe.recipes) * recipe.scenes_per_recipe * recipe.tiles_per_scene:
            return ts
    ts = build_tileset(recipe, progress=False)
    cache.write_bytes(pickle.dumps(ts))
    return ts


def baseline():
    from workstation.ml.classifier import PointClassifier
    from workstation.ml.dataset import load_dataset_recipe
    from workstation.ml.features import FEATURE_NAMES
    from workstation.ml.train import split_scores

    ts = _tileset()
    recipe = load_dataset_recipe(REPO / "datasets_synth" / "ml_train.toml")
    vm = ts.val[ts.tile]
    use = np.ones(len(ts.y), bool)
    if recipe.train.get("drop_ground_above_m") is not None:  # the same rows as the shipped MLP
        use = ~(~vm & (ts.y == 0) & (np.abs(ts.X[:, FEATURE_NAMES.index("hag_prov")]) > recipe.train["drop_ground_above_m"]))
    rf = PointClassifier(model="rf", seed=0, ignore_features=recipe.train.get("ignore_features", ()))
    rf.fit_arrays(ts.X[~vm & use], ts.y[~vm & use], ts.X[vm], ts.y[vm])
    emit(bench="rf_fit", seconds=rf.report_.seconds, cpu_seconds=rf.report_.cpu_seconds, validation=split_scores(rf, ts.X[vm], ts.y[vm]))
    goals(rf, "rf")


def sim():
    """Scores of the shipped model on the simulated validation scenes (never trained on)."""
    from workstation.ml.classifier import PointClassifier
    from workstation.ml.train import split_scores

    ts = _tileset()
    vm = ts.val[ts.tile]
    clf = PointClassifier.load(None, device="cpu")
    emit(bench="sim_validation", model="mlp", **split_scores(clf, ts.X[vm], ts.y[vm]))


def simtiles():
    """The shipped model's whole pipeline (gate, understorey step, roof test) on the whole
    simulated validation tiles, with and without the roof planarity test: building and
    vegetation F1 per tile (tiles with at least 50 building points) and their means."""
    from workstation.core.classes import ASPRSClass as C
    from workstation.ml.classifier import PointClassifier
    from workstation.ml.dataset import load_dataset_recipe, simulated_tiles
    from workstation.ml.realdata import VEG, f1

    recipe = load_dataset_recipe(REPO / "datasets_synth" / "ml_train.toml")
    clf = PointClassifier.load(None, device="cpu")
    rows = []
    for name, _seed, t, _val, cloud, _rng in simulated_tiles(recipe, validation_only=True):  # build_tileset's draws
        ref = np.asarray(cloud.attrs["classification"])
        if (ref == C.BUILDING).sum() < 50:
            continue
        row = {"tile": t, "recipe": name, "points": cloud.n, "density": cloud.meta["sim"]["density"],
               "range_sigma": cloud.meta["sim"]["range_sigma"]}
        for on in (False, True):
            clf.roof_test = on
            pred = clf.predict(cloud)
            key = "roof" if on else "no_roof"
            row[f"building_f1_{key}"] = f1(ref == C.BUILDING, pred == C.BUILDING)
            row[f"vegetation_f1_{key}"] = f1(np.isin(ref, VEG), np.isin(pred, VEG))
        emit(bench="sim_tile", **row)
        rows.append(row)
    emit(bench="sim_tiles_mean", tiles=len(rows),
         **{k: float(np.nanmean([r[k] for r in rows])) for k in rows[0] if k.endswith(("_roof", "_no_roof"))})


def simwater():
    """Water on the whole simulated validation tiles that hold some (the shipped pipeline with
    and without the water step): F1 per tile and over all their points."""
    from workstation.core.classes import ASPRSClass as C
    from workstation.ml.classifier import PointClassifier
    from workstation.ml.dataset import load_dataset_recipe, simulated_tiles
    from workstation.ml.realdata import f1

    recipe = load_dataset_recipe(REPO / "datasets_synth" / "ml_train.toml")
    clf = PointClassifier.load(None, device="cpu")
    tot = {k: np.zeros(3) for k in ("water", "no_water")}  # tp, ref, pred
    for name, _seed, t, _val, cloud, _rng in simulated_tiles(recipe, validation_only=True):
        ref = np.asarray(cloud.attrs["classification"]) == C.WATER
        if ref.sum() < 30:
            continue
        row = {"tile": t, "recipe": name, "points": cloud.n, "water_points": int(ref.sum()),
               "density": cloud.meta["sim"]["density"]}
        for on in (False, True):
            clf.water = on
            pred = clf.predict(cloud) == C.WATER
            key = "water" if on else "no_water"
            row[f"water_f1_{key}"] = f1(ref, pred)
            tot[key] += [(ref & pred).sum(), ref.sum(), pred.sum()]
        emit(bench="sim_water_tile", **row)
    emit(bench="sim_water", **{f"{k}_{m}": float(v) for k, (tp, r, p) in tot.items()
                                for m, v in (("f1", 2 * tp / max(r + p, 1)), ("recall", tp / max(r, 1)),
                                             ("precision", tp / max(p, 1)))})


def _confusion(ref: np.ndarray, pred: np.ndarray) -> dict:
    """{reference code: {predicted code: count}} of two code arrays."""
    return {int(r): {int(p): int(n) for p, n in zip(*np.unique(pred[ref == r], return_counts=True))}
            for r in np.unique(ref)}


def vegdiag(model=None):
    """Vegetation diagnosis on the real tiles with vegetation classes (the check, not a tuning
    set): the confusion matrix (reference code -> predicted code -> points), then building and
    vegetation F1 with each step switch off in turn and with all off, and the points that
    switch changes (reference code -> "code with the step off->code with it on" -> points)."""
    from dataclasses import fields

    from workstation.io import read_cloud
    from workstation.ml.classifier import PointClassifier, StepSwitches
    from workstation.ml.realdata import VEG, f1

    clf = PointClassifier.load(model, device="cpu")
    names = [f.name for f in fields(StepSwitches)]
    for f in ("warsaw_small.las", "lidarhd_extra_bytes.laz", "sample_c.las"):
        cloud = read_cloud(DATA / "lidar" / f)
        ref = np.asarray(cloud.attrs["classification"])
        base = clf.predict_codes(cloud).codes
        emit(bench="veg_confusion", file=f, confusion=_confusion(ref, base))
        runs = [("none", None)] + [(n, StepSwitches(**{n: False})) for n in names]
        runs.append(("all", StepSwitches(**{n: False for n in names})))
        for off, sw in runs:
            pred = base if sw is None else clf.predict_codes(cloud, sw).codes
            ch = pred != base
            moved = {int(r): {f"{a // 256}->{a % 256}": int(n) for a, n in
                              zip(*np.unique(pred[ch & (ref == r)].astype(int) * 256 + base[ch & (ref == r)], return_counts=True))}
                     for r in np.unique(ref[ch])}
            emit(bench="veg_steps_off", file=f, off=off, changed=int(ch.sum()), building_f1=f1(ref == 6, pred == 6),
                 vegetation_f1=f1(np.isin(ref, VEG), np.isin(pred, VEG)), moved_off_to_on=moved)


def simroof():
    """On the whole simulated validation tiles (a tuning set): the points the roof test takes
    from building and those the understorey step takes from ground, by their true model class
    (ground, vegetation, building, water, other, noise) and the code they take now, summed
    over the tiles; and the roof test's failures by true class and single / multi-echo pulse."""
    from workstation.ml.classifier import PointClassifier, StepSwitches
    from workstation.ml.dataset import MODEL_CLASSES, asprs_to_model, load_dataset_recipe, simulated_tiles

    recipe = load_dataset_recipe(REPO / "datasets_synth" / "ml_train.toml")
    clf = PointClassifier.load(None, device="cpu")
    steps = {"roof_test": 6, "understorey": 2}  # step -> the code it takes points from
    table = {k: np.zeros((len(MODEL_CLASSES), 256), np.int64) for k in steps}
    echoes = np.zeros((len(MODEL_CLASSES), 2), np.int64)  # roof failures: single / multi-echo pulses
    for _name, _seed, _t, _val, cloud, _rng in simulated_tiles(recipe, validation_only=True):
        true = asprs_to_model(np.asarray(cloud.attrs["classification"]))
        on = clf.predict_codes(cloud).codes
        for step, code in steps.items():
            off = clf.predict_codes(cloud, StepSwitches(**{step: False})).codes
            moved = (off == code) & (on != code)
            np.add.at(table[step], (true[moved], on[moved]), 1)
            if step == "roof_test":
                nr = np.asarray(cloud.attrs.get("number_of_returns", np.ones(cloud.n)))  # some tiles have none
                np.add.at(echoes, (true[moved], (nr[moved] > 1).astype(int)), 1)
    for step, t in table.items():
        emit(bench="sim_step_moves", step=step, by_true_class={
            MODEL_CLASSES[i]: {int(c): int(n) for c, n in enumerate(row) if n} for i, row in enumerate(t) if row.any()})
    emit(bench="sim_roof_failures_by_echoes", by_true_class={
        MODEL_CLASSES[i]: {"single_echo": int(a), "multi_echo": int(b)} for i, (a, b) in enumerate(echoes) if a + b})


if __name__ == "__main__":
    what = sys.argv[1] if len(sys.argv) > 1 else "speed"
    model = sys.argv[sys.argv.index("--model") + 1] if "--model" in sys.argv else None
    if what in ("speed", "phases"):
        n = int(sys.argv[sys.argv.index("--points") + 1]) if "--points" in sys.argv else None
        speed(model, n, "--crests" in sys.argv) if what == "speed" else phases(model, n)
    elif what == "goals":
        from workstation.ml.classifier import PointClassifier

        goals(PointClassifier.load(model, device="cpu"), "mlp")
    elif what == "isprs":
        isprs(model, with_auto="--with-auto" in sys.argv, without_patches="--without-patches" in sys.argv,
              with_crests="--with-crests" in sys.argv)
    elif what == "crests":
        crests(model)
    elif what == "gatediag":
        given = sys.argv[sys.argv.index("--samples") + 1].split(",") if "--samples" in sys.argv else None
        gatediag(model, *([given] if given else []))
    elif what == "baseline":
        baseline()
    elif what == "sim":
        sim()
    elif what == "simtiles":
        simtiles()
    elif what == "simwater":
        simwater()
    elif what == "vegdiag":
        vegdiag(model)
    elif what == "simroof":
        simroof()
    elif what == "tiles":
        arg = lambda k: sys.argv[sys.argv.index(k) + 1] if k in sys.argv else None  # noqa: E731
        tiles(model, int(arg("--tile-points") or 400_000), arg("--points"), arg("--only"))
    else:
        raise SystemExit(f"unknown benchmark {what!r}")
