"""Demo step of ground filtering: SMRF on the demo cloud (the simulated ALS when present) and the
ISPRS-style evaluation against the input's own classes (bare earth: ground, water, road)."""

from __future__ import annotations

import json

import numpy as np

from workstation.core.classes import ASPRSClass
from workstation.io import atomic_path, read_cloud, write_cloud


BARE_EARTH = (int(ASPRSClass.GROUND), int(ASPRSClass.WATER), int(ASPRSClass.ROAD_SURFACE))


def step(ctx) -> dict:
    from workstation.ground.evaluate import evaluate_clouds, plot_confusion, plot_errors
    from workstation.ground.smrf import smrf

    src = ctx.products.get("als_laz") or ctx.products["cloud_las"]
    cloud = read_cloud(src)
    truth = cloud.attrs.get("classification")
    out = smrf(cloud, reclassify=True)
    dst = ctx.outdir / "ground_smrf.laz"
    write_cloud(out, dst, overwrite=True, inputs=[src])
    made = {"ground_laz": dst}
    summary = {"input": str(src), "points": out.n,
               "ground_fraction": float(np.mean(np.asarray(out.attrs["classification"]) == ASPRSClass.GROUND))}
    if truth is not None and np.any(np.asarray(truth) == ASPRSClass.GROUND):
        ev, pi, ri = evaluate_clouds(out, cloud, ground_classes=BARE_EARTH)
        summary.update({"type1": ev.type1, "type2": ev.type2, "total_error": ev.total_error, "kappa": ev.kappa})
        rg = np.isin(np.asarray(truth)[ri], BARE_EARTH)
        pg = np.isin(np.asarray(out.attrs["classification"])[pi], BARE_EARTH)
        made["ground_errors_png"] = plot_errors(out.xyz[pi], rg, pg, ctx.outdir / "ground_errors.png", title="SMRF")
        made["ground_confusion_png"] = plot_confusion(ev, ctx.outdir / "ground_confusion.png")
    rep = ctx.outdir / "ground_eval.json"
    with atomic_path(rep, overwrite=True) as tmp:
        tmp.write_text(json.dumps(summary, indent=2))
    made["ground_eval"] = rep
    ctx.summaries["ground"] = summary
    return made
