"""Demo step of meshing and rendering: renders of the demo clouds, a terrain mesh, a mesh of the
dense rig cloud textured from its photos, the HTML report."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

CLOUD_SUFFIXES = (".las", ".laz", ".ply", ".pcd", ".e57")


def step(ctx) -> dict:
    from workstation.io import atomic_path, read_cloud
    from workstation.io.mesh import write_mesh
    from workstation.mesh import (CleanParams, DecimateParams, Delaunay25dParams, MeshChainParams, QualityParams,
                                  mesh_cloud)
    from workstation.render import RenderParams, render, save_png
    from workstation.render.report import ReportParams, write_report

    made: dict[str, Path] = {}
    # one top-view render per distinct demo cloud (the same cloud in LAS and LAZ once)
    seen = set()
    clouds = {}
    for key, path in sorted(ctx.products.items()):
        p = Path(path)
        if p.suffix.lower() not in CLOUD_SUFFIXES or not p.exists():
            continue
        c = read_cloud(p)
        sig = (c.n, tuple(np.round(c.xyz[:3].ravel(), 3)))
        if sig in seen:
            continue
        seen.add(sig)
        clouds[key] = c
        color = "class" if "classification" in c.attrs else "auto"
        img = render(c, RenderParams(size=(640, 480), view="top", color=color, max_points=300_000))
        out = ctx.outdir / f"render_{key}.png"
        save_png(img, out, overwrite=True)
        made[f"render_{key}"] = out
    if not clouds:
        return made
    # a terrain mesh (2.5D Delaunay) of a 20,000-point subset of the first cloud's ground and roads
    key, c = next(iter(clouds.items()))
    from workstation.core.classes import ASPRSClass

    if "classification" in c.attrs:
        bare = np.isin(np.asarray(c.attrs["classification"]), [ASPRSClass.GROUND, ASPRSClass.ROAD_SURFACE])
        if bare.any():
            c = c[bare]
    rng = np.random.default_rng(ctx.seed)
    small = c[np.sort(rng.choice(c.n, min(20_000, c.n), replace=False))]
    res = mesh_cloud(small, MeshChainParams(method="delaunay25d", delaunay=Delaunay25dParams(),
                                            clean=CleanParams(), decimate=DecimateParams(target_faces=8000),
                                            quality=QualityParams(max_cloud_points=20_000)))
    mesh_path = ctx.outdir / "terrain_mesh.ply"
    write_mesh(res.mesh, mesh_path, overwrite=True)
    summary = {"source": key, **res.to_dict()}
    summary_path = ctx.outdir / "terrain_mesh.json"
    with atomic_path(summary_path, overwrite=True) as tmp:
        tmp.write_text(json.dumps(summary, indent=2, default=float))
    img = render(res.mesh, RenderParams(size=(640, 480), view="iso", color="elevation"))
    save_png(img, ctx.outdir / "render_terrain_mesh.png", overwrite=True)
    made.update({"terrain_mesh": mesh_path, "terrain_mesh_summary": summary_path,
                 "render_terrain_mesh": ctx.outdir / "render_terrain_mesh.png"})
    ctx.summaries["mesh_render"] = {"faces": res.mesh.n_faces, "rms_to_cloud": res.quality["cloud_to_mesh"]["rms"]}
    made.update(_textured_rig_mesh(ctx))
    report = ctx.outdir / "report.html"
    write_report(ctx.outdir, report, overwrite=True, params=ReportParams(render_size=(400, 300), max_points=200_000))
    made["report"] = report
    return made


def _textured_rig_mesh(ctx) -> dict:
    """Screened Poisson mesh of the dense step's cloud (box and wall), textured from the rig's
    oriented photos: ``ws mesh dense_box.ply --reconstruction dense_rig -o textured_box.obj``."""
    from workstation.io import read_cloud
    from workstation.io.mesh import write_mesh
    from workstation.mesh import (CleanParams, DecimateParams, MeshChainParams, NormalParams, PoissonParams,
                                  TextureParams, mesh_cloud)
    from workstation.photogrammetry.sfm import read_reconstruction

    dense = ctx.products.get("dense_ply")
    work = ctx.outdir / "dense_rig"
    if dense is None or not Path(dense).exists() or not (work / "sparse" / "0").is_dir():
        return {}
    cloud = read_cloud(dense)
    rec = read_reconstruction(work, work / "images")
    res = mesh_cloud(cloud, MeshChainParams(method="poisson", normals=NormalParams(k=12),
                                            poisson=PoissonParams(depth=7, trim_quantile=0.1),
                                            clean=CleanParams(min_piece_fraction=0.1),
                                            decimate=DecimateParams(target_faces=6000), quality=None,
                                            texture=TextureParams(max_texture_size=1024)),
                     viewpoints=rec, reconstruction=rec)
    out = ctx.outdir / "textured_box.obj"
    write_mesh(res.mesh, out, overwrite=True)
    tex = next(s for s in res.steps if s.name == "texture")
    ctx.summaries["textured_mesh"] = {"faces": res.mesh.n_faces, **tex.summary}
    return {"textured_mesh": out}
