"""A vectorised voxel hash of local planes, and point-to-plane ICP against it.

Point-to-plane ICP (Chen & Medioni 1992, "Object modelling by registration of multiple range
images"; linearised as in Low 2004, "Linear least-squares optimization for point-to-plane ICP
surface registration", UNC TR04-004) spends nearly all its time in the nearest-neighbour
search. Here the target is summarised once into per-voxel planes (centroid and normal from
the voxel's covariance, as in NDT, Biber & Strasser 2003, and voxelised GICP, Koide et al.
2021, ICRA), stored in an open-addressing hash table built and probed with numpy, so finding
a source point's plane is a constant-time gather instead of a tree search. Each occupied voxel
also lends its plane to the empty voxels just above and below it along its normal, so points
up to one voxel off the surface still find it. A coarse-to-fine voxel schedule widens the
capture range.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workstation.core.errors import InvalidInputError
from workstation.core.pca import group_moments

_OFF = 1 << 20  # voxel indices are packed as three 21-bit fields
_GOLD = np.uint64(0x9E3779B97F4A7C15)


def _pack(q: np.ndarray) -> np.ndarray:
    q = q + _OFF
    return (q[:, 0] << 42) | (q[:, 1] << 21) | q[:, 2]


class _Hash:
    """Open-addressing (linear probing) int64 -> int32 table, built and queried in numpy."""

    def __init__(self, keys: np.ndarray):
        m = keys.size
        bits = max(4, int(np.ceil(np.log2(max(m, 1) * 3))))
        self.bits = bits
        self.size = 1 << bits
        self.keys = np.full(self.size, -1, dtype=np.int64)
        self.vals = np.full(self.size, -1, dtype=np.int32)
        pending = np.arange(m)
        slot = self._slot(keys)
        for _ in range(self.size):
            if pending.size == 0:
                break
            s = slot[pending]
            free = self.keys[s] == -1
            cand, cs = pending[free], s[free]
            # one winner per free slot: the first occurrence
            _, first = np.unique(cs, return_index=True)
            win, ws = cand[first], cs[first]
            self.keys[ws] = keys[win]
            self.vals[ws] = win.astype(np.int32)
            placed = np.zeros(m, dtype=bool)
            placed[win] = True
            pending = pending[~placed[pending]]
            slot[pending] = (slot[pending] + 1) & (self.size - 1)

    def _slot(self, keys: np.ndarray) -> np.ndarray:
        with np.errstate(over="ignore"):
            h = keys.astype(np.uint64) * _GOLD
        return (h >> np.uint64(64 - self.bits)).astype(np.int64)

    fill = -1

    def get(self, keys: np.ndarray) -> np.ndarray:
        """Values for ``keys`` (int64), ``fill`` where absent."""
        out = np.full(keys.size, self.fill, dtype=np.int32)
        slot = self._slot(keys)
        todo = np.arange(keys.size)
        for _ in range(64):
            k = self.keys[slot]
            hit = k == keys[todo]
            out[todo[hit]] = self.vals[slot[hit]]
            more = ~hit & (k != -1)
            todo, slot = todo[more], (slot[more] + 1) & (self.size - 1)
            if todo.size == 0:
                break
        return out


class _Grid:
    """Dense int32 voxel -> plane index array over a padded box (used when it is small)."""

    def __init__(self, q: np.ndarray, vals: np.ndarray, fill: int):
        self.lo = q.min(axis=0) - 1
        self.dims = (q.max(axis=0) - self.lo + 2).astype(np.int64)
        self.grid = np.full(int(np.prod(self.dims)), fill, dtype=np.int32)
        self.grid[self._flat(q - self.lo)] = vals

    def _flat(self, qq):
        return (qq[:, 0] * self.dims[1] + qq[:, 1]) * self.dims[2] + qq[:, 2]

    def get_q(self, q: np.ndarray) -> np.ndarray:
        """Values for voxel indices ``q`` (3, n) int32 (outside the box: the fill value)."""
        lo = self.lo.astype(np.int32)
        hi = (self.dims - 1).astype(np.int32)
        qx = np.clip(q[0] - lo[0], 0, hi[0])
        qy = np.clip(q[1] - lo[1], 0, hi[1])
        qz = np.clip(q[2] - lo[2], 0, hi[2])
        if self.grid.size < 2**31:
            idx = (qx * np.int32(self.dims[1]) + qy) * np.int32(self.dims[2]) + qz
        else:  # pragma: no cover - grids this large use the hash
            idx = (qx.astype(np.int64) * self.dims[1] + qy) * self.dims[2] + qz
        return self.grid[idx]


_DENSE_MAX = 1 << 25  # cells (128 MB of int32) below which a dense grid replaces the hash


@dataclass(frozen=True)
class VoxelPlanes:
    """Per-voxel planes of a target cloud behind a voxel index (dense grid or hash).

    Attributes
    ----------
    voxel : float
        Voxel edge (units of the cloud).
    centroid : (m, 3) float64
    normal : (m, 3) float64, unit
    planes : (m + 1, 4) float32
        ``(nx, ny, nz, n . centroid)`` per plane; row ``m`` is a sentinel whose offset is
        huge so any point mapped to it gets zero weight.
    """

    voxel: float
    centroid: np.ndarray
    normal: np.ndarray
    planes: np.ndarray
    index: object

    @classmethod
    def build(cls, xyz: np.ndarray, voxel: float, min_points: int = 4, max_curvature: float = 0.1) -> "VoxelPlanes":
        """Fit a plane to every voxel with ``min_points`` points whose surface variation
        ``l0 / (l0 + l1 + l2)`` (Pauly, Gross & Kobbelt 2002) is below ``max_curvature``."""
        xyz = np.asarray(xyz, dtype=np.float64)
        if voxel <= 0:
            raise InvalidInputError(f"voxel size must be > 0, got {voxel}", field="voxel_size")
        q = np.floor(xyz / voxel).astype(np.int64)
        if q.size and (np.abs(q).max() >= _OFF - 2):
            raise InvalidInputError("cloud too large for this voxel size", "use a larger voxel or a local origin")
        key = _pack(q)
        uk, inv, cnt = np.unique(key, return_inverse=True, return_counts=True)
        inv = inv.reshape(-1)
        m = uk.size
        _, mu, C = group_moments(xyz, inv, m)  # centroids and covariances of every voxel
        ok = cnt >= min_points
        w, V = np.linalg.eigh(C[ok])
        curv = w[:, 0] / np.maximum(w.sum(axis=1), 1e-300)
        good = curv < max_curvature
        idx = np.flatnonzero(ok)[good]
        normal = V[good, :, 0]
        uk, mu = uk[idx], mu[idx]
        k = idx.size
        # lend each plane to the empty voxels one step above and below along its dominant axis
        axis = np.argmax(np.abs(normal), axis=1)
        step = np.zeros((k, 3), dtype=np.int64)
        step[np.arange(k), axis] = 1
        qv = ((uk[:, None] >> np.array([42, 21, 0])) & ((1 << 21) - 1)) - _OFF
        extra_q = np.concatenate([qv + step, qv - step])
        extra_k = _pack(extra_q)
        extra_i = np.concatenate([np.arange(k), np.arange(k)])
        fresh = ~np.isin(extra_k, uk)
        extra_k, extra_i, extra_q = extra_k[fresh], extra_i[fresh], extra_q[fresh]
        extra_k, first = np.unique(extra_k, return_index=True)
        extra_i, extra_q = extra_i[first], extra_q[first]
        all_q = np.concatenate([qv, extra_q])
        vals = np.concatenate([np.arange(k), extra_i]).astype(np.int32)
        planes = np.zeros((k + 1, 4), dtype=np.float32)
        planes[:k, :3] = normal
        planes[:k, 3] = np.einsum("ij,ij->i", normal, mu)
        planes[k, 3] = 3.0e30
        if k == 0:
            index: object = _Grid(np.zeros((1, 3), dtype=np.int64), np.array([0], np.int32), 0)
        elif np.prod(all_q.max(axis=0) - all_q.min(axis=0) + 3) <= _DENSE_MAX:
            index = _Grid(all_q, vals, k)
        else:
            index = _Hash(np.concatenate([uk, extra_k]))
            index.fill = k
            index.vals = np.where(index.vals >= 0, vals[np.maximum(index.vals, 0)], k).astype(np.int32)
        return cls(float(voxel), mu, normal, planes, index)

    def lookup_q(self, q: np.ndarray) -> np.ndarray:
        """Plane row (sentinel ``m`` where none) for voxel indices ``q`` (3, n) int32."""
        if isinstance(self.index, _Grid):
            return self.index.get_q(q)
        key = ((q[0].astype(np.int64) + _OFF) << 42) | ((q[1].astype(np.int64) + _OFF) << 21) | (q[2] + _OFF)
        return self.index.get(key)

    def lookup(self, xyz: np.ndarray) -> np.ndarray:
        """Plane index of each point's voxel (n, 3) float, -1 where none."""
        q = np.floor(np.asarray(xyz, dtype=np.float64).T / self.voxel).astype(np.int32)
        r = self.lookup_q(q)
        return np.where(r == self.normal.shape[0], -1, r)


