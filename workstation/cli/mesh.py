"""`ws mesh IN -o OUT.{ply,obj,glb}`: a cloud to a cleaned, decimated, coloured mesh (MeshLab filters)."""

from __future__ import annotations

import click

from workstation.cli.options import allow_outside_option
from workstation.mesh import (BallPivotingParams, CleanParams, Delaunay25dParams, MeshChainParams, NormalParams,
                              PoissonParams, RefineParams, SmoothParams, TextureParams)
from workstation.mesh.chain import METHODS
from workstation.mesh.normals import ORIENTATIONS
from workstation.mesh.reconstruct import POISSON_BACKENDS
from workstation.mesh.simplify import SMOOTH_METHODS

from .options import emit_json, json_option, output_option, overwrite_option, read_options
from .options import FiniteFloatRange, SentinelIntRange, finite_float, nonneg_float, nonneg_int, positive_float
from .options import RegistryChoice, bound, field_option, param_group

#: Pieces smaller than this fraction of the mesh diagonal are removed by ``ws mesh`` (the library's
#: :class:`~workstation.mesh.CleanParams` keeps every piece unless asked: a command line mesh of a
#: scan is cleaned of the small floating pieces its noise makes).
MIN_PIECE_FRACTION = 0.05


@click.command()
@click.argument("src", metavar="IN", type=click.Path(exists=True, dir_okay=False))
@output_option
@field_option(MeshChainParams, "method", "--method", type=RegistryChoice(METHODS), show_default=True,
              help="Screened Poisson (objects, buildings), ball pivoting, or 2.5D Delaunay (terrain).")
@param_group(
    "poisson",
    bound(PoissonParams, "depth", "--depth", type=click.IntRange(1, 16), show_default=True,
          help="Poisson octree depth (finest cell = bounding cube / 2^depth)."),
    bound(PoissonParams, "samples_per_node", "--samples-per-node", type=positive_float, show_default=True,
          help="Poisson minimum points per octree cell (1-5 clean data, 15-20 noisy; larger is faster "
               "but smooths over sparsely sampled parts)."),
    bound(PoissonParams, "point_weight", "--point-weight", type=nonneg_float,
          help="Poisson screening weight (0 = unscreened) [default: twice the backend's B-spline degree: 2 open3d, 4 pymeshlab]."),
    bound(PoissonParams, "trim_quantile", "--trim-quantile", type=FiniteFloatRange(0, 1, max_open=True), show_default=True,
          help="Remove Poisson vertices below this quantile of sample density (fraction; 0 = keep all)."),
    bound(PoissonParams, "support_trim", "--support-trim", type=nonneg_float, show_default=True,
          help="Remove Poisson vertices farther than this many point spacings from every point (surface "
               "invented over holes and unseen parts; 0 = keep)."),
    bound(PoissonParams, "backend", "--poisson-backend", type=RegistryChoice(POISSON_BACKENDS), show_default=True,
          help="Open3D's build of screened PoissonRecon, or MeshLab's filter (same code, 2x slower here: PyMeshLab #408)."),
    bound(PoissonParams, "threads", "--threads", type=nonneg_int, show_default=True,
          help="Poisson solver threads (0 = all cores, or 1 if OpenMP spins; see OMP_WAIT_POLICY)."),
)
@param_group("ball_pivoting", bound(BallPivotingParams, "radius", "--radius", type=positive_float,
                                    help="Ball-pivoting radius in CRS units [default: 2 x point spacing]."))
@param_group("delaunay", bound(Delaunay25dParams, "max_edge", "--max-edge", type=positive_float,
                               help="2.5D Delaunay: longest triangle edge kept, CRS units [default: 8 x point spacing]."))
@param_group(
    "normals",
    bound(NormalParams, "k", "--k-normals", type=click.IntRange(3, 200), show_default=True,
          help="Neighbours per normal (PCA plane fit)."),
    bound(NormalParams, "orient", "--orient", type=RegistryChoice(ORIENTATIONS), show_default=True,
          help="Normal orientation (auto: toward --viewpoint if given, else propagate)."),
)
@click.option("--viewpoint", type=finite_float, nargs=3, default=None, metavar="X Y Z",
              help="Scanner position (CRS units) the normals must face.")
@param_group("normals", bound(NormalParams, "recompute", "--recompute-normals", is_flag=True,
                              help="Estimate normals even when the cloud has them."))
