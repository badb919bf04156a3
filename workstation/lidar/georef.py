r"""The direct georeferencing chain of a laser scanner on a moving platform.

A return measured as a range :math:`r` along the beam is carried through five frames, each a
homogeneous 4x4 transform (Baltsavias 1999, eq. 1; Glennie 2007, eq. 1; Habib et al. 2010):

.. math::

    \begin{bmatrix} X_m \\ 1 \end{bmatrix} =
    T^m_n(\mathbf p_m)\; T^n_b(\varphi, \theta, \psi)\; T^b_s(\mathbf R_{bs}, \mathbf a_b)\;
    T^s_l(\text{mirror})\; \begin{bmatrix} 0 \\ 0 \\ r \\ 1 \end{bmatrix}

i.e. :math:`X_m = \mathbf p_m + R^m_n R^n_b (R^b_s\, r\, \mathbf d_s + \mathbf a_b)` with

* **laser frame l**: the pulse leaves along +z; the point is (0, 0, r).
* **scanner frame s** (x forward, y right, z down): :math:`T^s_l` is the mirror deflection,
  so :math:`\mathbf d_s = R^s_l \mathbf e_z` is the beam direction; an across-track angle
  :math:`\alpha` (positive to the right) gives :math:`\mathbf d_s = (0, \sin\alpha, \cos\alpha)`.
* **IMU body frame b** (x forward, y right, z down): :math:`R^b_s` is the boresight
  misalignment (three small angles), :math:`\mathbf a_b` the lever arm from the IMU origin
  to the scanner origin, in metres in the body frame.
* **local level frame n** (north, east, down): :math:`R^n_b = R_z(\psi) R_y(\theta) R_x(\varphi)`
  from the IMU roll, pitch and yaw (heading, clockwise from north): the aerospace z-y-x
  sequence.
* **map frame m** (easting, northing, up; a projected grid): :math:`R^m_n` swaps north/east
  and flips down to up; :math:`\mathbf p_m` is the IMU origin from the GNSS/INS trajectory.
  Meridian convergence and the grid scale factor are neglected (under 0.1 % over a project
  area of a few km), as in most simulators.

Every transform has a closed-form inverse (:func:`invert`), so the chain runs backwards
from a map point to the range and beam direction (:meth:`GeorefChain.inverse`).

References
----------
E. P. Baltsavias (1999). Airborne laser scanning: basic relations and formulas. ISPRS J.
Photogramm. Remote Sens. 54(2-3):199-214.
C. Glennie (2007). Rigorous 3D error analysis of kinematic scanning LIDAR systems. Journal of
Applied Geodesy 1(3):147-157.
A. Habib, K. I. Bang, A. P. Kersting, J. Chow (2010). Alternative methodologies for LiDAR
system calibration. Remote Sensing 2(3):874-907.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workstation.core.errors import InvalidInputError

#: Rotation from the local level NED frame to the map ENU frame.
R_MAP_FROM_NED = np.array([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]])


def rot_x(a) -> np.ndarray:
    """Rotation matrices (..., 3, 3) about x by angles ``a`` (radians, right-handed)."""
    a = np.asarray(a, float)
    c, s = np.cos(a), np.sin(a)
    o, z = np.ones_like(a), np.zeros_like(a)
    return np.stack([np.stack([o, z, z], -1), np.stack([z, c, -s], -1), np.stack([z, s, c], -1)], -2)


def rot_y(a) -> np.ndarray:
    """Rotation matrices (..., 3, 3) about y by angles ``a`` (radians)."""
    a = np.asarray(a, float)
    c, s = np.cos(a), np.sin(a)
    o, z = np.ones_like(a), np.zeros_like(a)
    return np.stack([np.stack([c, z, s], -1), np.stack([z, o, z], -1), np.stack([-s, z, c], -1)], -2)


def rot_z(a) -> np.ndarray:
    """Rotation matrices (..., 3, 3) about z by angles ``a`` (radians)."""
    a = np.asarray(a, float)
    c, s = np.cos(a), np.sin(a)
    o, z = np.ones_like(a), np.zeros_like(a)
    return np.stack([np.stack([c, -s, z], -1), np.stack([s, c, z], -1), np.stack([z, z, o], -1)], -2)


def rpy_matrix(roll, pitch, yaw) -> np.ndarray:
    r"""Body-to-local-level rotation :math:`R_z(\psi) R_y(\theta) R_x(\varphi)`, shape (..., 3, 3).

    Written out element by element (no matrix products) so it is cheap for millions of pulses.
    """
    roll, pitch, yaw = np.broadcast_arrays(*(np.asarray(a, float) for a in (roll, pitch, yaw)))
    cr, sr = np.cos(roll), np.sin(roll)
    cp, sp = np.cos(pitch), np.sin(pitch)
    cy, sy = np.cos(yaw), np.sin(yaw)
    R = np.empty(roll.shape + (3, 3))
    R[..., 0, 0] = cy * cp
    R[..., 0, 1] = cy * sp * sr - sy * cr
    R[..., 0, 2] = cy * sp * cr + sy * sr
    R[..., 1, 0] = sy * cp
    R[..., 1, 1] = sy * sp * sr + cy * cr
    R[..., 1, 2] = sy * sp * cr - cy * sr
    R[..., 2, 0] = -sp
    R[..., 2, 1] = cp * sr
    R[..., 2, 2] = cp * cr
    return R


def rpy_trig(rpy: np.ndarray, precise: bool = True) -> tuple:
    """(cos, sin) of roll, pitch, yaw columns of (n, 3) angles, to share between rotations.

    With ``precise=False`` they are computed in float32 (about 15 times faster in numpy) after
    wrapping the yaw to [-pi, pi): errors below 1e-7 rad, 0.05 mm at 500 m range.
    """
    rpy = np.asarray(rpy, float)
    if precise:
        return tuple((np.cos(rpy[:, i]), np.sin(rpy[:, i])) for i in range(3))
    out = []
    for i in range(3):
        a = rpy[:, i] if i < 2 else np.remainder(rpy[:, i] + np.pi, 2 * np.pi) - np.pi
        a = a.astype(np.float32)
        out.append((np.cos(a), np.sin(a)))
    return tuple(out)


def rotate_rpy(rpy: np.ndarray, v: np.ndarray, inverse: bool = False, trig: tuple | None = None) -> np.ndarray:
    r"""Apply :math:`R^n_b = R_z R_y R_x` (or its transpose) of per-row angles ``rpy`` (n, 3)
    to vectors ``v`` (n, 3), as three plane rotations (no 3x3 matrices are formed).

    ``trig`` may hold :func:`rpy_trig` of ``rpy`` computed once for several rotations."""
    (cr, sr), (cp, sp), (cy, sy) = trig if trig is not None else rpy_trig(rpy)
    v = np.asarray(v)
    x, y, z = (v[:, i] for i in range(3))
    if not inverse:
        y, z = cr * y - sr * z, sr * y + cr * z
        x, z = cp * x + sp * z, -sp * x + cp * z
        x, y = cy * x - sy * y, sy * x + cy * y
    else:
        x, y = cy * x + sy * y, -sy * x + cy * y
        x, z = cp * x - sp * z, sp * x + cp * z
        y, z = cr * y + sr * z, -sr * y + cr * z
    out = np.empty((x.shape[0], 3), np.result_type(x, y, z))
    out[:, 0], out[:, 1], out[:, 2] = x, y, z
    return out


def matrix_to_rpy(R: np.ndarray) -> np.ndarray:
    """Inverse of :func:`rpy_matrix`: (..., 3) roll, pitch, yaw in radians (|pitch| < 90 deg)."""
    R = np.asarray(R, float)
    roll = np.arctan2(R[..., 2, 1], R[..., 2, 2])
    pitch = -np.arcsin(np.clip(R[..., 2, 0], -1.0, 1.0))
    yaw = np.arctan2(R[..., 1, 0], R[..., 0, 0])
    return np.stack([roll, pitch, yaw], -1)


def homogeneous(R: np.ndarray, t) -> np.ndarray:
    """4x4 (or (..., 4, 4)) transform from rotation (..., 3, 3) and translation (..., 3)."""
    R = np.asarray(R, float)
    t = np.broadcast_to(np.asarray(t, float), R.shape[:-2] + (3,))
    T = np.zeros(R.shape[:-2] + (4, 4))
    T[..., :3, :3] = R
    T[..., :3, 3] = t
    T[..., 3, 3] = 1.0
    return T


def invert(T: np.ndarray) -> np.ndarray:
    """Inverse of rigid transforms (..., 4, 4): [R^T, -R^T t]."""
    T = np.asarray(T, float)
    Rt = np.swapaxes(T[..., :3, :3], -1, -2)
    return homogeneous(Rt, -np.einsum("...ij,...j->...i", Rt, T[..., :3, 3]))


def beam_direction(across, along=0.0, dtype=np.float64) -> np.ndarray:
    r"""Scanner-frame beam directions (..., 3) for across-track and along-track deflections.

    :math:`\mathbf d_s = R_y(\beta) R_x(-\alpha) \mathbf e_z =
    (\sin\beta\cos\alpha,\ \sin\alpha,\ \cos\beta\cos\alpha)` with the across-track angle
    :math:`\alpha` (radians, positive to the right) and the along-track angle :math:`\beta`
    (positive forward). ``dtype`` float32 is faster where rays are float32 anyway.
    """
    a, b = np.broadcast_arrays(np.asarray(across, dtype), np.asarray(along, dtype))
    ca = np.cos(a)
    out = np.empty(a.shape + (3,), dtype)
    if np.any(b):
        out[..., 0] = np.sin(b) * ca
        out[..., 2] = np.cos(b) * ca
    else:
        out[..., 0] = 0.0
        out[..., 2] = ca
    out[..., 1] = np.sin(a)
    return out


@dataclass(frozen=True)
class GeorefChain:
    """Mounting of the scanner on the IMU: lever arm and boresight angles.

    Attributes
    ----------
    lever_arm : (3,) float
        Scanner origin in the IMU body frame (x forward, y right, z down), metres.
    boresight : (3,) float
        Boresight roll, pitch, yaw of the scanner frame in the body frame, radians
        (:math:`R^b_s = R_z R_y R_x`).
    """

    lever_arm: tuple = (0.0, 0.0, 0.0)
    boresight: tuple = (0.0, 0.0, 0.0)

    def __post_init__(self):
        for name in ("lever_arm", "boresight"):
            v = np.asarray(getattr(self, name), float)
            if v.shape != (3,) or not np.all(np.isfinite(v)):
                raise InvalidInputError(f"{name} must be 3 finite numbers, got {getattr(self, name)}", field=name)
            object.__setattr__(self, name, tuple(float(x) for x in v))

    @property
    def R_bs(self) -> np.ndarray:
        """(3, 3) boresight rotation scanner -> body."""
        return rpy_matrix(*self.boresight)

    def T_bs(self) -> np.ndarray:
        """(4, 4) scanner -> body transform (boresight and lever arm)."""
        return homogeneous(self.R_bs, self.lever_arm)

    @staticmethod
    def T_nb(rpy) -> np.ndarray:
        """(..., 4, 4) body -> local level (NED) rotation from (..., 3) roll, pitch, yaw (rad)."""
        rpy = np.asarray(rpy, float)
        return homogeneous(rpy_matrix(rpy[..., 0], rpy[..., 1], rpy[..., 2]), np.zeros(rpy.shape[:-1] + (3,)))

    @staticmethod
    def T_mn(position) -> np.ndarray:
        """(..., 4, 4) local level (NED) -> map (ENU) at the IMU position (..., 3), metres."""
        p = np.asarray(position, float)
        return homogeneous(np.broadcast_to(R_MAP_FROM_NED, p.shape[:-1] + (3, 3)), p)

    def matrix(self, position, rpy) -> np.ndarray:
        """Full (..., 4, 4) scanner -> map transform :math:`T^m_n T^n_b T^b_s`."""
        return self.T_mn(position) @ self.T_nb(rpy) @ self.T_bs()

    def forward(self, rng, d_s, position, rpy, trig: tuple | None = None) -> np.ndarray:
        """Map coordinates (n, 3) of ranges ``rng`` (n,) along scanner-frame beams ``d_s`` (n, 3)
        measured from IMU positions (n, 3) with attitudes ``rpy`` (n, 3) (radians).

        Vectorised form of the chain: :math:`\\mathbf p + R^m_n R^n_b (R^b_s r \\mathbf d_s + \\mathbf a)`.
        ``trig`` may hold :func:`rpy_trig` of ``rpy``.
        """
        rpy = np.asarray(rpy, float)
        v_b = np.asarray(rng, float)[:, None] * np.asarray(d_s, float)
        if any(self.boresight):
            v_b = v_b @ self.R_bs.T
        v_b += np.asarray(self.lever_arm)
        v_n = rotate_rpy(rpy, v_b, trig=trig)
        out = np.asarray(position, float).copy()
        out[:, 0] += v_n[:, 1]  # R^m_n: east = NED y, north = NED x, up = -NED z
        out[:, 1] += v_n[:, 0]
        out[:, 2] -= v_n[:, 2]
        return out

    def inverse(self, points, position, rpy) -> tuple[np.ndarray, np.ndarray]:
        """Ranges (n,) and unit scanner-frame beam directions (n, 3) of map points (n, 3)."""
        rpy = np.asarray(rpy, float)
        v_n = (np.asarray(points, float) - np.asarray(position, float)) @ R_MAP_FROM_NED  # R^T applied row-wise
        v_b = rotate_rpy(rpy, v_n, inverse=True) - np.asarray(self.lever_arm)
        v_s = v_b @ self.R_bs
        r = np.linalg.norm(v_s, axis=1)
        return r, v_s / np.where(r > 0, r, 1.0)[:, None]
