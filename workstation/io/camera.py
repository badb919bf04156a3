"""CAMERA.json: a calibrated camera on disk.

Schema (JSON object; lengths in pixels, pixel centres at integer coordinates as in OpenCV):

=============  ===========================================================================
key            meaning
=============  ===========================================================================
``model``      "OPENCV" (fx, fy, cx, cy, k1, k2, p1, p2[, k3]), "PINHOLE" (no distortion)
               or "SIMPLE_PINHOLE"; required
``width``      image width, pixels; required
``height``     image height, pixels; required
``fx``, ``fy`` focal lengths, pixels; required
``cx``, ``cy`` principal point, pixels; required
``skew``       skew term K[0, 1], pixels (default 0)
``dist``       OpenCV order [k1, k2, p1, p2, k3] (default zeros)
``rms``        reprojection RMS of the calibration, pixels (null when unknown)
``method``     "zhang", "dlt", "sfm", ... (optional)
``std``        standard deviations of the parameters by name (optional)
``per_image``  [{"name", "rms_px", "n_points"}] (optional)
``dropped``    [{"name", "reason"}] images not used (optional)
``extrinsics`` [{"name", "R", "t", "centre", "omega_deg", "phi_deg", "kappa_deg"}] (optional)
=============  ===========================================================================

Any other key is kept as free-form metadata.

Examples
--------
>>> import tempfile, pathlib
>>> from workstation.core.products import Camera
>>> p = pathlib.Path(tempfile.mkdtemp()) / "cam.json"
>>> write_camera(Camera(640, 480, 500.0, 501.0, 320.0, 240.0, dist=(-0.1, 0.01, 0, 0, 0)), p, rms=0.2)
>>> read_camera(p).fy
501.0
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from workstation.core.errors import InvalidInputError
from workstation.core.jsonutil import dumps
from workstation.core.products import Camera

from .textfile import read_text
from .atomic import atomic_path

REQUIRED = ("model", "width", "height", "fx", "fy", "cx", "cy")


def camera_to_dict(camera: Camera, rms: float | None = None) -> dict:
    """The required and standard keys of CAMERA.json for ``camera``."""
    d = {
        "model": camera.model,
        "width": int(camera.width),
        "height": int(camera.height),
        "fx": float(camera.fx),
        "fy": float(camera.fy),
        "cx": float(camera.cx),
        "cy": float(camera.cy),
        "skew": float(camera.skew),
        "dist": [float(x) for x in (list(camera.dist) + [0.0] * 5)[:5]],
        "rms": None if rms is None else float(rms),
    }
    return d


def camera_from_dict(d: dict, path=None) -> Camera:
    """Build a :class:`Camera` from a CAMERA.json document (validated)."""
    if not isinstance(d, dict):
        raise InvalidInputError("CAMERA.json must hold a JSON object", path=path)
    for k in REQUIRED:
        if k not in d:
            raise InvalidInputError(f"missing key '{k}'", "see workstation.io.camera for the schema", path=path, field=k)
    dist = list(d.get("dist") or [0.0] * 5)
    if len(dist) > 5 or any(not isinstance(v, (int, float)) for v in dist):
        raise InvalidInputError("dist must hold up to 5 numbers k1, k2, p1, p2, k3", path=path, field="dist")
    dist = [float(v) for v in dist] + [0.0] * (5 - len(dist))
    try:
        cam = Camera(
            width=int(d["width"]),
            height=int(d["height"]),
            fx=float(d["fx"]),
            fy=float(d["fy"]),
            cx=float(d["cx"]),
            cy=float(d["cy"]),
            skew=float(d.get("skew") or 0.0),
            dist=tuple(dist),
            model=str(d["model"]),
        )
    except (TypeError, ValueError, OverflowError):
        raise InvalidInputError("non-numeric or infinite camera parameter", "see workstation.io.camera for the schema",
                                path=path) from None
    if cam.width <= 0 or cam.height <= 0 or not (cam.fx > 0 and cam.fy > 0):
        raise InvalidInputError("width, height, fx and fy must be positive", path=path)
    if not all(np.isfinite([cam.fx, cam.fy, cam.cx, cam.cy, cam.skew, *cam.dist])):
        raise InvalidInputError("non-finite camera parameter", path=path)
    return cam


def read_camera(path) -> Camera:
    """Read CAMERA.json into a :class:`Camera`."""
    p = Path(path)
    if not p.is_file():
        raise InvalidInputError("camera file not found", path=p)
    try:
        d = json.loads(read_text(p))
    except json.JSONDecodeError as e:
        raise InvalidInputError(f"not valid JSON: {e.msg} at line {e.lineno}", "see workstation.io.camera for the schema",
                                path=p) from None
    except RecursionError:
        raise InvalidInputError("JSON nested too deeply", "see workstation.io.camera for the schema", path=p) from None
    return camera_from_dict(d, path=p)


def write_camera(camera_or_doc, path, overwrite: bool = False, rms: float | None = None, inputs=()) -> None:
    """Write CAMERA.json atomically.

    Parameters
    ----------
    camera_or_doc : Camera, CalibrationResult or dict
        A camera, a calibration result (its ``to_dict()``) or a full document.
    path : path-like
    overwrite : bool
    rms : float, optional
        Reprojection RMS to record with a bare Camera.
    """
    if isinstance(camera_or_doc, Camera):
        doc = camera_to_dict(camera_or_doc, rms)
    elif isinstance(camera_or_doc, dict):
        doc = dict(camera_or_doc)
        camera_from_dict(doc)
    else:
        doc = camera_or_doc.to_dict()
    with atomic_path(path, overwrite=overwrite, inputs=inputs) as tmp:
        Path(tmp).write_text(dumps(doc, indent=2) + "\n")
