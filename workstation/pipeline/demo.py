"""`ws demo`: the whole chain on a generated synthetic scene.

Each step is a function ``step(ctx: DemoContext) -> dict[str, Path]`` in
``workstation/pipeline/demo_steps/``; it reads earlier products from ``ctx.products`` and
returns its own, which are added there. Steps run in the order of :data:`STEPS`.
"""

from __future__ import annotations

import importlib
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

from workstation.core.log import get_logger

log = get_logger(__name__)

# (step title, "module:function")
STEPS: list[tuple[str, str]] = [
    ("synthetic cloud, convert, info", "workstation.pipeline.demo_steps.foundation:step"),
    ("LiDAR simulation: ALS flight and TLS stations", "workstation.pipeline.demo_steps.simulate:step"),
    ("ground filtering (SMRF) and its evaluation against the truth", "workstation.pipeline.demo_steps.ground:step"),
    ("point classifier (shipped model)", "workstation.pipeline.demo_steps.classify:step"),
    ("DSM, DTM, CHM, hillshade, contours", "workstation.pipeline.demo_steps.raster:step"),
    ("ws run: the ALS flight as a four-tile project on a local Dask cluster", "workstation.pipeline.demo_steps.project:step"),
    ("registration: two stations registered and merged", "workstation.pipeline.demo_steps.registration:step"),
    ("photogrammetry: DLT, resection, intersection, GCP check report", "workstation.pipeline.demo_steps.photogrammetry:step"),
    ("dense stereo: CPU semi-global matching and fusion on a tiny rig", "workstation.pipeline.demo_steps.dense:step"),
    ("renders, terrain mesh, HTML report", "workstation.pipeline.demo_steps.mesh_render:step"),
]


@dataclass
class DemoContext:
    """What steps share: the output folder, the seed and the products made so far."""

    outdir: Path
    seed: int = 0
    products: dict[str, Path] = field(default_factory=dict)
    summaries: dict[str, dict] = field(default_factory=dict)


def _resolve(target: str) -> Callable[[DemoContext], dict]:
    mod, attr = target.split(":")
    return getattr(importlib.import_module(mod), attr)


def run_demo(outdir, seed: int = 0, on_step: Callable[[str, float, dict], None] | None = None) -> DemoContext:
    """Run every demo step into ``outdir`` (created); returns the context with all products."""
    ctx = DemoContext(Path(outdir), seed)
    ctx.outdir.mkdir(parents=True, exist_ok=True)
    for title, target in STEPS:
        t0 = time.perf_counter()
        made = _resolve(target)(ctx) or {}
        ctx.products.update(made)
        if on_step:
            on_step(title, time.perf_counter() - t0, made)
    return ctx
