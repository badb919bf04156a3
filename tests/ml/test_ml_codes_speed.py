"""The classifier's inference shortcuts give what the plain computations give."""

import numpy as np


def _roof_scene(seed=0):
    from workstation.ml.roofs import RoofTest

    rng = np.random.default_rng(seed)
    # 1 cm coordinates, as in LAS files: many neighbours at equal distances
    xyz = np.round(rng.uniform(0, 20, (4000, 3)) * [1, 1, 0.3], 2) + [0, 0, 3.0]
    return xyz, RoofTest(xyz, xyz[:, 2])


def test_vote_more_equals_the_vote_among_both_sets():
    from scipy.spatial import cKDTree

    xyz, t = _roof_scene()
    rng = np.random.default_rng(1)
    cand = rng.random(len(xyz)) < 0.6
    tested, bad = t.test(cand)
    bad = rng.random(len(tested)) < 0.5  # mixed decisions: the lookups run
    extra = ~cand & (rng.random(len(xyz)) < 0.5)
    more, _ = t.test(extra)
    more = np.concatenate([more, tested[:7]])  # points at a tested point's place: exact ties
    more_bad = rng.random(len(more)) < 0.5
    ref = t.vote(extra, np.concatenate([tested, more]), np.concatenate([bad, more_bad]))
    got = t.vote_more(extra, tested, bad, cKDTree(tested), more, more_bad)
    assert ref[extra].any() and not ref[extra].all()
    assert np.array_equal(got, ref)
    for few in (more[:1], more[:3]):  # fewer newcomers than neighbours
        fb = more_bad[:len(few)]
        ref = t.vote(extra, np.concatenate([tested, few]), np.concatenate([bad, fb]))
        assert np.array_equal(t.vote_more(extra, tested, bad, cKDTree(tested), few, fb), ref)
    assert np.array_equal(t.vote_more(extra, tested, bad, None, more, more_bad),
                          t.vote(extra, np.concatenate([tested, more]), np.concatenate([bad, more_bad])))


def test_plane_residuals_do_not_depend_on_the_query_order():
    from workstation.ml.roofs import plane_residuals, z_order

    xyz, t = _roof_scene(2)
    query = t.ref[::3]
    perm = np.random.default_rng(0).permutation(len(query))
    r1, d1 = plane_residuals(query, t.ref, 24, workers=1, tree=t.tree)
    r2, d2 = plane_residuals(query[perm], t.ref, 24, workers=2, tree=t.tree)
    assert np.array_equal(r1[perm], r2) and np.array_equal(d1[perm], d2)
    o = z_order(query)
    assert np.array_equal(np.sort(o), np.arange(len(query)))
    assert len(z_order(query[:0])) == 0


def test_batch_runs_cover_every_batch_once_in_order():
    from workstation.ml.model import CPU_BATCH, _batch_runs

    n = CPU_BATCH * 5 + 3
    for threads in (1, 2, 3, 8):
        runs = _batch_runs(n, threads)
        assert len(runs) == min(threads, 6)
        assert sum(runs, []) == list(range(0, n, CPU_BATCH))
    assert _batch_runs(0, 2) == [[]]


def test_predict_codes_equals_the_codes_of_its_probabilities():
    # predict_codes starts the ground steps and the roof test beside the segment step;
    # codes_from_proba runs them in turn: the same codes and confidences
    from workstation.core.cloud import Cloud
    from workstation.ml.classifier import PointClassifier, StepSwitches

    rng = np.random.default_rng(4)
    n = 30000
    xy = rng.uniform(0, 100, (n, 2))
    z = 50 + 0.02 * xy[:, 0] + rng.normal(0, 0.03, n)
    for cx, cy, h in ((25, 30, 8.0), (70, 60, 12.0)):
        inside = (np.abs(xy[:, 0] - cx) < 9) & (np.abs(xy[:, 1] - cy) < 7)
        z[inside] += h + 0.3 * (np.abs(xy[inside, 0] - cx) < 1)
    crown = np.hypot(xy[:, 0] - 40, xy[:, 1] - 75) < 6
    z[crown] += rng.uniform(2, 12, crown.sum())
    cloud = Cloud(np.column_stack([xy + [400000, 6000000], z]), {"return_number": np.ones(n, np.uint8),
                  "number_of_returns": np.where(crown & (rng.random(n) < 0.5), 2, 1).astype(np.uint8)},
                  crs="EPSG:32632")
    clf = PointClassifier.load(device="cpu")
    for sw in (None, StepSwitches(roof_test=False), StepSwitches(raised_patches=False, water=False)):
        pred = clf.predict_codes(cloud, sw)
        codes, conf = clf.codes_from_proba(pred.proba, clf._infer(cloud)[1], cloud, sw)
        assert np.array_equal(codes, pred.codes) and np.array_equal(conf, pred.confidence)
    assert (pred.codes == 6).any()