@click.option("--refine-k", type=SentinelIntRange(0, min=3, max=1000), default=None,
              help="Project the vertices onto the moving-least-squares planes of this many cloud points after "
                   "reconstruction (averages the noise of photogrammetric clouds; 0 = off, else at least 3: "
                   "a plane fit needs 3 points) "
                   f"[default: {RefineParams.k} with --reconstruction, else off].")
@click.option("--target-faces", type=click.IntRange(4, None), default=None,
              help="Quadric edge-collapse decimation to this face count [default: no decimation].")
@param_group(
    "smooth",
    bound(SmoothParams, "method", "--smooth", type=RegistryChoice(SMOOTH_METHODS, first=["none"]), default="none",
          show_default=True, help="Smoothing after decimation."),
    bound(SmoothParams, "iterations", "--smooth-iterations", type=click.IntRange(0, 1000), show_default=True,
          help="Smoothing passes."),
)
@param_group(
    "clean",
    bound(CleanParams, "min_piece_fraction", "--min-piece-fraction", type=FiniteFloatRange(0, 1, max_open=True),
          default=MIN_PIECE_FRACTION, show_default=True,
          help="Remove pieces smaller than this fraction of the mesh diagonal."),
    bound(CleanParams, "max_hole_edges", "--max-hole-edges", type=click.IntRange(0, None), show_default=True,
          help="Close holes bounded by at most this many edges (0 = none)."),
)
@click.option("--no-color", is_flag=True, help="Do not transfer cloud colours to the vertices.")
@click.option("--no-quality", is_flag=True, help="Skip the quality summary (distances to the cloud).")
@click.option("--reconstruction", "workdir", type=click.Path(exists=True), default=None,
              help="Oriented photos (COLMAP work folder or cameras.json) in the cloud's frame: texture the mesh "
                   "from them (OUT must be .obj, .glb or .gltf) and orient normals toward the cameras.")
@click.option("--images", "image_dir", type=click.Path(exists=True, file_okay=False), default=None,
              help="Folder of the photos [default: the folder `ws sfm` recorded in WORKDIR, else WORKDIR/images].")
