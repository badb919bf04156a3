"""Filter chains: cloud -> normals -> surface -> refine -> clean -> decimate -> smooth -> colours -> quality.

Each step is one named function with a frozen parameter dataclass; the chain records every
step (parameters resolved to numbers, seconds, summary) in the result and in the mesh's
``meta["steps"]``.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any, Mapping

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.core.log import get_logger
from workstation.core.products import Mesh, Reconstruction

from .clean import CleanParams, clean
from .color import ColorTransferParams, transfer_colors
from workstation.core.geometry import require_spread

from .normals import NormalParams, estimate_normals
from .quality import QualityParams, mesh_quality
from .reconstruct import (BallPivotingParams, Delaunay25dParams, PoissonParams, RefineParams, ball_pivoting, centred_tree,
                          delaunay25d, poisson, refine_to_cloud)
from .simplify import DecimateParams, SmoothParams, decimate, smooth
from .steps import StepRecord, Timer
from .texture import TextureParams, texture_from_photos

log = get_logger(__name__)

METHODS = ("poisson", "bpa", "delaunay25d")


@dataclass(frozen=True)
class MeshChainParams:
    """The whole chain; each field is the parameter set of one step (None = skip the step).

    Attributes
    ----------
    method : {"poisson", "bpa", "delaunay25d"}
        Surface reconstruction: screened Poisson (closed objects, noisy data), ball pivoting
        (dense, even sampling; keeps the input points as vertices), 2.5D Delaunay (terrain).
    normals : NormalParams
        Used by poisson and bpa.
    poisson, ball_pivoting, delaunay : parameter sets of the reconstruction methods
    refine : RefineParams or None
        Vertices projected onto the cloud's moving-least-squares surface right after the
        reconstruction (averages the noise of photogrammetric clouds; by default only for a
        cloud meshed with its cameras, see :attr:`RefineParams.photos_only`; None = off).
    clean : CleanParams or None
    decimate : DecimateParams or None
    smooth : SmoothParams or None
    color : ColorTransferParams or None
        Applied when the cloud has ``rgb``.
    quality : QualityParams or None
        Quality summary with distances to the input cloud.
    texture : TextureParams or None
        Texture from the oriented photos, applied when a reconstruction is given (last step;
        the quality summary is taken on the mesh before its corners are split for the atlas).
    """

    method: str = "poisson"
    normals: NormalParams = NormalParams()
    poisson: PoissonParams = PoissonParams()
    ball_pivoting: BallPivotingParams = BallPivotingParams()
    delaunay: Delaunay25dParams = Delaunay25dParams()
    refine: RefineParams | None = RefineParams()
    clean: CleanParams | None = CleanParams()
    decimate: DecimateParams | None = None
    smooth: SmoothParams | None = None
    color: ColorTransferParams | None = ColorTransferParams()
    quality: QualityParams | None = QualityParams()
    texture: TextureParams | None = TextureParams()

    def __post_init__(self):
        if self.method not in METHODS:
            raise InvalidInputError(f"unknown meshing method '{self.method}'", "use one of " + ", ".join(METHODS),
                                    field="method")


@dataclass(frozen=True)
class MeshResult:
    """A mesh, the record of every step that made it, and its quality summary."""

    mesh: Mesh
    steps: tuple[StepRecord, ...] = ()
    quality: Mapping[str, Any] = field(default_factory=dict)
    seconds: float = 0.0

    def to_dict(self) -> dict:
        return {"faces": self.mesh.n_faces, "vertices": self.mesh.n_vertices, "seconds": round(self.seconds, 3),
                "steps": [s.to_dict() for s in self.steps], "quality": dict(self.quality)}


def mesh_cloud(cloud: Cloud, params: MeshChainParams = MeshChainParams(), viewpoints=None, *,
               reconstruction: Reconstruction | None = None, images=None,
               photogrammetric: bool | None = None) -> MeshResult:
    """Run the meshing chain on a cloud.

    Parameters
    ----------
    cloud : Cloud
    params : MeshChainParams
    viewpoints : (3,) or (n, 3) float, or Reconstruction, optional
        Scanner positions or cameras for normal orientation. Cameras (or ``reconstruction``)
        mark the cloud as photogrammetric: ``params.refine`` then runs even when it is
        :attr:`~RefineParams.photos_only`.
    reconstruction : Reconstruction, optional
        Oriented photos in the cloud's frame: the mesh is textured from them
        (``params.texture``).
    images : mapping of image id to (h, w, 3) uint8, optional
        The photos' pixels (read from their paths otherwise).
    photogrammetric : bool, optional
        Whether the cloud comes from photos (``params.refine`` runs even when it is
        ``photos_only``); None: when cameras are given.

    Returns
    -------
    MeshResult
    """
    if cloud.n < 3:
        raise InvalidInputError(f"{cloud.n} points: too few to mesh", path=cloud.meta.get("source"))
    if params.method in ("poisson", "bpa"):  # normals need k neighbours and a surface, before Open3D sees them
        require_spread(cloud.xyz, 2, what=f"meshing ({params.method})", min_points=max(3, params.normals.k), field="xyz",
                       path=cloud.meta.get("source"))
    steps: list[StepRecord] = []
    with Timer() as t:
        work = cloud
        if params.method in ("poisson", "bpa"):
            work, rec = estimate_normals(cloud, params.normals, viewpoints)
            steps.append(rec)
        photos = isinstance(viewpoints, Reconstruction) or reconstruction is not None
        refining = params.refine is not None and ((photos if photogrammetric is None else photogrammetric)
                                                  or not params.refine.photos_only)
        # Poisson's support trim and the refinement search the same tree of the cloud: build it once
        tree = centred_tree(cloud.xyz) if refining and params.method == "poisson" and params.poisson.support_trim > 0 else None
        if params.method == "poisson":
            mesh, rec = poisson(work, params.poisson, tree=tree)
        elif params.method == "bpa":
            mesh, rec = ball_pivoting(work, params.ball_pivoting)
        else:
            mesh, rec = delaunay25d(work, params.delaunay)
        steps.append(rec)
        log.info("%s: %d faces in %.1f s", rec.name, mesh.n_faces, rec.seconds)
        if refining:
            mesh, rec = refine_to_cloud(mesh, cloud, params.refine, tree=tree)
            steps.append(rec)
        if params.clean is not None:
            cp = params.clean
            if params.quality is not None and params.quality.self_intersections:
                cp = replace(cp, report_self_intersections=False)  # counted once, on the final mesh
            mesh, rec = clean(mesh, cp)
            steps.append(rec)
        if params.decimate is not None:
            mesh, rec = decimate(mesh, params.decimate)
            steps.append(rec)
        if params.smooth is not None:
            mesh, rec = smooth(mesh, params.smooth)
            steps.append(rec)
        if params.clean is not None and params.decimate is not None:
            # edge collapses can pinch the surface into non-manifold edges again
            mesh, rec = clean(mesh, CleanParams(report_self_intersections=False))
            steps.append(replace(rec, name="clean_after_decimation"))
        if params.color is not None and "rgb" in cloud.attrs:
            mesh, rec = transfer_colors(mesh, cloud, params.color)
            steps.append(rec)
        attrs = {k: v for k, v in mesh.vertex_attrs.items() if k in ("rgb", "normal")}
        mesh = Mesh(mesh.vertices, mesh.faces, attrs, crs=cloud.crs,
                    meta={"steps": [s.to_dict() for s in steps], "source_points": cloud.n})
        quality = {}
        if params.quality is not None:
            with Timer() as tq:
                quality = mesh_quality(mesh, cloud, params.quality)
            steps.append(StepRecord("quality", {"mesh_samples": params.quality.mesh_samples}, tq.seconds))
        if reconstruction is not None and params.texture is not None:
            mesh, rec = texture_from_photos(mesh, reconstruction, params.texture, images=images)
            steps.append(rec)
            mesh = Mesh(mesh.vertices, mesh.faces, mesh.vertex_attrs, mesh.face_attrs, crs=mesh.crs,
                        meta={**mesh.meta, "steps": [s.to_dict() for s in steps]})
    return MeshResult(mesh, tuple(steps), quality, t.seconds)
