"""Colour transfer from a cloud to mesh vertices (inverse-distance weighting of k neighbours)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.color import rgb_to_unit
from workstation.core.errors import InvalidInputError
from workstation.core.products import Mesh

from .steps import StepRecord, Timer


@dataclass(frozen=True)
class ColorTransferParams:
    """Colour transfer parameters.

    Attributes
    ----------
    k : int
        Nearest cloud points averaged per vertex (count).
    power : float
        Inverse-distance weight exponent (dimensionless; weights 1 / d**power).
    """

    k: int = 4
    power: float = 2.0

    def __post_init__(self):
        if self.k < 1:
            raise InvalidInputError("k must be >= 1", field="k")


def transfer_colors(mesh: Mesh, cloud: Cloud, params: ColorTransferParams = ColorTransferParams()) -> tuple[Mesh, StepRecord]:
    """Give every mesh vertex the weighted colour of its k nearest cloud points.

    Parameters
    ----------
    mesh : Mesh
    cloud : Cloud
        Must carry ``rgb`` (n, 3).

    Returns
    -------
    (Mesh, StepRecord)
        The mesh with ``rgb`` (n_vertices, 3) uint8; the record's summary has the median and
        95th percentile vertex-to-nearest-point distance (CRS units).
    """
    from scipy.spatial import cKDTree

    if "rgb" not in cloud.attrs:
        raise InvalidInputError("the cloud has no colours to transfer", "colourise it first", field="rgb")
    with Timer() as t:
        k = min(int(params.k), cloud.n)
        d, idx = cKDTree(cloud.xyz).query(mesh.vertices, k=k)
        d = d.reshape(len(mesh.vertices), k)
        idx = idx.reshape(len(mesh.vertices), k)
        w = 1.0 / np.maximum(d, 1e-12) ** params.power
        w /= w.sum(axis=1, keepdims=True)
        col = rgb_to_unit(np.asarray(cloud.attrs["rgb"]))
        rgb = np.einsum("vk,vkc->vc", w, col[idx])
        attrs = dict(mesh.vertex_attrs)
        attrs["rgb"] = np.round(np.clip(rgb, 0, 1) * 255).astype(np.uint8)
        out = Mesh(mesh.vertices, mesh.faces, attrs, mesh.face_attrs, crs=mesh.crs, meta=mesh.meta)
    rec = StepRecord("color_transfer", {"k": k, "power": params.power}, t.seconds,
                     {"distance_median": float(np.median(d[:, 0])), "distance_p95": float(np.percentile(d[:, 0], 95))})
    return out, rec