@dataclass(frozen=True)
class FastICPResult:
    """Transform (4x4, local frame), inlier share, point-to-plane RMS, iterations run."""

    transform: np.ndarray
    fitness: float
    rmse: float
    iterations: int
    converged: bool


def _normal_equations(ch: np.ndarray, T32: np.ndarray, vp: "VoxelPlanes"):
    """Point-to-plane normal equations of one source chunk (3, k) float32 under ``T32``.

    Returns (H (6, 6), g (6,), inliers, sum of squared residuals), Tukey-weighted."""
    y = T32[:3, :3] @ ch
    y += T32[:3, 3][:, None]
    q = y * np.float32(1.0 / vp.voxel)
    np.floor(q, out=q)
    row = vp.lookup_q(q.astype(np.int32))
    pl = vp.planes[row]
    nx, ny, nz = pl[:, 0], pl[:, 1], pl[:, 2]
    r = nx * y[0] + ny * y[1] + nz * y[2] - pl[:, 3]
    w = _tukey(r, np.float32(vp.voxel))
    inl = w > 0
    r = np.where(inl, r, np.float32(0.0))
    J = np.empty((6, ch.shape[1]), dtype=np.float32)
    J[0] = y[1] * nz - y[2] * ny
    J[1] = y[2] * nx - y[0] * nz
    J[2] = y[0] * ny - y[1] * nx
    J[3], J[4], J[5] = nx, ny, nz
    Jw = J * w
    H = (Jw @ J.T).astype(np.float64)
    g = (Jw @ r).astype(np.float64)
    return H, g, int(inl.sum()), float(np.dot(r, r))


