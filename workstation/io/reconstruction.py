"""cameras.json: oriented cameras and images (a :class:`Reconstruction` without points) on disk.

Layout (one JSON object; pixel centres at integer coordinates, ``x_cam = R @ X_world + t``)::

    {"convention": "...",
     "crs": "EPSG:32632" or null,
     "cameras": {"1": {"width", "height", "fx", "fy", "cx", "cy", "skew", "dist", "model"}},
     "images": {"1": {"name", "camera_id", "R": 3×3, "t": 3, "path"}},
     "meta": {scalar values only}}

``dist`` is OpenCV's (k1, k2, p1, p2, k3). An image's ``path`` (or, without it, its ``name``)
is read relative to the JSON file's folder and must stay inside it.

Examples
--------
>>> import tempfile, pathlib
>>> import numpy as np
>>> from workstation.core.products import Camera, Image, Pose, Reconstruction
>>> folder = pathlib.Path(tempfile.mkdtemp())
>>> rec = Reconstruction({1: Camera(64, 48, 50.0, 50.0, 31.5, 23.5)},
...                      {1: Image("a.png", 1, Pose(np.eye(3), np.zeros(3)), "a.png")})
>>> p = write_reconstruction_json(rec, folder / "cameras.json")
>>> back = read_reconstruction_json(p)
>>> back.cameras[1].fx, back.images[1].name, pathlib.Path(back.images[1].path) == folder / "a.png"
(50.0, 'a.png', True)
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from workstation.core.errors import InvalidInputError
from workstation.core.products import Camera, Image, Pose, Reconstruction

from .atomic import atomic_path
from .paths import resolve_inside
from .textfile import read_text

CONVENTION = "x_cam = R @ X_world + t; pixel centres at integer coordinates; dist = OpenCV k1 k2 p1 p2 k3"


def _camera_to_dict(c: Camera) -> dict:
    return {"width": c.width, "height": c.height, "fx": c.fx, "fy": c.fy, "cx": c.cx, "cy": c.cy,
            "skew": c.skew, "dist": list(c.dist), "model": c.model}


def _camera_from_dict(c: dict) -> Camera:
    """A camera entry of cameras.json; ``fy`` defaults to ``fx``, missing distortion terms to 0."""
    return Camera(int(c["width"]), int(c["height"]), float(c["fx"]), float(c.get("fy", c["fx"])),
                  float(c["cx"]), float(c["cy"]), float(c.get("skew", 0.0)),
                  tuple(float(d) for d in (list(c.get("dist", [])) + [0.0] * 5)[:5]), c.get("model", "OPENCV"))


def write_reconstruction_json(rec: Reconstruction, path, overwrite: bool = False) -> Path:
    """Write cameras and oriented images as JSON (pixel centres at integers, x_cam = R X + t)."""
    doc = {
        "convention": CONVENTION,
        "crs": rec.crs,
        "cameras": {str(k): _camera_to_dict(c) for k, c in rec.cameras.items()},
        "images": {str(k): {"name": im.name, "camera_id": im.camera_id, "R": np.asarray(im.pose.R).tolist(),
                            "t": np.asarray(im.pose.t).tolist(), "path": im.path} for k, im in rec.images.items()},
        "meta": {k: v for k, v in dict(rec.meta).items() if isinstance(v, (int, float, str, bool))},
    }
    with atomic_path(path, overwrite=overwrite) as tmp:
        tmp.write_text(json.dumps(doc, indent=1))
    return Path(path)


def read_reconstruction_json(path) -> Reconstruction:
    """Read a cameras JSON written by :func:`write_reconstruction_json`; image paths become
    paths inside the JSON file's folder."""
    path = Path(path)
    try:
        doc = json.loads(read_text(path))
        cams = {int(k): _camera_from_dict(c) for k, c in doc["cameras"].items()}
        imgs = {}
        for k, im in doc["images"].items():
            p = str(resolve_inside(im.get("path") or im["name"], path.parent, source=path, field=f"images.{k}.path"))
            imgs[int(k)] = Image(im["name"], int(im["camera_id"]), Pose(np.array(im["R"], float), np.array(im["t"], float)), p)
    except (KeyError, TypeError, ValueError, json.JSONDecodeError) as e:
        raise InvalidInputError(f"not a cameras JSON ({e})", "see write_reconstruction_json for the layout", path=path) from None
    return Reconstruction(cams, imgs, crs=doc.get("crs"), meta=doc.get("meta", {}))


__all__ = ["CONVENTION", "read_reconstruction_json", "write_reconstruction_json"]
