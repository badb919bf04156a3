"""The photo stages of a project run: structure from motion, dense matching and the mesh.

The photos are one block, so each stage is one task over all of them, calling the library
functions and parameter dataclasses of ``ws sfm``, ``ws dense`` and ``ws mesh``. ``OUT/sfm/``
is a work folder in the layout ``ws sfm`` writes (``database.db``, ``sparse/0``,
``sparse.ply``, ``summary.json``; the dense stage adds ``dense/`` with its depth maps,
``fused.ply`` and record), so ``ws dense OUT/sfm``, ``ws mesh --reconstruction OUT/sfm`` and
``ws report OUT/sfm`` work on it as on a folder the commands made. The deliverables are
``OUT/dense/dense.laz`` (the fused cloud) and ``OUT/mesh/mesh.<format>``.

A stage that runs again starts from a clean folder (the sfm stage removes ``OUT/sfm`` and so
the dense maps built on the old model); what a failed or killed task made is removed
(:func:`workstation.io.work_folder`), and single files are written atomically.
"""

from __future__ import annotations

import dataclasses
import os
import shutil
import time
from pathlib import Path

from workstation.core.errors import InvalidInputError

from .manifest import task_key
from .tasks import elapsed, peak_rss_mb


def check_photo_names(photos: tuple, project_path: Path) -> None:
    """Refuse two photos of one file name in different folders (COLMAP names images by file
    name, and the photos are read from one folder)."""
    names: dict[str, Path] = {}
    for p in photos:
        if p.name in names:
            raise InvalidInputError(f"two photos are named {p.name}: {names[p.name]} and {p}",
                                    "rename one; the photos of a block need distinct file names",
                                    path=project_path, field="inputs.photos")
        names[p.name] = p


def photo_folder(cache: Path, photos: tuple) -> tuple[Path, bool]:
    """The folder the photos are read from, and whether it is to be made of links: their own
    folder when they are all of its images, else ``OUT/.ws-cache/photos`` (filled with links by
    the sfm task)."""
    from workstation.photogrammetry.calibration import IMAGE_SUFFIXES

    folders = {p.parent for p in photos}
    if len(folders) == 1:
        folder = next(iter(folders))
        own = {q.resolve() for q in folder.iterdir() if q.is_file() and q.suffix.lower() in IMAGE_SUFFIXES}
        if own == set(photos):
            return folder, False
    return cache / "photos", True


def _link_photos(photos: list, folder: Path) -> None:
    """``folder`` holding a link to each photo and nothing else (a subset of a folder, or
    photos from several folders)."""
    if folder.is_dir():
        shutil.rmtree(folder)
    folder.mkdir(parents=True)
    for p in photos:
        os.symlink(p, folder / Path(p).name)


def sfm_task(out: str, photos: list, image_dir: str, link: bool, stage) -> dict:
    """Orient the photos into the work folder ``OUT/sfm`` (``ws sfm`` without GCPs): the COLMAP
    model, the upright (and scaled) sparse cloud and the stage record."""
    from workstation.io import work_folder
    from workstation.io.reconstruction import SFM_RECORD, write_stage_record
    from workstation.photogrammetry.scale import parse_scale_texts
    from workstation.photogrammetry.sfm import orient_photos, sfm_record

    t0 = time.perf_counter()
    workdir, image_dir = Path(out) / "sfm", Path(image_dir)
    if link:
        _link_photos(photos, image_dir)
    camera = None
    if stage.camera is not None:
        from workstation.io.camera import read_camera

        camera = read_camera(stage.camera)
    if workdir.exists():
        shutil.rmtree(workdir)  # the dense maps of an older model go with it
    bars = parse_scale_texts(stage.scale_bars, stage.scale_distances)
    with work_folder(workdir):
        result, doc = orient_photos(image_dir, workdir, camera, stage.params, upright=stage.upright,
                                    scale_bars=bars, sigma_px=stage.sigma_px, overwrite=True)
        outputs = [workdir / "sparse" / "0", workdir / "sparse.ply", workdir / SFM_RECORD]
        rec = sfm_record(doc, image_dir, workdir, stage.params, upright=stage.upright, outputs=outputs[:2],
                         seconds=elapsed(t0), camera_file=stage.camera)
        write_stage_record(rec, workdir / SFM_RECORD)
    s = result.summary
    return {"images": s["images"], "registered": s["registered"], "points": s["points"],
            "reprojection_px": s["mean_reprojection_error_px"], "scaled": doc.get("scaled"),
            "unregistered": list(result.unregistered), "seconds": elapsed(t0), "peak_rss_mb": peak_rss_mb(),
            "outputs": [str(p) for p in outputs]}


