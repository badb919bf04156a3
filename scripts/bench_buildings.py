"""Benchmark of `ws buildings`: speed, accuracy on analytic buildings, solar figures, real tiles.

Prints one JSON line per result. Usage::

    PYTHONPATH=. python scripts/bench_buildings.py speed [--buildings 500] [--workers 2]  # buildings/min, LoD2 from classified points
    PYTHONPATH=. python scripts/bench_buildings.py accuracy [--buildings 60] [--seed 5] # IoU, tilt, azimuth, roof RMS per roof kind
    PYTHONPATH=. python scripts/bench_buildings.py accuracy --kinds complex [--seed 5]  # the same on cross-gabled L / T and dormer roofs
    PYTHONPATH=. python scripts/bench_buildings.py accuracy --kinds complex --faces dormer  # and a line per true face of the dormers
    PYTHONPATH=. python scripts/bench_buildings.py accuracy --kinds complex --seed 7 --density 4  # a sparser district (points/m2)
    PYTHONPATH=. python scripts/bench_buildings.py accuracy --kinds complex --seed 7 --density 2 --alone  # each house on its own
    PYTHONPATH=. python scripts/bench_buildings.py solar                     # clear-sky kWh/m2/year at 48 N; against PVGIS
    PYTHONPATH=. python scripts/bench_buildings.py real                      # ../shared/data/lidar urban tiles

Real data come from ../shared/data (or $WS_SHARED_DATA) and are never copied.
"""

from __future__ import annotations

import argparse
import json
import os
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
DATA = Path(os.environ.get("WS_SHARED_DATA", REPO.parent / "shared" / "data"))


def emit(**kw):
    print(json.dumps(kw, default=float), flush=True)


def speed(n: int, seed: int = 0, solar: bool = False, workers: int = 1):
    """Footprints + planes + LoD1.2/LoD2.2 (no solar unless asked) on a simulated district, in this
    process or on a local Dask cluster of ``workers`` processes (started within the time measured).
    CPU seconds count this process and, with workers, the workers' own (their tasks' process time)."""
    from workstation.buildings import synth
    from workstation.buildings.pipeline import BuildingsParams, reconstruct_buildings

    xyz, cls, _ = synth.district(n, seed=seed, density=8.0)
    reconstruct_buildings(*synth.district(4, seed=1, density=8.0)[:2], BuildingsParams(solar=None))  # imports
    load0 = os.getloadavg()[0]
    t, c, ch = time.perf_counter(), time.process_time(), _children_cpu()
    params = BuildingsParams(solar=None) if not solar else BuildingsParams()
    r = reconstruct_buildings(xyz, cls, params, workers=workers)
    dt, dc = time.perf_counter() - t, time.process_time() - c + _children_cpu() - ch
    emit(bench="speed", buildings=len(r.models), points=len(xyz), building_points=int((cls == 6).sum()), seconds=dt,
         cpu_seconds=dc, cpu_ms_per_building=1000 * dc / len(r.models), buildings_per_min=len(r.models) / dt * 60,
         buildings_per_cpu_min=len(r.models) / dc * 60,
         timings=r.timings, solar=solar, workers=workers, load_before=load0, load=os.getloadavg()[0])


def _children_cpu() -> float:
    """CPU seconds (user + system) of this process's ended child processes (the local cluster's
    workers once it is closed)."""
    import resource

    u = resource.getrusage(resource.RUSAGE_CHILDREN)
    return u.ru_utime + u.ru_stime


