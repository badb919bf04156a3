"""Surface reconstruction: screened Poisson, ball pivoting (MeshLab), 2.5D Delaunay (terrain).

- Screened Poisson: Kazhdan & Hoppe, "Screened Poisson surface reconstruction", ACM TOG 2013,
  through MeshLab's ``generate_surface_reconstruction_screened_poisson``. MeshLab stores the
  sample density of each output vertex as vertex quality; vertices below a density quantile
  (surface invented far from the data, e.g. the closed-off unseen side) are trimmed.
- Ball pivoting: Bernardini et al., "The ball-pivoting algorithm for surface
  reconstruction", IEEE TVCG 1999 (``generate_surface_reconstruction_ball_pivoting``).
- 2.5D Delaunay: a triangulated irregular network, Delaunay triangulation of the XY
  positions with Z carried along (Peucker et al. 1978). MeshLab 2025.7 has no such filter
  (its filter list was checked by introspection), so scipy's Qhull triangulation is used, and
  long-edged triangles over gaps and the convex hull are removed.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.color import rgb_to_u8
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.geometry import require_spread
from workstation.core.log import get_logger
from workstation.core.products import Mesh

from .steps import StepRecord, Timer, import_pymeshlab, openmp_threads, passive_openmp, point_spacing

#: The screened Poisson implementations of :class:`PoissonParams` (``backend``).
POISSON_BACKENDS = ("open3d", "pymeshlab")

log = get_logger(__name__)


@dataclass(frozen=True)
class PoissonParams:
    """Screened Poisson reconstruction parameters.

    Attributes
    ----------
    depth : int
        Maximum octree depth; the finest cell is (bounding cube side) / 2**depth.
    full_depth : int
        Depth up to which the octree is complete.
    samples_per_node : float
        Minimum number of points per octree cell (count; 1-5 noise-free, 15-20 noisy). Where
        the finest cells of ``depth`` are smaller than the point spacing, a larger value lets
        the octree stop where the data stop: depth 10 on a million points of a 23 m object
        (0.4 points per finest cell) took 46 s CPU with 6 against 122 s with 1.5, with the same
        surface error (median 0.31 against 0.25 mm, 95th percentile 1.03 against 0.99 mm;
        ``scripts/bench_mesh.py --only poisson_profile``). Default 2: through Open3D (point
        weight 2) that torus took 52-54 s in three runs against 55-65 s with 1.5, with a smaller
        error (0.26 / 1.11 against 0.30 / 1.20 mm), and the bunny's mesh is unchanged (mesh ->
        scans RMS 0.313 against 0.315 mm); 3 is faster again but invents surface where scans are
        sparse (bunny RMS 0.53 mm).
    point_weight : float or None
        Screening weight of the interpolation term (dimensionless; 0 = plain Poisson). None:
        Kazhdan's default for the backend's B-spline degree, twice the degree: 2 for Open3D's
        build (degree 1), 4 for MeshLab's (degree 2). Depth 10 on a million points through
        Open3D on 2 cores, samples per node 1.5: 2 took 51.6-65.5 s over six runs, surface error
        0.30 / 1.20 mm (median / 95th percentile, 23 m torus); 4 took 64 s, 0.25 / 0.99 mm.
    scale : float
        Ratio of the reconstruction cube to the bounding cube of the points (dimensionless).
    iterations : int
        Gauss-Seidel iterations per level (count; the ``pymeshlab`` backend only: Open3D keeps
        PoissonRecon's default of 8).
    trim_quantile : float
        Vertices whose density is below this quantile of the output vertices' densities are
        removed, with their faces (fraction in [0, 1); 0 = keep the closed surface).
    support_trim : float
        Vertices farther from the nearest input point than this many point spacings are
        removed, with their faces (dimensionless; 0 = off). The spacing is the median
        nearest-neighbour distance (:func:`~workstation.mesh.steps.point_spacing`), or half
        the spacing across scan lines where that is larger (:func:`support_spacing`: points
        close along lines far apart, whose surface between the lines lies up to half the gap
        from every point). Poisson closes the surface over holes and unseen parts; such
        invented surface has no data near it, while surface over the data lies within about
        one spacing of a point. The density trim misses invented sheets spanning small gaps,
        whose density is interpolated from their rims. Default 3 (chosen on the F-score of a
        simulated photo rig's dense cloud, checked on laser scans).
    backend : {"open3d", "pymeshlab"}
        Open3D's build of Kazhdan's screened PoissonRecon (default) or MeshLab's filter (the
        same algorithm and parameters). MeshLab's build is the slow Linux Poisson of PyMeshLab
        issue #408, measured here: depth 10 on a million points took 128 s on 2 idle cores
        against 64 s through Open3D at the same settings and surface error
        (``scripts/bench_mesh.py --only poisson,poisson_backend_open3d``); part of #408 is OpenMP's spinning wait (see
        :func:`workstation.mesh.steps.passive_openmp`), the rest is the build itself. So the
        Poisson step of the chain runs through Open3D unless ``pymeshlab`` is asked for.
    threads : int
        OpenMP threads of the solver (count; 0 = all cores, or 1 when OpenMP would spin:
        see :func:`workstation.mesh.steps.openmp_threads`).
    """

    depth: int = 9
    full_depth: int = 5
    samples_per_node: float = 2.0
    point_weight: float | None = None
    scale: float = 1.1
    iterations: int = 8
    trim_quantile: float = 0.05
    support_trim: float = 3.0
    backend: str = "open3d"
    threads: int = 0

    def __post_init__(self):
        if not 1 <= self.depth <= 16:
            raise InvalidInputError(f"depth={self.depth} out of 1..16", field="depth")
        if not 0.0 <= self.trim_quantile < 1.0:
            raise InvalidInputError(f"trim_quantile={self.trim_quantile} not in [0, 1)", field="trim_quantile")
        if not (np.isfinite(self.support_trim) and self.support_trim >= 0):
            raise InvalidInputError(f"support_trim={self.support_trim} must be ≥ 0", field="support_trim")
        if self.backend not in POISSON_BACKENDS:
            raise InvalidInputError(f"unknown Poisson backend '{self.backend}'", "use open3d or pymeshlab",
                                    field="backend")
        if self.samples_per_node <= 0:
            raise InvalidInputError("samples_per_node must be positive", field="samples_per_node")


@dataclass(frozen=True)
class BallPivotingParams:
    """Ball pivoting parameters.

    Attributes
    ----------
    radius : float or None
        Ball radius in CRS units; None = ``radius_factor`` × point spacing.
    radius_factor : float
        Radius in point spacings when ``radius`` is None (dimensionless).
    clustering : float
        Points closer than this fraction of the radius are merged (percent of the radius).
    crease_angle : float
        Maximum angle between adjacent faces in degrees.
    """

    radius: float | None = None
    radius_factor: float = 2.0
    clustering: float = 20.0
    crease_angle: float = 90.0


@dataclass(frozen=True)
class Delaunay25dParams:
    """2.5D Delaunay (TIN) parameters.

    Attributes
    ----------
    max_edge : float or None
        Triangles with an XY edge longer than this (CRS units) are dropped; None =
        ``max_edge_factor`` × point spacing (XY).
    max_edge_factor : float
        Edge limit in point spacings when ``max_edge`` is None (dimensionless).
    """

    max_edge: float | None = None
    max_edge_factor: float = 8.0


def _check_mesh(stage: str, mesh: Mesh) -> Mesh:
    if mesh.n_faces == 0:
        raise StageError(stage, "the reconstruction has no faces",
                         "check normals and the point spacing; try another method or parameters")
    return mesh


def poisson(cloud: Cloud, params: PoissonParams = PoissonParams(), tree=None) -> tuple[Mesh, StepRecord]:
    """Screened Poisson surface of an oriented cloud (needs ``normal``); ``tree``: the cloud's
    :func:`centred_tree` for the support trim when the caller has it already.

    Returns
    -------
    (Mesh, StepRecord)
        The mesh carries ``quality`` (float32): the solver's per-vertex sample density.
        Colours are not transferred here (see :func:`workstation.mesh.color.transfer_colors`).
    """
    if "normal" not in cloud.attrs:
        raise InvalidInputError("screened Poisson needs oriented normals", "run estimate_normals first",
                                field="normal")
    # PoissonRecon crashes the process on one repeated point and makes a tube of a line
    require_spread(cloud.xyz, 2, what="screened Poisson meshing", field="xyz", path=cloud.meta.get("source"))
    if params.backend == "open3d":
        passive_openmp()
    else:
        import_pymeshlab()
    from workstation.interop.pymeshlab import cloud_to_pymeshlab, meshset_with, pymeshlab_to_mesh

    threads = openmp_threads(params.threads)
    if params.point_weight is None:
        params = replace(params, point_weight=2.0 if params.backend == "open3d" else 4.0)
    with Timer() as t:
        if params.backend == "open3d":
            mesh = _poisson_open3d(cloud, params, threads)
        else:
            m, origin = cloud_to_pymeshlab(cloud.without_attrs("rgb") if "rgb" in cloud.attrs else cloud)
            ms = meshset_with(m)
            ms.generate_surface_reconstruction_screened_poisson(
                depth=int(params.depth), fulldepth=int(params.full_depth),
                samplespernode=float(params.samples_per_node), pointweight=float(params.point_weight),
                scale=float(params.scale), iters=int(params.iterations), confidence=False, preclean=False,
                threads=threads,
            )
            mesh = pymeshlab_to_mesh(ms.current_mesh(), origin, crs=cloud.crs)
        n_before = mesh.n_faces
        thr = None
        if params.trim_quantile > 0 and "quality" in mesh.vertex_attrs and mesh.n_faces:
            q = np.asarray(mesh.vertex_attrs["quality"], dtype=np.float64)
            thr = float(np.quantile(q, params.trim_quantile))
            mesh = keep_vertices(mesh, q >= thr)
        spacing, across, reach, n_support = None, None, None, 0
        if params.support_trim > 0 and mesh.n_faces:
            tree = centred_tree(cloud.xyz) if tree is None else tree
            spacing, across = point_spacing(cloud.xyz, tree=tree), across_spacing(cloud.xyz, tree=tree)
            reach = params.support_trim * max(spacing, 0.5 * across)
            far = support_distance(mesh.vertices, cloud.xyz, reach, tree=tree) > reach
            n_support = int(far.sum())
            mesh = keep_vertices(mesh, ~far)
    rec = StepRecord(
        "poisson",
        {"depth": params.depth, "full_depth": params.full_depth, "samples_per_node": params.samples_per_node,
         "point_weight": params.point_weight, "scale": params.scale, "iterations": params.iterations,
         "trim_quantile": params.trim_quantile, "support_trim": params.support_trim, "backend": params.backend,
         "threads": threads},
        t.seconds,
        {"faces_untrimmed": n_before, "faces": mesh.n_faces, "vertices": mesh.n_vertices,
         "density_threshold": thr, "point_spacing": spacing, "across_spacing": across, "support_reach": reach,
         "vertices_without_support": n_support,
         "cpu_seconds": round(t.cpu, 3)},
    )
    return _check_mesh("poisson", mesh), rec


def _poisson_open3d(cloud: Cloud, params: PoissonParams, threads: int) -> Mesh:
    """Open3D's screened Poisson (same PoissonRecon code); its densities become ``quality``."""
    try:
        import open3d as o3d
    except ImportError as e:  # pragma: no cover - declared dependency
        from workstation.core.errors import MissingDependencyError

        raise MissingDependencyError("open3d", "the open3d Poisson backend", "pip install open3d") from e
    origin = np.round(0.5 * (cloud.xyz.min(axis=0) + cloud.xyz.max(axis=0)))
    pc = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(cloud.xyz - origin))
    pc.normals = o3d.utility.Vector3dVector(np.array(cloud.attrs["normal"], dtype=np.float64))
    m, dens = o3d.geometry.TriangleMesh.create_from_point_cloud_poisson(
        pc, depth=int(params.depth), scale=float(params.scale), linear_fit=False, n_threads=int(threads),
        full_depth=int(params.full_depth), samples_per_node=float(params.samples_per_node),
        point_weight=float(params.point_weight))
    return Mesh(np.asarray(m.vertices) + origin, np.asarray(m.triangles, dtype=np.int64),
                {"quality": np.asarray(dens, dtype=np.float32)}, crs=cloud.crs)


