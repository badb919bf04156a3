r"""Weighted least squares with a rank test and robust (MAD) rejection of observations.

Each step solves the normal equations :math:`N\,\delta = A^\top W l`, :math:`N = A^\top W A`,
with :math:`W = \mathrm{diag}(1/\sigma_i^2)` from the a-priori standard deviations of the
observations. The unknowns are first scaled to a common unit, metres of displacement at the
data (an angle times the mean range, a range offset or shift as it is), so that the
eigen-decomposition :math:`N = V \Lambda V^\top` compares like with like: an eigen-direction
:math:`v_k` is estimated with the a-priori standard deviation :math:`1/\sqrt{\lambda_k}`
metres. A direction whose standard deviation exceeds the noise of one point is **not
determined** by the data (e.g. the heading boresight from flat ground only, where every
patch normal is vertical): it is left out of the solution (the pseudo-inverse on the
determined subspace, so those combinations keep their nominal value) and reported, rather
than estimated from noise (the datum/rank-defect analysis of geodetic networks, Koch 1999,
ch. 3.4; Skaloud & Lichti 2006 discuss which boresight angles flat surfaces recover). When the
residuals show a standard deviation of unit weight :math:`\hat\sigma_0 > 1` (robustly:
1.4826 MAD of the standardised residuals, so that gross errors do not inflate it), the test
is repeated with the a-posteriori standard deviations :math:`\hat\sigma_0/\sqrt{\lambda_k}`.

Outliers: after each solution the standardised residuals :math:`r_i = v_i/\sigma_i` get a
robust scale :math:`\hat\sigma = 1.4826\,\mathrm{MAD}(r)`; observations with
:math:`|r_i - \mathrm{med}(r)| > 3.5\,\hat\sigma` are rejected for the next iteration
(the modified z-score of Iglewicz & Hoaglin 1993), recomputed from all observations each time.

References
----------
K.-R. Koch (1999). Parameter Estimation and Hypothesis Testing in Linear Models. Springer.
J. Skaloud, D. Lichti (2006). Rigorous approach to bore-sight self-calibration in airborne
laser scanning. ISPRS J. Photogramm. Remote Sens. 61(1):47-59.
B. Iglewicz, D. C. Hoaglin (1993). How to Detect and Handle Outliers. ASQC Quality Press.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: Modified z-score beyond which an observation is an outlier (Iglewicz & Hoaglin 1993).
MAD_LIMIT = 3.5


@dataclass(frozen=True)
class Step:
    """One weighted least-squares solution.

    Attributes
    ----------
    delta : (u,) float
        Corrections to the unknowns in their own units.
    cov : (u, u) float
        A-posteriori covariance (own units squared), :math:`\\hat\\sigma_0^2 N^+`.
    sigma0 : float
        A-posteriori standard deviation of unit weight.
    determined : (u,) bool
        Unknowns lying (to 99 % of their length) in the determined subspace.
    null_directions : list of (u,) float
        Unit eigen-directions (scaled unknowns) left out as not determined.
    residuals : (m,) float
        :math:`A\\delta - l` for every observation (metres).
    """

    delta: np.ndarray
    cov: np.ndarray
    sigma0: float
    determined: np.ndarray
    null_directions: list
    residuals: np.ndarray


def solve(A: np.ndarray, l: np.ndarray, sigma: np.ndarray, scale: np.ndarray, tol_m: float,
          inliers: np.ndarray | None = None) -> Step:
    """Minimise :math:`\\sum w_i (A_i\\delta - l_i)^2` over ``inliers`` with the rank test.

    Parameters
    ----------
    A : (m, u) float
        Design matrix (metres per unit of each unknown).
    l : (m,) float
        Observations minus their computed values (metres).
    sigma : (m,) float
        A-priori standard deviations of the observations (metres).
    scale : (u,) float
        Metres of displacement per unit of each unknown (module docs).
    tol_m : float
        Largest a-priori standard deviation (metres) of a determined direction.
    inliers : (m,) bool, optional

    Examples
    --------
    A shift observed directly and a second unknown that no observation sees:

    >>> A = np.column_stack([np.ones(4), np.zeros(4)])
    >>> step = solve(A, np.array([0.1, 0.1, 0.12, 0.08]), np.full(4, 0.01), np.ones(2), tol_m=0.05)
    >>> round(float(step.delta[0]), 3), step.determined.tolist(), len(step.null_directions)
    (0.1, [True, False], 1)
    """
    m, u = A.shape
    use = np.ones(m, bool) if inliers is None else inliers
    As = A[use] / scale  # unknowns in metres
    w = 1.0 / sigma[use] ** 2
    N = As.T @ (As * w[:, None])
    lam, V = np.linalg.eigh(N)
    b = As.T @ (w * l[use])
    s0 = 1.0
    for _ in range(2):  # a-priori, then again with the robust a-posteriori sigma0 when larger
        keep = lam > s0 ** 2 / tol_m ** 2
        Vk = V[:, keep]
        Ninv = (Vk / lam[keep]) @ Vk.T
        delta = (Ninv @ b) / scale
        res = A @ delta - l
        dof = max(int(use.sum()) - int(keep.sum()), 1)
        s0 = float(np.sqrt(np.sum(w * res[use] ** 2) / dof))
        r = res[use] / sigma[use]
        s0_robust = 1.4826 * float(np.median(np.abs(r - np.median(r)))) if r.size else 0.0
        if s0_robust <= 1.0 or np.all(lam[keep] > s0_robust ** 2 / tol_m ** 2):
            break
        s0 = s0_robust
    cov = s0 ** 2 * Ninv / np.outer(scale, scale)
    inside = np.sum(Vk ** 2, axis=1) if keep.any() else np.zeros(u)
    return Step(delta, cov, s0, inside >= 0.99 ** 2, [V[:, k] for k in np.flatnonzero(~keep)], res)


def robust_inliers(residuals: np.ndarray, sigma: np.ndarray) -> np.ndarray:
    """Observations whose standardised residual is within :data:`MAD_LIMIT` robust sigmas."""
    r = residuals / sigma
    med = np.median(r)
    mad = 1.4826 * np.median(np.abs(r - med))
    if mad == 0:
        return np.ones(r.size, bool)
    return np.abs(r - med) <= MAD_LIMIT * mad


def correlations(cov: np.ndarray) -> np.ndarray:
    """Correlation matrix of a covariance (zeros where a variance is zero)."""
    s = np.sqrt(np.clip(np.diag(cov), 0, None))
    d = np.outer(s, s)
    return np.where(d > 0, cov / np.where(d > 0, d, 1.0), 0.0)