def accuracy(n: int, seed: int = 5, kinds: str = "basic", faces: str | None = None, density: float = 10.0,
             alone: bool = False):
    """Goals of issue 26 per roof kind on a district of analytic buildings (10 points/m2, 3 cm noise):
    the ``basic`` kinds (flat to L-shaped) or the ``complex`` ones (cross-gabled L and T, dormer),
    whose expected roof type is none of the model's classes, so the types found are counted. With
    ``faces`` (a kind), one line per true sloped face of the buildings of that kind
    (:func:`_face_rows`). With ``alone``, every building is reconstructed from the points of its
    own plot only (:func:`_alone`), as for a tile holding one house."""
    from workstation.buildings import synth
    from workstation.buildings.export import cityjson_document, validate_cityjson
    from workstation.buildings.models import is_watertight
    from workstation.buildings.pipeline import BuildingsParams, reconstruct_buildings

    names = synth.KINDS if kinds == "basic" else synth.COMPLEX_KINDS
    xyz, cls, blds = synth.district(n, seed=seed, density=density, noise=0.03, kinds=names)
    t, c = time.perf_counter(), time.process_time()
    r = _alone(xyz, cls, blds) if alone else reconstruct_buildings(xyz, cls, BuildingsParams(solar=None))
    dt, dc = time.perf_counter() - t, time.process_time() - c
    rows = synth.evaluate(r.models, blds)
    for row in _face_rows(r.models, blds, xyz[cls == 6], 0.03, faces) if faces else ():
        emit(bench="face", seed=seed, **row)
    for kind in names:
        k = [x for x in rows if x["kind"] == kind]
        extra = {"roof_type_correct": float(np.mean([x.get("roof_type") == {"lshape": "flat"}.get(kind, kind) for x in k]))} \
            if kinds == "basic" else _complex_fields(k)
        emit(bench="accuracy", kind=kind, buildings=len(k), found=sum(x["found"] for x in k),
             iou_min=min(x["iou"] for x in k), iou_median=float(np.median([x["iou"] for x in k])),
             iou_ge_0_9=float(np.mean([x["iou"] >= 0.9 for x in k])),
             tilt_err_max_deg=max(x.get("tilt_err_deg", np.nan) for x in k),
             azimuth_err_max_deg=max(x.get("azimuth_err_deg", np.nan) for x in k),
             roof_rms_median_m=float(np.median([x.get("roof_rms_m", np.nan) for x in k])),
             roof_rms_max_m=max(x.get("roof_rms_m", np.nan) for x in k), **extra)
    doc = cityjson_document(r.models, r.solar_kwh_m2_year)
    emit(bench="validity", watertight=float(np.mean([is_watertight(s) for m in r.models for s in m.lod2])),
         cityjson_errors=len(validate_cityjson(doc)), buildings=len(r.models), truth=len(blds), seed=seed, kinds=kinds,
         density=density, alone=alone, seconds=dt, cpu_seconds=dc, load=os.getloadavg()[0])


def _alone(xyz: np.ndarray, cls: np.ndarray, blds: list, pitch: float = 30.0):
    """:func:`~workstation.buildings.pipeline.reconstruct_buildings` run once per building of a
    :func:`~workstation.buildings.synth.district` on the points (roof and ground) of its own
    square plot of side ``pitch`` (m, the district's) centred on it; the models of all runs
    gathered in one result."""
    from dataclasses import replace

    from workstation.buildings.pipeline import BuildingsParams, reconstruct_buildings

    runs = [reconstruct_buildings(xyz[sel], cls[sel], BuildingsParams(solar=None))
            for sel in (np.all(np.abs(xyz[:, :2] - np.asarray(b.center)) < pitch / 2, axis=1) for b in blds)]
    return replace(runs[0], models=[m for r in runs for m in r.models],
                   solar_kwh_m2_year=[s for r in runs for s in r.solar_kwh_m2_year])