@param_group(
    "texture",
    bound(TextureParams, "texel_size", "--texel-size", type=positive_float,
          help="Texture: surface size of one texel in CRS units [default: per face, texels no larger than the pixels of its best photo]."),
    bound(TextureParams, "max_texture_size", "--texture-size", type=click.IntRange(16, 32768), show_default=True,
          help="Texture: largest side of the texture image, pixels."),
    bound(TextureParams, "max_views", "--texture-views", type=click.IntRange(1, 16), show_default=True,
          help="Texture: photos blended per face (1 = the sharpest view)."),
    bound(TextureParams, "exposure_balance", "--exposure-balance/--no-exposure-balance", show_default=True,
          help="Texture: balance the photos' exposure and white balance by per-photo gains (Brown & Lowe 2007)."),
    bound(TextureParams, "last_resort", "--last-resort/--no-last-resort", show_default=True,
          help="Texture: a face no photo sees frontally and whole takes a grazing or partly hidden view rather "
               "than none."),
    bound(TextureParams, "photo_consistency", "--photo-consistency/--no-photo-consistency", show_default=True,
          help="Texture: drop the photos whose colour of a face disagrees with most others (an occluder the mesh "
               "lacks: trees, people, cars) before choosing its photo (Waechter et al. 2014)."),
)
@overwrite_option
@allow_outside_option
@read_options
@json_option
def mesh(src, output, method, poisson, ball_pivoting, delaunay, normals, viewpoint, refine_k, target_faces, smooth,
         clean, no_color, no_quality, workdir, image_dir, texture, overwrite, read_opts, as_json):
    """Mesh the cloud IN and write OUT (.ply, .obj, .glb, .gltf, .off) with a quality summary.

    With --reconstruction the mesh is textured from the oriented photos: OUT.obj comes with
    OUT.mtl and the texture OUT.png (material and texture named after the mesh, so meshes in
    one folder never collide; --overwrite covers them too), OUT.glb embeds the texture. The
    photos, the model and every image it names are checked before any work, and the stage
    record WORKDIR/mesh_OUT.json (shown by `ws report WORKDIR`) is written.
    """
    import numpy as np

    from workstation.core.errors import InvalidInputError
    from workstation.core.log import get_logger
    from workstation.io import check_outputs, read_cloud
    from workstation.io.mesh import check_mesh_extension, write_mesh
    from workstation.mesh import ColorTransferParams, DecimateParams, QualityParams, mesh_cloud

    log = get_logger(__name__)
    ext = check_mesh_extension(output)
    if workdir is not None and ext not in (".obj", ".glb", ".gltf"):
        raise InvalidInputError(f"a textured mesh cannot be written as {ext}", "write .obj, .glb or .gltf",
                                path=output)
    rec = None
    if workdir is not None:
        rec, image_dir = _checked_reconstruction(workdir, image_dir)
    check_outputs(textured_mesh_files(output) if workdir is not None else [output], overwrite, inputs=[src])
    cloud = read_cloud(src, **read_opts)
    params = MeshChainParams(
        method=method, normals=NormalParams(**normals), poisson=PoissonParams(**poisson),
        ball_pivoting=BallPivotingParams(**ball_pivoting), delaunay=Delaunay25dParams(**delaunay),
        refine=_refine(refine_k), clean=CleanParams(**clean),
        decimate=DecimateParams(target_faces=target_faces) if target_faces else None,
        smooth=SmoothParams(**smooth) if smooth["method"] != "none" else None,
        color=None if no_color else ColorTransferParams(), quality=None if no_quality else QualityParams(),
        texture=TextureParams(**texture),
    )
    vp = np.asarray(viewpoint) if viewpoint else rec
    res = mesh_cloud(cloud, params, viewpoints=vp, reconstruction=rec)
    write_mesh(res.mesh, output, overwrite=overwrite, inputs=[src])
    log.info("wrote %s: %d faces, %d vertices in %.1f s", output, res.mesh.n_faces, res.mesh.n_vertices, res.seconds)
    from workstation.cli.summary import count, emit_summary

    emit_summary("mesh", f"{count(res.mesh.n_faces, 'faces')}, {count(res.mesh.n_vertices, 'vertices')}", output,
                 details=[method, f"from {count(cloud.n, 'points')}"])
    doc = {"input": src, "output": output, "method": method, **res.to_dict()}
    if workdir is not None:
        _write_record(doc, src, output, workdir, image_dir, params)
    if as_json:
        emit_json(doc)


def _refine(refine_k):
    """The refinement of ``--refine-k``: None (the default) projects the meshes of clouds given
    with their cameras only (:attr:`RefineParams.photos_only`), 0 none, k every mesh."""
    if refine_k is None:
        return RefineParams()
    return RefineParams(k=refine_k, photos_only=False) if refine_k else None


def textured_mesh_files(output) -> list:
    """The files a textured mesh OUT makes: OUT.obj with OUT.mtl and OUT.png; OUT.glb/.gltf alone
    (texture embedded)."""
    from pathlib import Path

    from workstation.io.mesh import textured_obj_files

    return textured_obj_files(output) if Path(output).suffix.lower() == ".obj" else [Path(output)]


def _checked_reconstruction(workdir, image_dir):
    """The oriented photos of WORKDIR, with the image folder from the `ws sfm` record unless
    --images is given, and every image on disk (checked before the cloud is read)."""
    from workstation.io.reconstruction import check_image_files, resolve_image_dir
    from workstation.photogrammetry.sfm import read_reconstruction

    image_dir = resolve_image_dir(workdir, image_dir)
    rec = read_reconstruction(workdir, image_dir)
    check_image_files(rec, image_dir, workdir)
    return rec, image_dir


def _write_record(doc: dict, src, output, workdir, image_dir, params) -> None:
    """The mesh stage record WORKDIR/mesh_<OUT stem>.json (the --json document, inputs, params)."""
    import dataclasses
    from pathlib import Path

    from workstation.cli.summary import elapsed
    from workstation.io.reconstruction import stage_record, work_folder_of, write_stage_record

    rec = stage_record("mesh", doc, inputs={"cloud": src, "reconstruction": workdir, "image_dir": image_dir},
                       params=dataclasses.asdict(params),
                       outputs=[f for f in textured_mesh_files(output) if Path(f).exists()], seconds=elapsed())
    write_stage_record(rec, work_folder_of(workdir) / f"mesh_{Path(output).stem}.json", required=False)
