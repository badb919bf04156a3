"""Demo step of the point classifier: classify the simulated ALS scan (or the foundation
cloud) with the shipped model, score it against the true classes, write the result."""

from __future__ import annotations

import json

import numpy as np

from workstation.core.classes import ASPRSClass as C
from workstation.io import atomic_path, read_cloud, write_cloud


def step(ctx) -> dict:
    from workstation.ml.classifier import PointClassifier
    from workstation.ml.realdata import f1

    src = ctx.products.get("als_laz") or ctx.products.get("cloud_las")
    if src is None:
        return {}
    cloud = read_cloud(src)
    if cloud.n > 400_000:  # keep the step within its time budget
        cloud = cloud[np.random.default_rng(ctx.seed).choice(cloud.n, 400_000, replace=False)]
    clf = PointClassifier.load(None, device="cpu")
    out = clf.classify(cloud)
    dst = ctx.outdir / "classified.laz"
    write_cloud(out, dst, overwrite=True)
    pred = np.asarray(out.attrs["classification"])
    summary = {"input": str(src), "points": cloud.n,
               "classes": {int(k): int(v) for k, v in zip(*np.unique(pred, return_counts=True))}}
    if "classification" in cloud.attrs:
        ref = np.asarray(cloud.attrs["classification"])
        summary["ground_f1"] = f1(ref == C.GROUND, pred == C.GROUND)
        summary["building_f1"] = f1(ref == C.BUILDING, pred == C.BUILDING)
        veg = (C.LOW_VEGETATION, C.MEDIUM_VEGETATION, C.HIGH_VEGETATION)
        if np.isin(ref, veg).any():
            summary["vegetation_f1"] = f1(np.isin(ref, veg), np.isin(pred, veg))
        if (ref == C.WATER).any():
            summary["water_f1"] = f1(ref == C.WATER, pred == C.WATER)
    js = ctx.outdir / "classified_summary.json"
    with atomic_path(js, overwrite=True) as tmp:
        tmp.write_text(json.dumps(summary, indent=2))
    ctx.summaries["classify"] = summary
    return {"classified_laz": dst, "classified_summary": js}