def _face_rows(models: list, blds: list, roof_xyz: np.ndarray, noise: float, kind: str) -> list:
    """Per true sloped face of each building of ``kind``: its tilt and azimuth, the model face
    matched as :func:`workstation.buildings.synth.evaluate` matches it
    (:func:`~workstation.buildings.synth.best_model`, :func:`~workstation.buildings.synth.matched_faces`)
    and its errors, the true face's points ``n`` (points of ``roof_xyz`` whose true roof
    gradient, by central differences, is the face's), the tilt and azimuth standard errors a
    least-squares plane of those points has at vertical noise ``noise`` (m)
    (:func:`~workstation.buildings.planes.plane_standard_errors` at ``noise cos(tilt)`` along
    the normal) and the errors over them (``tilt_z``, ``azimuth_z``; beyond about 3: more than
    the points support for a face fitted alone; null for under 4 points), and the errors of the oracle (``oracle_*``):
    the least-squares plane z = g . xy + c of those true points, which with vertical Gaussian
    noise no estimator using only them beats systematically (Gauss-Markov); for a face with an
    opposite face on its ridge, the same for the tilt the two share once regularised
    (``pair_*``, :func:`_pair_oracle`)."""
    import shapely

    from workstation.buildings.synth import best_model, matched_faces

    polys = [shapely.Polygon(m.footprint) for m in models]
    tree = shapely.STRtree(polys)
    out = []
    for i, b in enumerate(blds):
        j = best_model(polys, tree, b) if b.kind == kind else None
        if j is None:
            continue
        pts = roof_xyz[b.inside(roof_xyz[:, :2])]
        h = 1e-3
        g = np.column_stack([(b.roof_z(pts[:, :2] + [h, 0]) - b.roof_z(pts[:, :2] - [h, 0])) / (2 * h),
                             (b.roof_z(pts[:, :2] + [0, h]) - b.roof_z(pts[:, :2] - [0, h])) / (2 * h)])
        dist = np.linalg.norm(g[:, None, :] - b.roof_gradients()[None], axis=2)
        on = np.where(dist.min(axis=1) < 1e-3, np.argmin(dist, axis=1), -1)  # -1: on an edge
        for q, tilt, az, f in matched_faces(models[j], b):
            out.append({"building": i, "kind": kind, "face": q, "tilt_deg": tilt, "azimuth_deg": az,
                        "n": int((on == q).sum()), "model_tilt_deg": f.tilt_deg, "model_azimuth_deg": f.azimuth_deg,
                        **_face_errors(pts[on == q], tilt, az, f.tilt_deg, f.azimuth_deg, noise),
                        **_pair_oracle(pts, on, b.roof_gradients(), q, f.tilt_deg - tilt, noise)})
    return out


def _pair_oracle(pts: np.ndarray, on: np.ndarray, grads: np.ndarray, q: int, err: float, noise: float) -> dict:
    """For true face ``q`` with an opposite face (gradient ``-grads[q]``: the other side of its
    ridge, of the same tilt), the oracle of the tilt the model shares between the two when it
    regularises them: the least-squares slope s of z = -s w + c_face over both faces' true points
    (``pts`` labelled ``on``), w the horizontal coordinate down each face's true slope, centred
    per face (azimuths known). Its standard error is noise / sqrt(sum w^2) on s, cos^2(tilt) times
    that on the tilt. Returns its tilt error, that standard error and ``err`` (the model's tilt
    error) over it; nothing without an opposite face."""
    opp = np.flatnonzero(np.linalg.norm(grads + grads[q], axis=1) < 1e-9)
    if not len(opp):
        return {}
    swz = sww = 0.0
    for k in (q, int(opp[0])):
        down = -grads[k] / np.linalg.norm(grads[k])
        w, z = pts[on == k, :2] @ down, pts[on == k, 2]
        w, z = w - w.mean(), z - z.mean()
        swz, sww = swz - w @ z, sww + w @ w
    t = np.arctan(np.linalg.norm(grads[q]))
    se = float(np.degrees(np.cos(t) ** 2 * noise / np.sqrt(sww))) if sww > 0 else float("inf")
    return {"pair_oracle_tilt_err_deg": float(np.degrees(np.arctan(swz / sww) - t)) if sww > 0 else float("nan"),
            "pair_tilt_se_deg": se, "pair_tilt_z": _z(err, se)}


