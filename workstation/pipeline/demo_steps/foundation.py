"""Demo step of the foundation: a synthetic cloud written as LAZ, converted to LAS, summarised."""

from __future__ import annotations

import json

import numpy as np

from workstation.core.classes import ASPRSClass
from workstation.core.cloud import Cloud
from workstation.io import atomic_path, read_cloud, write_cloud
from workstation.qc.summary import summarize


def synthetic_cloud(seed: int = 0, n: int = 200_000) -> Cloud:
    """A 100 m × 100 m patch: rolling ground and a flat-roofed box building, in UTM 32N.

    Points on the roof are class 6 (building), the rest class 2 (ground); intensity is higher
    on the roof; coordinates are quantised to millimetres like a LAS file.
    """
    rng = np.random.default_rng(seed)
    x = rng.uniform(0, 100, n)
    y = rng.uniform(0, 100, n)
    z = 200 + 2 * np.sin(x / 15) + 1.5 * np.cos(y / 20) + rng.normal(0, 0.03, n)
    roof = (np.abs(x - 50) < 12) & (np.abs(y - 45) < 8)
    z = np.where(roof, 212 + rng.normal(0, 0.03, n), z)
    cls = np.where(roof, ASPRSClass.BUILDING, ASPRSClass.GROUND).astype(np.uint8)
    intensity = np.where(roof, 3000, 1200) + rng.integers(0, 400, n)
    xyz = np.round(np.column_stack([500_000 + x, 5_000_000 + y, z]), 3)
    return Cloud(
        xyz,
        {"intensity": intensity, "classification": cls, "return_number": np.ones(n), "number_of_returns": np.ones(n),
         "gps_time": np.sort(rng.uniform(0, 60, n))},
        crs="EPSG:32632",
    ).with_history("demo.synthetic_cloud", {"seed": seed, "n": n})


def step(ctx) -> dict:
    laz = ctx.outdir / "synthetic.laz"
    las = ctx.outdir / "synthetic.las"
    info = ctx.outdir / "synthetic_info.json"
    write_cloud(synthetic_cloud(ctx.seed), laz, overwrite=True)
    write_cloud(read_cloud(laz), las, overwrite=True)
    summary = summarize(las)
    with atomic_path(info, overwrite=True) as tmp:
        tmp.write_text(json.dumps(summary, indent=2))
    ctx.summaries["foundation"] = summary
    return {"cloud_laz": laz, "cloud_las": las, "cloud_info": info}