@dataclass(frozen=True)
class RefineParams:
    """Projection of a mesh's vertices onto the moving-least-squares surface of its cloud.

    Attributes
    ----------
    k : int
        Cloud points per local plane (count): the noise of the cloud is averaged over about
        this many points; more smooths across edges narrower than their footprint, and bends
        curved surfaces toward their chords.
    photos_only : bool
        Project only the meshes of photogrammetric clouds, those meshed with their cameras
        (:func:`workstation.mesh.mesh_cloud` given a
        :class:`~workstation.core.products.Reconstruction`): multi-view
        stereo depths are noisy at the scale of their spacing, so the average gains more than
        the plane's bend costs. Laser clouds (low noise, dense) keep Poisson's surface, which
        already lies within their noise; False projects every mesh.
    chunk : int
        Vertices projected per vectorised batch (count; bounds the memory to about
        ``chunk × k × 100`` bytes).
    """

    k: int = 48
    photos_only: bool = True
    chunk: int = 50_000

    def __post_init__(self):
        if self.k < 3:
            raise InvalidInputError(f"k={self.k}: a plane fit needs at least 3 points", field="k")
        if self.chunk < 1:
            raise InvalidInputError("chunk must be ≥ 1", field="chunk")


def refine_to_cloud(mesh: Mesh, cloud: Cloud, params: RefineParams = RefineParams(),
                    tree=None) -> tuple[Mesh, StepRecord]:
    """Move every vertex to its foot on the Gaussian-weighted least-squares plane of its ``k``
    nearest cloud points: one first-order MLS projection step (Alexa et al., "Computing and
    rendering point set surfaces", IEEE TVCG 2003, with a plane as the local fit; bandwidth the
    median distance to the k-th neighbour). Screened Poisson interpolates its points, so the
    noise of a photogrammetric cloud stays in the surface; the projection averages it over the
    points of every view near the vertex. Faces and attributes are kept. ``tree``: the cloud's
    :func:`centred_tree` when the caller has it already (Poisson's support trim builds the same).

    Returns
    -------
    (Mesh, StepRecord)
        The record's summary gives the median and 95th percentile of the vertex moves.
    """
    if cloud.n < params.k:
        raise InvalidInputError(f"{cloud.n} points: too few for planes of k={params.k}", field="k")
    with Timer() as t:
        origin = cloud.xyz.mean(axis=0)
        xyz = cloud.xyz - origin
        v = mesh.vertices - origin
        if tree is None:  # centred_tree's, made from the centred points already here
            from scipy.spatial import cKDTree

            tree = cKDTree(xyz)
        d, _ = tree.query(v[: min(len(v), 20_000)], k=params.k)
        h = float(np.median(d[:, -1]))
        out = np.empty_like(v)
        for a in range(0, len(v), params.chunk):
            out[a:a + params.chunk] = _mls_plane_foot(v[a:a + params.chunk], xyz, tree, params.k, h)
        move = np.linalg.norm(out - v, axis=1)
        refined = Mesh(out + origin, mesh.faces, dict(mesh.vertex_attrs), dict(mesh.face_attrs), crs=mesh.crs,
                       meta=dict(mesh.meta))
    rec = StepRecord("refine_mls", {"k": params.k, "bandwidth": h}, t.seconds,
                     {"move_p50": float(np.median(move)) if move.size else 0.0,
                      "move_p95": float(np.percentile(move, 95)) if move.size else 0.0})
    return refined, rec