def _z(err: float, se: float):
    """``err`` over its standard error ``se``; None (JSON null) when ``se`` is infinite (too few
    true points to fit a plane): no measure of consistency, where err / inf would read 0."""
    return float(err / se) if np.isfinite(se) else None


def _face_errors(pts: np.ndarray, tilt: float, az: float, model_tilt: float, model_az: float, noise: float) -> dict:
    """Tilt and azimuth errors (degrees) of a model face against the true plane (``tilt``,
    ``az``), their standard errors for the face's true points ``pts`` (m, 3) at vertical noise
    ``noise`` and the errors of the oracle plane of those points (:func:`_face_rows`)."""
    from workstation.buildings.planes import azimuth_of, plane_standard_errors

    t, a = np.radians(tilt), np.radians(az)
    nt = np.array([np.sin(t) * np.sin(a), np.sin(t) * np.cos(a), np.cos(t)])
    se_t, se_a = plane_standard_errors(pts, nt, noise * np.cos(t))  # inf for under 4 points
    err_t, err_a = model_tilt - tilt, (model_az - az + 180) % 360 - 180
    row = {"tilt_err_deg": err_t, "azimuth_err_deg": err_a, "tilt_se_deg": se_t, "azimuth_se_deg": se_a,
           "tilt_z": _z(err_t, se_t), "azimuth_z": _z(err_a, se_a)}
    if len(pts) >= 4:
        xy = pts[:, :2] - pts[:, :2].mean(axis=0)
        gx, gy = np.linalg.lstsq(xy, pts[:, 2] - pts[:, 2].mean(), rcond=None)[0]
        n = np.array([-gx, -gy, 1.0]) / np.sqrt(1.0 + gx * gx + gy * gy)
        row["oracle_tilt_err_deg"] = float(np.degrees(np.arctan(np.hypot(gx, gy)))) - tilt
        row["oracle_azimuth_err_deg"] = float((azimuth_of(n[None])[0] - az + 180) % 360 - 180)
    return row


def _complex_fields(k: list) -> dict:
    """Extra per-kind figures of the composite kinds: roof types found, median errors, share of
    roofs within the 0.15 m goal and of watertight models."""
    found = {}
    for x in k:
        found[x.get("roof_type")] = found.get(x.get("roof_type"), 0) + 1
    return {"roof_types": found, "tilt_err_median_deg": float(np.median([x.get("tilt_err_deg", np.nan) for x in k])),
            "azimuth_err_median_deg": float(np.median([x.get("azimuth_err_deg", np.nan) for x in k])),
            "roof_rms_le_0_15": float(np.mean([x.get("roof_rms_m", np.inf) <= 0.15 for x in k])),
            "watertight": float(np.mean([x.get("watertight", False) for x in k]))}


def solar():
    """Clear-sky annual irradiation (ESRA, hourly) on unshaded planes at 48 N 11 E, and on a 35-degree
    south plane at 51.64 N against PVGIS 5's clear-sky figure for it (tests/buildings/test_solar.py)."""
    from workstation.buildings.solar import SolarParams, plane_irradiation

    def n(t, a):
        t, a = np.radians(t), np.radians(a)
        return [np.sin(t) * np.sin(a), np.sin(t) * np.cos(a), np.cos(t)]

    planes = {"horizontal": n(0, 0), "south_35": n(35, 180), "east_35": n(35, 90), "north_35": n(35, 0), "south_90": n(90, 180)}
    for tl in (3.0, 3.5, 4.0):
        for step in (60.0, 10.0):
            v = plane_irradiation(np.array(list(planes.values())), None, SolarParams(latitude=48.0, longitude=11.0,
                                                                                      linke_turbidity=tl, step_minutes=step))
            emit(bench="solar", linke_turbidity=tl, step_minutes=step, **{k: round(float(x), 1) for k, x in zip(planes, v)})
    from tests.buildings.test_solar import DAYS, PVGIS_CLEAR_SKY_35S_51N_WH_DAY  # PVGIS 5 clear-sky Gcs(i), cited there

    pvgis = float(PVGIS_CLEAR_SKY_35S_51N_WH_DAY @ DAYS) / 1000.0
    for tl in (3.0, 3.5, 4.0):
        ours = float(plane_irradiation(np.array([n(35, 180)]), None, SolarParams(latitude=51.64, longitude=-0.51,
                                                                                   elevation=87.0, linke_turbidity=tl))[0])
        emit(bench="solar_pvgis", site="51.64 N 0.51 W, 87 m", plane="35 deg south, unshaded, clear sky",
             pvgis_kwh_m2_year=round(pvgis, 1), linke_turbidity=tl, ours_kwh_m2_year=round(ours, 1),
             difference_percent=round(100 * (ours / pvgis - 1), 2))


