"""Scale a reconstruction without ground control: scale bars and known distances.

An SfM model is right up to a similarity; without GCPs its unit is arbitrary. One known length
fixes the scale (the rotation and position stay free, as for a 7-parameter similarity with the
rotation and shift left out). A length is given either between two points seen in the photos
(a *scale bar*: a ruler, a levelling staff, two targets measured with a tape) or between two
points of the model (picked in a viewer).

Syntax (the ``--scale-bar`` / ``--scale-distance`` text)::

    END ; END = LENGTH [UNIT]

* an ``END`` seen in the photos is two or more image observations ``IMAGE:x,y`` separated by
  spaces: the image's file name as in the reconstruction (a name may contain spaces, not
  ``:`` ``;`` ``=``), and the pixel column and row of the point (OpenCV convention: origin at
  the centre of the top-left pixel, x right, y down). The end is triangulated by space
  intersection from the oriented images (:func:`~.collinearity.intersect`): one observation
  gives a ray, not a point, so each end needs at least two;
* an ``END`` given in the model is its coordinates ``X,Y,Z`` (model units);
* ``LENGTH`` is a positive number; ``UNIT`` one of ``m`` (the default), ``cm``, ``mm``, ``km``,
  ``in``, ``ft`` (international foot, 0.3048 m), ``us-ft`` (US survey foot, 1200/3937 m),
  ``yd``.

Examples: ``"DSC_01.JPG:1520.5,1006 DSC_02.JPG:1498,1010 ; DSC_01.JPG:2210,1003
DSC_02.JPG:2187,1009 = 1.000 m"`` (a one-metre bar seen in two photos) and
``"0.12,-1.5,3.2 ; 2.9,-1.4,3.3 = 4.25 m"`` (a known distance between two model points).

With several bars the scale is their inverse-variance weighted mean (each bar's variance from
the intersection covariances of its ends, Wolf et al., *Elements of Photogrammetry*, 2014,
§11-7, propagated to the length), and every bar's length after scaling against its known
length is reported: the residuals check the bars against each other. The model is scaled
about its origin (``X' = s X``; rotations and image residuals unchanged).

A reconstruction is *scaled* (lengths in metres) when it carries a CRS, a georeference or a
scale from here (:func:`is_scaled`); reports of an unscaled one print "unscaled" instead of
"m" (:func:`length_text`).

Examples
--------
>>> bar = parse_scale_bar("a.jpg:10,20 b.jpg:30.5,40 ; a.jpg:50,60 b.jpg:70,80 = 25 cm")
>>> [o.image for o in bar.ends[0].observations], bar.length_m
(['a.jpg', 'b.jpg'], 0.25)
>>> parse_scale_distance("0,0,0 ; 3,4,0 = 10 ft").length_m
3.048
>>> length_text(2.5, False), length_text(2.5, True)
('2.500 (unscaled)', '2.500 m')
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from typing import Any, Mapping, Sequence

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.core.products import Image, Reconstruction

from .georef import Similarity

log = get_logger(__name__)

UNITS_M = {"m": 1.0, "cm": 0.01, "mm": 0.001, "km": 1000.0, "in": 0.0254, "ft": 0.3048,
           "us-ft": 1200.0 / 3937.0, "yd": 0.9144}
SYNTAX = "END ; END = LENGTH [UNIT], END = IMAGE:x,y IMAGE:x,y [...] or X,Y,Z"
_NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_OBS = re.compile(rf"\s*([^:;=]+?)\s*:\s*({_NUM})\s*,\s*({_NUM})(?=\s|$)")
_XYZ = re.compile(rf"^\s*({_NUM})\s*,\s*({_NUM})\s*,\s*({_NUM})\s*$")
_LEN = re.compile(rf"^\s*({_NUM})\s*([A-Za-z-]*)\s*$")


@dataclass(frozen=True)
class Observation:
    """A point's pixel in one image: ``image`` name, column ``x`` and row ``y`` (pixels,
    OpenCV convention)."""

    image: str
    x: float
    y: float


@dataclass(frozen=True)
class BarEnd:
    """One end of a scale bar: image observations (≥ 2) or model coordinates."""

    observations: tuple = ()
    model_xyz: tuple | None = None


@dataclass(frozen=True)
class ScaleBar:
    """A known length between two points.

    Attributes
    ----------
    ends : (BarEnd, BarEnd)
    length_m : float
        The known length, metres.
    text : str
        The text it was parsed from.
    """

    ends: tuple
    length_m: float
    text: str = ""


def _bad(text: str, why: str, opt: str) -> InvalidInputError:
    return InvalidInputError(f"{opt} {text!r}: {why}", f"write {SYNTAX}, e.g. "
                             "'A.JPG:1520,1006 B.JPG:1498,1010 ; A.JPG:2210,1003 B.JPG:2187,1009 = 1.000 m'",
                             field=opt)


def _parse_length(text: str, part: str, opt: str) -> float:
    m = _LEN.match(part)
    if not m:
        raise _bad(text, f"the length {part.strip()!r} is not a number with an optional unit", opt)
    value, unit = float(m.group(1)), (m.group(2) or "m").lower()
    if unit not in UNITS_M:
        raise _bad(text, f"unknown unit {unit!r} (units: {', '.join(UNITS_M)})", opt)
    if not (value > 0 and math.isfinite(value)):
        raise _bad(text, f"the length must be positive, got {value:g}", opt)
    return value * UNITS_M[unit]


def _parse_end(text: str, part: str, which: str, opt: str) -> BarEnd:
    m = _XYZ.match(part)
    if m:
        return BarEnd(model_xyz=tuple(float(v) for v in m.groups()))
    obs, pos = [], 0
    for m in _OBS.finditer(part):
        if part[pos:m.start()].strip():
            break
        obs.append(Observation(m.group(1), float(m.group(2)), float(m.group(3))))
        pos = m.end()
    rest = part[pos:].strip()
    if rest or not obs:
        raise _bad(text, f"the {which} end: cannot read {rest or part.strip()!r} as IMAGE:x,y observations "
                         "or X,Y,Z model coordinates", opt)
    if len({o.image for o in obs}) < 2:
        raise _bad(text, f"the {which} end is observed in {len({o.image for o in obs})} image: one pixel gives a "
                         "ray, not a point; give it in at least two photos (IMAGE:x,y IMAGE:x,y)", opt)
    return BarEnd(observations=tuple(obs))


def parse_scale_bar(text: str, option: str = "--scale-bar") -> ScaleBar:
    """A :class:`ScaleBar` from ``END ; END = LENGTH [UNIT]`` (module docstring).

    Raises
    ------
    InvalidInputError
        The text does not follow the syntax; the message says which part.
    """
    s = str(text)
    if s.count("=") != 1:
        raise _bad(s, "needs exactly one '=' before the known length", option)
    ends_part, length_part = s.split("=")
    length = _parse_length(s, length_part, option)
    ends = ends_part.split(";")
    if len(ends) != 2:
        raise _bad(s, f"needs two ends separated by ';', found {len(ends)} part(s)", option)
    a, b = (_parse_end(s, e, w, option) for e, w in zip(ends, ("first", "second")))
    if a.model_xyz is not None and a.model_xyz == b.model_xyz:
        raise _bad(s, "both ends are the same point", option)
    return ScaleBar((a, b), length, s)


def parse_scale_distance(text: str, option: str = "--scale-distance") -> ScaleBar:
    """A known distance between two model points, ``X,Y,Z ; X,Y,Z = LENGTH [UNIT]``."""
    bar = parse_scale_bar(text, option)
    if any(e.model_xyz is None for e in bar.ends):
        raise _bad(text, "both ends must be model coordinates X,Y,Z (use --scale-bar for points in the photos)", option)
    return bar


def parse_scale_texts(bars: Sequence[str] = (), distances: Sequence[str] = ()) -> list[ScaleBar]:
    """Every ``--scale-bar`` (:func:`parse_scale_bar`) and ``--scale-distance``
    (:func:`parse_scale_distance`) text, parsed, bars first."""
    return [parse_scale_bar(t) for t in bars] + [parse_scale_distance(t) for t in distances]


def _end_point(end: BarEnd, rec: Reconstruction, lookup: Mapping[str, Image], sigma_px: float, label: str):
    """(point (3,), covariance (3, 3), info dict) of a bar end in the model frame."""
    from .collinearity import intersect

    if end.model_xyz is not None:
        return np.asarray(end.model_xyz, dtype=float), np.zeros((3, 3)), {"source": "model"}
    missing = [o.image for o in end.observations if o.image not in lookup]
    if missing:
        names = ", ".join(sorted(lookup)[:8])
        raise InvalidInputError(f"{label}: image(s) {', '.join(missing)} not in the reconstruction",
                                f"use the oriented images' names, e.g. {names}", field="scale-bar")
    ims = [lookup[o.image] for o in end.observations]
    uv = np.array([[o.x, o.y] for o in end.observations])
    res = intersect(uv, [rec.cameras[im.camera_id] for im in ims], [im.pose for im in ims], sigma_px=sigma_px)
    return res.point, res.covariance, {"source": "images", "rays": len(ims), "rms_px": res.rms_px,
                                      "angle_deg": res.max_angle_deg}


@dataclass(frozen=True)
class ScaleResult:
    """The scale of a reconstruction from known lengths.

    Attributes
    ----------
    scale : float
        Metres per model unit.
    scale_rel_std : float
        Relative standard deviation of ``scale`` (unitless; from the intersections, or from
        the spread of the bars when there are ≥ 2 and it is larger).
    bars : list of dict
        Per bar: ``text``, ``model_length`` (model units), ``model_length_std``,
        ``length_m`` (known), ``scaled_length_m`` (after scaling), ``residual_m``
        (scaled - known), ``scale``, and per end its ``source``, ``rays``, ``rms_px``, ``angle_deg``.
    """

    scale: float
    scale_rel_std: float
    bars: list = field(default_factory=list)

    @property
    def similarity(self) -> Similarity:
        """``X_metres = scale · X_model`` (about the origin)."""
        return Similarity(float(self.scale), np.eye(3), np.zeros(3))

    def to_meta(self) -> dict[str, Any]:
        """Scalar entries for ``Reconstruction.meta`` and cameras.json."""
        return {"scaled": True, "scale_m_per_unit": float(self.scale), "scale_rel_std": float(self.scale_rel_std),
                "scale_bars": len(self.bars)}

    def to_dict(self) -> dict:
        return {"scaled": True, "scale_m_per_unit": float(self.scale), "scale_rel_std": float(self.scale_rel_std),
                "bars": list(self.bars)}


def estimate_scale(rec: Reconstruction, bars: Sequence[ScaleBar], sigma_px: float = 1.0) -> ScaleResult:
    """Metres per model unit from known lengths (inverse-variance weighted over the bars).

    Parameters
    ----------
    rec : Reconstruction
        Oriented images (bars seen in the photos) in the model frame to be scaled.
    bars : sequence of ScaleBar
    sigma_px : float
        A-priori precision of the clicked pixels, pixels.

    Raises
    ------
    InvalidInputError
        No bar, an image not in the reconstruction, or a bar whose ends coincide in the model.
    """
    if not bars:
        raise InvalidInputError("no scale bar or known distance given", f"give one as {SYNTAX}")
    if rec.crs is not None:
        log.warning("the reconstruction has a CRS (%s): scaling it changes its units", rec.crs)
    from .georef import image_lookup

    lookup = image_lookup(rec)
    rows, s, var = [], [], []
    for i, bar in enumerate(bars, start=1):
        label = f"scale bar {i}"
        (p, cp, ia), (q, cq, ib) = (_end_point(e, rec, lookup, sigma_px, label) for e in bar.ends)
        d = q - p
        L = float(np.linalg.norm(d))
        if not L > 0:
            raise InvalidInputError(f"{label}: its two ends are the same model point", "check the pixels",
                                    field="scale-bar")
        u = d / L
        L_std = float(math.sqrt(max(u @ (cp + cq) @ u, 0.0)))
        s.append(bar.length_m / L)
        var.append((s[-1] * L_std / L) ** 2)
        rows.append({"text": bar.text, "model_length": L, "model_length_std": L_std, "length_m": bar.length_m,
                     "scale": s[-1], "ends": [ia, ib]})
    s, var = np.array(s), np.array(var)
    w = 1.0 / var if np.all(var > 0) else np.ones_like(s)
    scale = float(np.sum(w * s) / np.sum(w))
    rel = float(math.sqrt(1.0 / np.sum(w)) / scale) if np.all(var > 0) else 0.0
    if len(s) >= 2:  # the bars' own spread, when larger than the intersections promise
        rel = max(rel, float(np.std(s, ddof=1) / math.sqrt(len(s)) / scale))
    for r in rows:
        r["scaled_length_m"] = scale * r["model_length"]
        r["residual_m"] = r["scaled_length_m"] - r["length_m"]
    if not (scale > 0 and math.isfinite(scale)):
        raise StageError("scale", f"the scale came out as {scale}", "check the scale bars")
    log.info("scale: %.6g m per model unit (±%.2g %%) from %d bar(s)", scale, 100 * rel, len(rows))
    return ScaleResult(scale, rel, rows)


def scale_reconstruction(rec: Reconstruction, result: ScaleResult) -> Reconstruction:
    """A new reconstruction in metres: camera centres and points times ``result.scale``
    (rotations, intrinsics, tracks and colours kept); ``meta`` gains
    :meth:`ScaleResult.to_meta`."""
    sim = result.similarity
    images = {k: Image(im.name, im.camera_id, sim.apply_pose(im.pose), im.path) for k, im in rec.images.items()}
    pts = None if rec.points is None else sim.apply(rec.points)
    return Reconstruction(dict(rec.cameras), images, pts, rec.colors, rec.crs, {**dict(rec.meta), **result.to_meta()},
                          rec.tracks)


def scale_cloud(cloud: Cloud, result: ScaleResult) -> Cloud:
    """A new cloud with coordinates in metres (``X' = scale · X``; normals unchanged)."""
    return cloud.with_xyz(np.asarray(cloud.xyz) * result.scale).with_history(
        "scale", {"scale_m_per_unit": float(result.scale), "bars": len(result.bars)})


def compose(first: Similarity, then: Similarity) -> Similarity:
    """The similarity applying ``first`` then ``then`` (e.g. upright, then scale)."""
    R = np.asarray(then.R) @ np.asarray(first.R)
    t = then.scale * np.asarray(then.R) @ np.asarray(first.t) + np.asarray(then.t)
    return Similarity(float(then.scale * first.scale), R, t)


@dataclass(frozen=True)
class ModelFrame:
    """The upright and scaled frame of an SfM model (what ``ws sfm`` applies to ``sparse/0``).

    Attributes
    ----------
    similarity : Similarity or None
        Model frame → upright, scaled frame (None: nothing to apply).
    orientation : Orientation or None
    scale : ScaleResult or None
    summary : dict
        ``upright``: ``{"applied", "method", "tilt_deg", "facade", "inliers"}``;
        ``scale``: :meth:`ScaleResult.to_dict` or ``{"scaled": False}``; for the stage record.
    """

    similarity: Similarity | None
    orientation: Any
    scale: ScaleResult | None
    summary: dict

    def apply_reconstruction(self, rec: Reconstruction) -> Reconstruction:
        """``rec`` in this frame (meta gains the upright and scale entries)."""
        from .orient import orient_reconstruction

        out = rec if self.orientation is None else orient_reconstruction(rec, self.orientation)
        return out if self.scale is None else scale_reconstruction(out, self.scale)

    def apply_cloud(self, cloud: Cloud) -> Cloud:
        """``cloud`` (model frame) in this frame."""
        from .orient import orient_cloud

        out = cloud if self.orientation is None else orient_cloud(cloud, self.orientation)
        return out if self.scale is None else scale_cloud(out, self.scale)


def upright_and_scale(rec: Reconstruction, upright: bool = True, bars: Sequence[ScaleBar] = (),
                      orient_params=None, sigma_px: float = 1.0) -> ModelFrame:
    """Upright (:func:`~.orient.estimate_orientation`) and scale (:func:`estimate_scale`) an
    SfM model in one similarity. The scale is a ratio of lengths, so it is the same before or
    after the rotation, and model points of ``bars`` may be given in either frame.

    Parameters
    ----------
    rec : Reconstruction
        The SfM model (cameras, poses, sparse points).
    upright : bool
        Level the model and turn its main façade to face -y.
    bars : sequence of ScaleBar
        Scale bars and known distances (:func:`parse_scale_bar`, :func:`parse_scale_distance`).
    orient_params : OrientParams, optional
    sigma_px : float
        Precision of the scale bars' pixels, pixels.
    """
    from .orient import OrientParams, estimate_orientation

    o = estimate_orientation(rec, orient_params or OrientParams()) if upright else None
    sc = estimate_scale(rec, bars, sigma_px) if bars else None
    sims = [x.similarity for x in (o, sc) if x is not None]
    sim = None if not sims else (sims[0] if len(sims) == 1 else compose(sims[0], sims[1]))
    summary = {"upright": {"applied": False} if o is None else {
        "applied": True, "method": o.method, "tilt_deg": float(o.tilt_deg), "facade": o.facade_source,
        "inliers": int(o.inliers)}, "scale": {"scaled": False} if sc is None else sc.to_dict()}
    if sim is not None:
        summary["similarity"] = sim.to_dict()
    return ModelFrame(sim, o, sc, summary)


def is_scaled(obj) -> bool:
    """Whether lengths of a reconstruction (or its stage record / meta mapping) are in metres:
    it has a CRS, a georeference, or a scale from a scale bar or known distance."""
    if isinstance(obj, Reconstruction):
        if obj.crs is not None:
            return True
        meta = obj.meta
    else:
        meta = obj or {}
    if meta.get("crs") or meta.get("scaled") is True or "georeference" in meta or meta.get("georef"):
        return True
    sc = meta.get("scale")
    return isinstance(sc, Mapping) and sc.get("scaled") is True


def length_text(value: float, scaled: bool, digits: int = 3) -> str:
    """A length for a report: ``"2.500 m"`` when scaled, ``"2.500 (unscaled)"`` when not."""
    return f"{value:.{digits}f} m" if scaled else f"{value:.{digits}f} (unscaled)"


__all__ = [
    "BarEnd",
    "ModelFrame",
    "Observation",
    "SYNTAX",
    "ScaleBar",
    "ScaleResult",
    "UNITS_M",
    "compose",
    "estimate_scale",
    "is_scaled",
    "length_text",
    "parse_scale_bar",
    "parse_scale_distance",
    "scale_cloud",
    "scale_reconstruction",
    "upright_and_scale",
]


def level_and_scale_model(result, workdir, upright: bool, bars: Sequence[ScaleBar], sigma_px: float):
    """Level and scale an SfM result in its work folder (:func:`upright_and_scale`) before
    anything reads it: ``workdir/sparse/0`` is rewritten in the new frame, so georeferencing,
    dense matching and meshing all start from it. Returns the sparse cloud in that frame and
    the summary entries of the record ("upright", "scale", "similarity")."""
    from pathlib import Path

    from workstation.interop.pycolmap import apply_similarity, import_pycolmap, write_model

    frame = upright_and_scale(result.reconstruction, upright=upright, bars=bars, sigma_px=sigma_px)
    if frame.similarity is None:
        return result.cloud, frame.summary
    sparse = Path(workdir) / "sparse" / "0"
    model = import_pycolmap().Reconstruction(str(sparse))
    apply_similarity(model, frame.similarity)
    write_model(model, sparse)
    return frame.apply_cloud(result.cloud), frame.summary