def _mls_plane_foot(v: np.ndarray, xyz: np.ndarray, tree, k: int, h: float) -> np.ndarray:
    """Feet (m, 3) of the points ``v`` on the Gaussian-weighted (bandwidth ``h``) planes of
    their k nearest points of ``xyz`` (indexed by ``tree``)."""
    d, idx = tree.query(v, k=k)
    w = np.exp(-(d / max(h, 1e-300)) ** 2) + 1e-12
    nb = xyz[idx]
    c = np.einsum("mk,mki->mi", w, nb) / w.sum(axis=1, keepdims=True)
    x = nb - c[:, None, :]
    _, vec = np.linalg.eigh(np.einsum("mk,mki,mkj->mij", w, x, x))
    n = vec[:, :, 0]
    return v - np.einsum("mi,mi->m", v - c, n)[:, None] * n


def centred_tree(xyz: np.ndarray):
    """A cKDTree of ``xyz`` (n, 3) less its mean (float64), the tree that
    :func:`support_distance` and :func:`across_spacing` search; build it once to share it."""
    from scipy.spatial import cKDTree

    xyz = np.asarray(xyz, np.float64)
    return cKDTree(xyz - xyz.mean(axis=0))


def support_distance(vertices: np.ndarray, xyz: np.ndarray, upper: float = np.inf, tree=None) -> np.ndarray:
    """Distance (n,) from each vertex to the nearest point of ``xyz`` (cKDTree); distances
    beyond ``upper`` come back as ``inf`` (the search stops there, which keeps it fast).
    ``tree``: :func:`centred_tree` of ``xyz``, built here when not given."""
    origin = np.asarray(xyz, np.float64).mean(axis=0)
    tree = centred_tree(xyz) if tree is None else tree
    return tree.query(np.asarray(vertices, np.float64) - origin, distance_upper_bound=float(upper))[0]