def _small_motion(x: np.ndarray) -> np.ndarray:
    """4x4 transform of a small-motion update (rx, ry, rz, tx, ty, tz), R = Rz Ry Rx."""
    a, b, c = x[:3]
    ca, sa, cb, sb, cg, sg = np.cos(a), np.sin(a), np.cos(b), np.sin(b), np.cos(c), np.sin(c)
    Rx = np.array([[1, 0, 0], [0, ca, -sa], [0, sa, ca]])
    Ry = np.array([[cb, 0, sb], [0, 1, 0], [-sb, 0, cb]])
    Rz = np.array([[cg, -sg, 0], [sg, cg, 0], [0, 0, 1]])
    dT = np.eye(4)
    dT[:3, :3] = Rz @ Ry @ Rx
    dT[:3, 3] = x[3:]
    return dT


def _tukey(r: np.ndarray, c: float) -> np.ndarray:
    u = np.minimum(np.abs(r), c) / c
    u = 1.0 - u * u
    return u * u


def point_to_plane_voxel(source: np.ndarray, target: np.ndarray, voxel: float, init: np.ndarray | None = None,
                         iterations: int = 30, levels: tuple[float, ...] = (4.0, 2.0, 1.0),
                         planes: list[VoxelPlanes] | None = None, tolerance: float = 1e-7,
                         threads: int = 2) -> FastICPResult:
    """Point-to-plane ICP of ``source`` onto ``target`` with voxel-hash correspondences.

    Parameters
    ----------
    source, target : (n, 3), (m, 3) float
        Local coordinates (subtract an origin first: keys are 21-bit voxel indices).
    voxel : float
        Finest plane voxel (units of the clouds), about 2-4 times the point spacing.
    init : (4, 4) float, optional
    iterations : int
        Total iterations, split evenly over ``levels``.
    levels : tuple of float
        Voxel multipliers from coarse to fine; each level's residuals are Tukey-weighted
        with a cut-off of one level voxel.
    planes : list of VoxelPlanes, optional
        Prebuilt maps for ``levels`` (to reuse a target).
    tolerance : float
        Stop a level when the update is below this (radians and units/voxel).
    threads : int
        Source chunks processed in parallel threads (numpy releases the GIL).

    Notes
    -----
    The loop runs in float32 on local coordinates (a float32 step of 4 micrometres at 50 m
    from the origin); the 6x6 normal equations are summed in float64.
    """
    src = np.asarray(source, dtype=np.float64)
    T = np.eye(4) if init is None else np.asarray(init, dtype=np.float64).copy()
    if planes is None:
        planes = [VoxelPlanes.build(target, voxel * f) for f in levels]
    try:  # the hot loop is memory bound; BLAS threads only spin on a shared machine
        from threadpoolctl import threadpool_limits

        limiter = threadpool_limits(1)
    except ImportError:  # pragma: no cover
        limiter = None
    chunks = _source_chunks(src, threads)
    pool = None
    if len(chunks) > 1:
        from concurrent.futures import ThreadPoolExecutor

        pool = ThreadPoolExecutor(len(chunks))
    try:
        return _iterate_levels(planes, chunks, pool, T, src.shape[0], iterations, tolerance)
    finally:
        if pool is not None:
            pool.shutdown()
        if limiter is not None:
            limiter.unregister() if hasattr(limiter, "unregister") else limiter.restore_original_limits()