def dense_task(out: str, image_dir: str, params, *upstream) -> dict:
    """Depth maps and fusion in ``OUT/sfm/dense`` (``ws dense OUT/sfm``) and the fused cloud
    as ``OUT/dense/dense.laz``."""
    from workstation.cli.dense import write_dense_record
    from workstation.io import work_folder, write_cloud
    from workstation.photogrammetry.dense import run_dense

    t0 = time.perf_counter()
    workdir = Path(out) / "sfm"
    with work_folder(workdir / "dense"):
        cloud, summary = run_dense(workdir, image_dir, params, overwrite=True)
    record = write_dense_record(workdir, Path(image_dir), params, summary)
    laz = Path(out) / "dense" / "dense.laz"
    laz.parent.mkdir(parents=True, exist_ok=True)
    write_cloud(cloud, laz, overwrite=True)
    return {"points": int(cloud.n), "device": summary["device"], "method": summary.get("method"),
            "seconds": elapsed(t0), "peak_rss_mb": peak_rss_mb(),
            "outputs": [summary["fused"], str(record), str(laz)]}


def mesh_task(out: str, image_dir: str, stage, *upstream) -> dict:
    """The mesh of the fused cloud (``ws mesh OUT/sfm/dense/fused.ply``), textured from the
    oriented photos when the stage asks (``--reconstruction OUT/sfm``), as
    ``OUT/mesh/mesh.<format>``; its record goes to ``OUT/sfm/mesh_mesh.json``."""
    from workstation.cli.mesh import textured_mesh_files
    from workstation.io import read_cloud
    from workstation.io.mesh import write_mesh
    from workstation.io.reconstruction import stage_record, write_stage_record
    from workstation.mesh import mesh_cloud

    t0 = time.perf_counter()
    workdir = Path(out) / "sfm"
    src = workdir / "dense" / "fused.ply"
    cloud = read_cloud(src)
    rec = None
    if stage.textured:
        from workstation.photogrammetry.sfm import read_reconstruction

        rec = read_reconstruction(workdir, image_dir)
    res = mesh_cloud(cloud, stage.params, viewpoints=rec, reconstruction=rec, photogrammetric=True)
    path = Path(out) / "mesh" / f"mesh.{stage.format}"
    path.parent.mkdir(parents=True, exist_ok=True)
    write_mesh(res.mesh, path, overwrite=True)
    files = [str(f) for f in (textured_mesh_files(path) if stage.textured else [path]) if Path(f).exists()]
    doc = {"input": str(src), "output": str(path), "method": stage.params.method, **res.to_dict()}
    record = write_stage_record(stage_record("mesh", doc, inputs={"cloud": src, "reconstruction": workdir,
                                                                  "image_dir": image_dir},
                                             params=dataclasses.asdict(stage.params), outputs=files,
                                             seconds=elapsed(t0)), workdir / "mesh_mesh.json")
    return {"faces": int(res.mesh.n_faces), "vertices": int(res.mesh.n_vertices), "points": int(cloud.n),
            "seconds": elapsed(t0), "peak_rss_mb": peak_rss_mb(), "outputs": files + [str(record)]}


def photo_tasks(ctx, plan, manifest) -> list:
    """The sfm, dense and mesh tasks the plan asks for, keyed by the photos' contents, the
    stage's parameters and the upstream key."""
    from .plan import Task

    if plan.sfm is None:
        return []
    photos = [str(p) for p in ctx.photos]
    hashes = {p: manifest.file_hash(Path(p)) for p in photos}
    folder, link = photo_folder(ctx.cache, ctx.photos)
    image_dir = str(folder)
    out = str(ctx.out)
    p = plan.params_of("sfm")
    sfm = Task("sfm/photos", "sfm", sfm_task, (out, photos, image_dir, link, plan.sfm),
               key=task_key("sfm", {**p, "image_dir": image_dir}, list(hashes.values())), params=p, inputs=hashes)
    tasks = [sfm]
    if plan.dense is not None:
        p = plan.params_of("dense")
        tasks.append(Task("dense/photos", "dense", dense_task, (out, image_dir, plan.dense), [sfm.id],
                          task_key("dense", p, (), [sfm.key]), p))
    if plan.mesh is not None and plan.dense is not None:
        p = plan.params_of("mesh")
        tasks.append(Task("mesh/photos", "mesh", mesh_task, (out, image_dir, plan.mesh), [tasks[-1].id],
                          task_key("mesh", p, (), [tasks[-1].key]), p))
    return tasks