def across_spacing(xyz: np.ndarray, sample: int = 20000, seed: int = 0, k_max: int = 512, tree=None) -> float:
    """Median spacing across the lines a cloud's points may lie on, in coordinate units.

    For each query point (a seeded random sample of at most ``sample``, as
    :func:`~workstation.mesh.steps.point_spacing` draws), the distance to the nearest point at
    least 45° off the line through it and its nearest neighbour. On scan lines (airborne or
    terrestrial strips: points close along each line, lines far apart) that is the gap between
    lines; on a regular grid it is the grid step, the nearest-neighbour spacing; on an
    irregular isotropic cloud about 1.9 times that spacing (the nearest point in half of the
    directions, beyond the nearest). So half of it exceeds the nearest-neighbour spacing only
    where lines lie more than about twice as far apart as the points on them, which is when
    the surface between lines lies farther from every point than the nearest-neighbour
    spacing says. The search takes the 16 nearest points, doubled up to ``k_max`` for the
    points whose nearest ones all lie along their line; past ``k_max`` the farthest of them
    stands in (a lower bound). ``tree``: :func:`centred_tree` of ``xyz``, built here when not
    given.
    """
    xyz = np.asarray(xyz, dtype=np.float64)
    if xyz.shape[0] < 3:
        raise InvalidInputError(f"{xyz.shape[0]} points: need at least 3 to measure the spacing across lines")
    pts = xyz - xyz.mean(axis=0)
    rng = np.random.default_rng(seed)
    q = pts if len(pts) <= sample else pts[rng.choice(len(pts), sample, replace=False)]
    tree = centred_tree(xyz) if tree is None else tree
    out = np.full(len(q), np.nan)
    todo, k = np.arange(len(q)), 16
    while todo.size:
        k = min(k, len(pts) - 1)
        val, found = _across_block(tree, pts, q[todo], k)
        out[todo[found]] = val[found]
        if k >= min(k_max, len(pts) - 1):
            out[todo[~found]] = val[~found]
            break
        todo, k = todo[~found], 2 * k
    out = out[np.isfinite(out)]
    if out.size == 0:
        raise InvalidInputError("all points coincide: the spacing across lines is zero", "remove duplicate points")
    return float(np.median(out))