def real():
    """`reconstruct_buildings` on the urban tiles (their own classes); counts and what happens."""
    from workstation.buildings.pipeline import BuildingsParams, reconstruct_buildings
    from workstation.buildings.export import cityjson_document, validate_cityjson
    from workstation.buildings.models import is_watertight
    from workstation.io import read_cloud

    for name in ("sample_c.las", "lidarhd_extra_bytes.laz", "autzen_trim.las"):
        path = DATA / "lidar" / name
        if not path.exists():
            emit(bench="real", file=name, skipped="absent")
            continue
        cloud = read_cloud(path)
        cls = np.asarray(cloud.attrs.get("classification", np.zeros(cloud.n, np.uint8)))
        t = time.perf_counter()
        try:
            r = reconstruct_buildings(cloud.xyz, cls, BuildingsParams(solar=None))
        except Exception as exc:  # report what happens
            emit(bench="real", file=name, points=cloud.n, building_points=int((cls == 6).sum()), error=str(exc))
            continue
        kinds = {}
        for m in r.models:
            kinds[m.roof_type] = kinds.get(m.roof_type, 0) + 1
        emit(bench="real", file=name, points=cloud.n, building_points=int((cls == 6).sum()), buildings=len(r.models),
             seconds=time.perf_counter() - t, roof_types=kinds, spacing_m=r.spacing,
             watertight=float(np.mean([is_watertight(s) for m in r.models for s in m.lod2])),
             cityjson_errors=len(validate_cityjson(cityjson_document(r.models, r.solar_kwh_m2_year))))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    s = sub.add_parser("speed")
    s.add_argument("--buildings", type=int, default=500)
    s.add_argument("--solar", action="store_true")
    s.add_argument("--workers", type=int, default=1, help="processes of a local Dask cluster (1: this process)")
    a = sub.add_parser("accuracy")
    a.add_argument("--buildings", type=int, default=60)
    a.add_argument("--seed", type=int, default=5, help="district seed (5: the reported one; which seeds tuned and which validated a choice "
                   "is said with each figure in docs/benchmarks.md)")
    a.add_argument("--kinds", choices=("basic", "complex"), default="basic",
                   help="basic: flat, shed, gabled, hipped, multi-level, L; complex: cross-gabled L and T, dormer")
    a.add_argument("--faces", default=None, help="a kind: also a line per true sloped face of its buildings")
    a.add_argument("--density", type=float, default=10.0, help="points/m2 of the simulated district (10: the reported one)")
    a.add_argument("--alone", action="store_true", help="reconstruct each building from its own plot's points only")
    sub.add_parser("solar")
    sub.add_parser("real")
    args = ap.parse_args()
    if args.cmd == "speed":
        speed(args.buildings, solar=args.solar, workers=args.workers)
    elif args.cmd == "accuracy":
        accuracy(args.buildings, args.seed, args.kinds, args.faces, density=args.density, alone=args.alone)
    elif args.cmd == "solar":
        solar()
    else:
        real()


if __name__ == "__main__":
    main()