def _source_chunks(src: np.ndarray, threads: int) -> list[np.ndarray]:
    """The source as float32 (3, n) column blocks, one per thread (at most ``threads``, and at
    least 50,000 points each)."""
    src32 = np.ascontiguousarray(src.T, dtype=np.float32)
    n_src = src.shape[0]
    n_chunks = max(1, min(int(threads), n_src // 50_000))
    bounds = np.linspace(0, n_src, n_chunks + 1).astype(int)
    return [src32[:, a:b] for a, b in zip(bounds[:-1], bounds[1:])]


def _iterate_levels(planes: list[VoxelPlanes], chunks, pool, T: np.ndarray, n_src: int, iterations: int,
                    tolerance: float) -> FastICPResult:
    """The Gauss-Newton iterations over the plane maps, coarse to fine: ``iterations`` split
    evenly over the levels (the last takes the rest); a level stops early when the update falls
    below ``tolerance``; the run fails with fewer than 6 inliers or a singular system.
    Converged: the last level's last step was small (1e-4 rad and 1e-3 of its voxel)."""
    per = max(1, iterations // len(planes))
    it_total = 0
    conv = False
    fit = rmse = 0.0
    for li, vp in enumerate(planes):
        n_it = per if li < len(planes) - 1 else iterations - it_total
        c = vp.voxel
        for _ in range(n_it):
            it_total += 1
            H, g, n_inl, sse = _summed_equations(chunks, T.astype(np.float32), vp, pool)
            fit = n_inl / max(n_src, 1)
            if n_inl < 6:
                return FastICPResult(T, fit, float("nan"), it_total, False)
            rmse = float(np.sqrt(sse / n_inl))
            try:
                x = -np.linalg.solve(H, g)
            except np.linalg.LinAlgError:
                return FastICPResult(T, fit, rmse, it_total, False)
            T = _small_motion(x) @ T
            step_small = np.abs(x[:3]).max() < 1e-4 and np.abs(x[3:]).max() < 1e-3 * c
            conv = li == len(planes) - 1 and step_small
            if np.abs(x[:3]).max() < tolerance and np.abs(x[3:]).max() < tolerance * c:
                break
    return FastICPResult(T, fit, rmse, it_total, bool(conv))


def _summed_equations(chunks, T32: np.ndarray, vp: VoxelPlanes, pool):
    """:func:`_normal_equations` of every source chunk (in ``pool``'s threads when given), summed:
    ``(H, g, inliers, sum of squared residuals)``."""
    if pool is None:
        parts = [_normal_equations(ch, T32, vp) for ch in chunks]
    else:
        parts = list(pool.map(lambda ch: _normal_equations(ch, T32, vp), chunks))
    H = sum(p[0] for p in parts)
    g = sum(p[1] for p in parts)
    n_inl = sum(p[2] for p in parts)
    sse = sum(p[3] for p in parts)
    return H, g, n_inl, sse