def _across_block(tree, pts: np.ndarray, q: np.ndarray, k: int, chunk: int = 1 << 20) -> tuple[np.ndarray, np.ndarray]:
    """For the query points ``q`` (m, 3), among their k nearest points of ``pts`` (``tree``):
    the distance (m,) to the nearest one at least 45° off the line to the nearest distinct
    point, and whether one was found (m,) bool; where none was, the distance is the k-th
    neighbour's (``inf`` when every neighbour coincides with the query). Queries run in
    blocks of about ``chunk`` neighbours."""
    val, found = np.empty(len(q)), np.zeros(len(q), bool)
    step = max(1, chunk // (k + 1))
    for s in range(0, len(q), step):
        qq = q[s:s + step]
        d, idx = tree.query(qq, k=k + 1)
        off = pts[idx] - qq[:, None, :]
        valid = d > 0
        m = np.arange(len(qq))
        first = np.argmax(valid, axis=1)
        d1 = off[m, first] / np.where(valid[m, first], d[m, first], np.inf)[:, None]
        across = valid & (np.abs(np.einsum("mki,mi->mk", off, d1)) <= np.sqrt(0.5) * d)
        hit = across.any(axis=1) & valid.any(axis=1)
        val[s:s + step] = np.where(hit, np.where(across, d, np.inf).min(axis=1),
                                   np.where(valid.any(axis=1), d[:, -1], np.inf))
        found[s:s + step] = hit
    return val, found


def keep_vertices(mesh: Mesh, keep: np.ndarray) -> Mesh:
    """Sub-mesh of the vertices where ``keep`` (n,) bool is True and the faces among them."""
    keep = np.asarray(keep, dtype=bool)
    fk = keep[mesh.faces].all(axis=1)
    remap = np.full(mesh.n_vertices, -1, dtype=np.int64)
    remap[keep] = np.arange(int(keep.sum()))
    return Mesh(mesh.vertices[keep], remap[mesh.faces[fk]],
                {k: np.asarray(v)[keep] for k, v in mesh.vertex_attrs.items()},
                {k: np.asarray(v)[fk] for k, v in mesh.face_attrs.items()}, crs=mesh.crs, meta=dict(mesh.meta))


def ball_pivoting(cloud: Cloud, params: BallPivotingParams = BallPivotingParams()) -> tuple[Mesh, StepRecord]:
    """Ball-pivoting mesh of a cloud with normals; the radius derives from the point spacing.

    Returns
    -------
    (Mesh, StepRecord)
    """
    if "normal" not in cloud.attrs:
        raise InvalidInputError("ball pivoting needs oriented normals", "run estimate_normals first", field="normal")
    require_spread(cloud.xyz, 2, what="ball-pivoting meshing", field="xyz", path=cloud.meta.get("source"))
    pml = import_pymeshlab()
    from workstation.interop.pymeshlab import cloud_to_pymeshlab, meshset_with, pymeshlab_to_mesh

    with Timer() as t:
        spacing = None
        radius = params.radius
        if radius is None:
            spacing = point_spacing(cloud.xyz)
            radius = params.radius_factor * spacing
        if radius <= 0:
            raise InvalidInputError(f"ball radius {radius} must be positive", field="radius")
        m, origin = cloud_to_pymeshlab(cloud.without_attrs("rgb") if "rgb" in cloud.attrs else cloud)
        ms = meshset_with(m)
        ms.generate_surface_reconstruction_ball_pivoting(
            ballradius=pml.PureValue(float(radius)), clustering=float(params.clustering),
            creasethr=float(params.crease_angle), deletefaces=False,
        )
        mesh = pymeshlab_to_mesh(ms.current_mesh(), origin, crs=cloud.crs, quality_name=None)
    rec = StepRecord("ball_pivoting", {"radius": float(radius), "point_spacing": spacing, "clustering_percent":
                                       params.clustering, "crease_angle_deg": params.crease_angle},
                     t.seconds, {"faces": mesh.n_faces, "vertices": mesh.n_vertices})
    return _check_mesh("ball_pivoting", mesh), rec


def delaunay25d(cloud: Cloud, params: Delaunay25dParams = Delaunay25dParams()) -> tuple[Mesh, StepRecord]:
    """2.5D Delaunay triangulation (TIN) of a terrain-like cloud: Z is a function of XY.

    Points with the same XY keep the first one. Triangles with an XY edge above the limit
    are removed (gaps, convex-hull slivers).

    Returns
    -------
    (Mesh, StepRecord)
    """
    from scipy.spatial import Delaunay

    if cloud.n < 3:
        raise InvalidInputError(f"{cloud.n} points: a triangulation needs at least 3", path=cloud.meta.get("source"))
    require_spread(cloud.xyz[:, :2], 2, what="a 2.5D Delaunay triangulation (of X, Y)", field="xyz",
                   path=cloud.meta.get("source"))
    with Timer() as t:
        xyz = cloud.xyz
        xy = xyz[:, :2]
        _, first = np.unique(xy, axis=0, return_index=True)
        first = np.sort(first)
        pts = xyz[first]
        origin = np.round(pts[:, :2].mean(axis=0))
        spacing = None
        max_edge = params.max_edge
        if max_edge is None:
            spacing = point_spacing(np.column_stack([pts[:, :2], np.zeros(len(pts))]))
            max_edge = params.max_edge_factor * spacing
        try:
            tri = Delaunay(pts[:, :2] - origin)
        except Exception as e:  # scipy raises QhullError for degenerate input
            raise StageError("delaunay25d", f"triangulation failed: {e}", "the points may be collinear") from e
        f = tri.simplices.astype(np.int64)
        p = pts[:, :2][f]
        e = np.stack([p[:, 1] - p[:, 0], p[:, 2] - p[:, 1], p[:, 0] - p[:, 2]], axis=1)
        longest = np.sqrt((e ** 2).sum(axis=2)).max(axis=1)
        f = f[longest <= max_edge]
        # counter-clockwise in XY so normals point up
        a = pts[f]
        cross_z = (a[:, 1, 0] - a[:, 0, 0]) * (a[:, 2, 1] - a[:, 0, 1]) - (a[:, 1, 1] - a[:, 0, 1]) * (a[:, 2, 0] - a[:, 0, 0])
        f = np.where((cross_z < 0)[:, None], f[:, [0, 2, 1]], f)
        used = np.zeros(len(pts), dtype=bool)
        used[f.ravel()] = True
        remap = np.cumsum(used) - 1
        attrs = {}
        if "rgb" in cloud.attrs:
            attrs["rgb"] = rgb_to_u8(np.asarray(cloud.attrs["rgb"])[first][used])
        mesh = Mesh(pts[used], remap[f], attrs, crs=cloud.crs)
    rec = StepRecord("delaunay25d", {"max_edge": float(max_edge), "point_spacing_xy": spacing},
                     t.seconds, {"faces": mesh.n_faces, "vertices": mesh.n_vertices,
                                 "duplicate_xy_dropped": int(cloud.n - len(first))})
    return _check_mesh("delaunay25d", mesh), rec
