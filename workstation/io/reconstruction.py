"""cameras.json: oriented cameras and images (a :class:`Reconstruction` without points) on disk.

Layout (one JSON object; pixel centres at integer coordinates, ``x_cam = R @ X_world + t``)::

    {"convention": "...",
     "crs": "EPSG:32632" or null,
     "cameras": {"1": {"width", "height", "fx", "fy", "cx", "cy", "skew", "dist", "model"}},
     "images": {"1": {"name", "camera_id", "R": 3×3, "t": 3, "path"}},
     "meta": {scalar values only}}

``dist`` is OpenCV's (k1, k2, p1, p2, k3). An image's ``path`` (or, without it, its ``name``)
is read relative to the JSON file's folder and must stay inside it.

The work folder's stage records live here too. Every photogrammetry command that works on a
work folder (``ws sfm``, ``ws dense``, ``ws mesh --reconstruction``, ``ws colorize``,
``ws ortho``) writes one JSON record (:func:`stage_record`): its ``--json`` document plus
``stage``, ``finished`` (UTC, ISO 8601), ``seconds``, ``inputs`` (absolute paths), ``params``
and ``outputs``. The record of ``ws sfm`` (``WORKDIR/summary.json``) holds the absolute image
folder (``inputs.image_dir``) and the camera settings (``params``: camera model, shared or
per-image intrinsics, max image size, matcher...), so the later commands find the photos
without ``--images`` (:func:`resolve_image_dir`) and ``ws report WORKDIR`` lists every step.
As with ODM's per-stage ``log.json``, the record is what makes a work folder self-describing.

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

import datetime as _dt
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


SFM_RECORD = "summary.json"
"""File name of the ``ws sfm`` record in a work folder."""

IMAGES_HINT = "pass the folder of the original photos with --images IMAGES/"


def stage_record(stage: str, figures: dict | None = None, *, inputs: dict, params: dict, outputs, seconds: float) -> dict:
    """A work-folder stage record: ``stage``, ``finished`` (UTC ISO 8601), ``seconds`` (wall
    time of the command, s), ``inputs`` (name -> absolute path, None kept), ``params`` (the
    command's settings), ``outputs`` (absolute paths; None left out) and the stage's own
    figures (``figures``, e.g. the ``--json`` document), which never replace those keys (a
    figure named like one of them, e.g. a stage's own ``seconds``, gives way).

    Examples
    --------
    >>> r = stage_record("dense", {"points": 10, "seconds": 0.5}, inputs={"image_dir": "/data/photos"},
    ...                  params={"device": "cpu"}, outputs=["/w/dense/fused.ply", None], seconds=1.23456)
    >>> r["stage"], r["seconds"], r["outputs"], r["points"]
    ('dense', 1.235, ['/w/dense/fused.ply'], 10)
    """
    def absolute(p):
        return None if p is None else str(Path(p).absolute())

    outs = [outputs] if isinstance(outputs, (str, Path)) else list(outputs or [])
    head = {
        "stage": stage,
        # microseconds: stages of a small job finish within one second, and the report orders by this
        "finished": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="microseconds"),
        "seconds": round(float(seconds), 3),
        "inputs": {k: absolute(v) for k, v in inputs.items()},
        "params": dict(params),
        "outputs": [absolute(o) for o in outs if o is not None],
    }
    return {**{k: v for k, v in (figures or {}).items() if k not in head}, **head}


def write_stage_record(record: dict, path, required: bool = True) -> Path | None:
    """Write a stage record as JSON (atomically; a record is replaced by its stage's next run).

    With ``required=False`` a folder that cannot be written (a read-only work folder whose
    products go elsewhere) only logs a warning and returns None: the products are made.
    """
    from workstation.core.jsonutil import json_clean, to_jsonable

    try:
        with atomic_path(path, overwrite=True) as tmp:
            Path(tmp).write_text(json.dumps(json_clean(record), indent=2, default=to_jsonable) + "\n")
    except OSError as e:
        if required:
            raise
        from workstation.core.log import get_logger

        get_logger(__name__).warning("stage record %s not written: %s", path, e)
        return None
    return Path(path)


def work_folder_of(path) -> Path:
    """The work folder of a reconstruction path: the folder itself, the folder holding a
    cameras JSON, or ``WORKDIR`` for a COLMAP model folder ``WORKDIR/sparse/N`` or ``WORKDIR/sparse``."""
    p = Path(path)
    if p.is_file():
        return p.parent
    if p.parent.name == "sparse" and p.name.isdigit():
        return p.parent.parent
    return p.parent if p.name == "sparse" else p


def read_sfm_record(workdir) -> dict | None:
    """The ``ws sfm`` record of a work folder (``summary.json`` with ``"stage": "sfm"``), or None
    when there is none (a rig folder, a work folder from an older version)."""
    p = work_folder_of(workdir) / SFM_RECORD
    if not p.is_file():
        return None
    try:
        doc = json.loads(read_text(p))
    except (OSError, ValueError):
        return None
    return doc if isinstance(doc, dict) and doc.get("stage") == "sfm" else None


def resolve_image_dir(workdir, image_dir=None) -> Path | None:
    """The folder of a work folder's original photos, found before any work starts.

    In order: ``image_dir`` when given (an explicit ``--images`` always wins); the folder the
    ``ws sfm`` record names; ``WORKDIR/images`` (rig folders). None for a cameras JSON (its
    images are named relative to the JSON file).

    Raises
    ------
    InvalidInputError
        The recorded folder no longer exists (names it and the option to pass), or a COLMAP
        work folder has neither a record nor ``images/``.
    """
    if image_dir is not None:
        return Path(image_dir)
    p = Path(workdir)
    if p.is_file() or (p / "cameras.json").is_file():
        return None  # a cameras JSON names its images relative to itself
    wd = work_folder_of(p)
    rec = read_sfm_record(wd)
    recorded = (rec.get("inputs") or {}).get("image_dir") if rec else None
    if recorded:
        folder = Path(recorded)
        if not folder.is_dir():
            raise InvalidInputError(f"the image folder recorded by `ws sfm` no longer exists: {folder}",
                                    f"{IMAGES_HINT} (the folder was moved or renamed)",
                                    path=wd / SFM_RECORD, field="inputs.image_dir")
        return folder
    for cand in (p / "images", wd / "images"):
        if cand.is_dir():
            return cand
    raise InvalidInputError("no image folder: the work folder has no `ws sfm` record (summary.json) and no images/",
                            IMAGES_HINT, path=wd)


def check_image_files(images, image_dir=None, source=None) -> None:
    """Refuse a model whose images are not all on disk (checked before any work).

    Parameters
    ----------
    images : Reconstruction or iterable of str
        A reconstruction (its images' ``path``) or image names (looked up in ``image_dir``).
    image_dir : path, optional
        The folder searched, named in the error.
    source : path, optional
        The work folder or file the error names (default ``image_dir``).

    Raises
    ------
    InvalidInputError
        Naming the first missing files, their count and the folder searched.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> d = pathlib.Path(tempfile.mkdtemp()); _ = (d / "a.png").write_bytes(b"")
    >>> check_image_files(["a.png"], d)
    >>> check_image_files(["a.png", "b.png"], d)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    workstation.core.errors.InvalidInputError: ...: 1 of the 2 images of the model are missing in ...: b.png (hint: ...)
    """
    if isinstance(images, Reconstruction):
        paths = {im.name: im.path for im in images.images.values()}
    else:
        paths = {n: None if image_dir is None else Path(image_dir) / n for n in images}
    missing = sorted(n for n, p in paths.items() if not p or not Path(p).is_file())
    if not missing:
        return
    where = f" in {image_dir}" if image_dir is not None else ""
    shown = ", ".join(missing[:5]) + (f" and {len(missing) - 5} more" if len(missing) > 5 else "")
    raise InvalidInputError(f"{len(missing)} of the {len(paths)} images of the model are missing{where}: {shown}",
                            IMAGES_HINT + ", the folder holding every image the model names",
                            path=source if source is not None else image_dir)


__all__ = ["CONVENTION", "IMAGES_HINT", "SFM_RECORD", "check_image_files", "read_reconstruction_json",
           "read_sfm_record", "resolve_image_dir", "stage_record", "work_folder_of", "write_reconstruction_json",
           "write_stage_record"]
