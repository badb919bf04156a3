"""The MLS refinement (``ws mesh --refine-k``) on clouds that are not photogrammetric: the
bunny scans, the simulated TLS heritage church (``bench_mesh.heritage``) and scan lines, each
meshed once by Poisson and then refined with each k (0: off), one JSON line per result.

    PYTHONPATH=. python scripts/bench_mesh_refine.py bunny|tls|scanlines 0,16,32,48,64

Data: ``$WS_SHARED_DATA`` or ``../shared/data`` next to the repository.
"""
import importlib.util, json, os, sys, time
from dataclasses import replace
from pathlib import Path
import numpy as np
ROOT = Path(__file__).resolve().parents[1]
DATA = Path(os.environ.get("WS_SHARED_DATA", ROOT.parent / "shared" / "data"))
sys.path.insert(0, str(ROOT)); sys.path.insert(0, str(ROOT / "tests" / "mesh"))
from workstation.core.cloud import Cloud, concatenate
from workstation.core.products import Mesh
from workstation.mesh import (CleanParams, DecimateParams, MeshChainParams, PoissonParams, QualityParams,
                              mesh_cloud, clean, decimate, mesh_quality)
from workstation.mesh.reconstruct import RefineParams, refine_to_cloud
spec = importlib.util.spec_from_file_location("bm", ROOT / "scripts" / "bench_mesh.py")
bm = importlib.util.module_from_spec(spec); spec.loader.exec_module(bm)
KS = [int(k) for k in sys.argv[2].split(",")]
which = sys.argv[1]

def emit(**kw):
    print(json.dumps(kw), flush=True)

def after_poisson(raw, cloud, k, dec):
    m = raw
    if k:
        m, _ = refine_to_cloud(m, cloud, RefineParams(k=k))
    m, _ = clean(m, CleanParams(min_piece_fraction=0.1 if dec == 20000 else 0.05, report_self_intersections=False))
    if dec:
        m, _ = decimate(m, DecimateParams(target_faces=dec))
        m, _ = clean(m, CleanParams(report_self_intersections=False))
    return m

if which == "bunny":
    from test_mesh_bunny import bunny_scans
    merged = concatenate(bunny_scans(DATA / "registration"))
    base = mesh_cloud(merged, MeshChainParams(method="poisson", poisson=PoissonParams(depth=9, trim_quantile=0.05),
                      clean=None, quality=None, color=None, texture=None))
    mm = lambda d: {k: round(v * 1000, 4) for k, v in d.items() if k in ("rms", "p95", "max", "p50")}
    for k in KS:
        t = time.process_time()
        m = after_poisson(base.mesh, merged, k, 20000)
        q = mesh_quality(Mesh(m.vertices, m.faces), Cloud(merged.xyz), QualityParams(mesh_samples=200_000))
        emit(data="bunny", k=k, faces=q["faces"], nme=q["non_manifold_edges"], m2c_mm=mm(q["mesh_to_cloud"]),
             m2c_floor_mm=mm(q["mesh_to_cloud_floor"]), m2c_plane_mm=mm(q["mesh_to_cloud_local_plane"]),
             c2m_mm=mm(q["cloud_to_mesh"]), cpu=round(time.process_time() - t, 1))
elif which == "scanlines":
    from test_mesh_normals_scanlines import scan_lines, surface, ORIGIN
    from workstation.mesh.quality import closest_on_mesh
    for gap, along, noise in [(0.5, 0.05, 0.003), (0.5, 0.05, 0.0), (0.2, 0.05, 0.003)]:
        x, y, z = scan_lines(gap=gap, along=along, noise=noise)
        cloud = Cloud(np.column_stack([x, y, z]) + ORIGIN)
        base = mesh_cloud(cloud, MeshChainParams(clean=None, quality=None, color=None, texture=None))
        rng = np.random.default_rng(1)
        qx, qy = rng.uniform(1.0, 19.0, (2, 20000))
        for k in KS:
            m = after_poisson(base.mesh, cloud, k, None)
            d, _ = closest_on_mesh(np.column_stack([qx, qy, surface(qx, qy)]) + ORIGIN, m.vertices, m.faces)
            vv = m.vertices - ORIGIN
            inside = (vv[:, 0] > 1) & (vv[:, 0] < 19) & (vv[:, 1] > 1) & (vv[:, 1] < 19)
            ev = np.abs(vv[inside, 2] - surface(vv[inside, 0], vv[inside, 1]))
            emit(data=f"scanlines gap={gap} along={along} noise={noise}", k=k, truth_far5cm=round(float(np.mean(d > 0.05)), 4),
                 truth2mesh_p50_mm=round(1000 * float(np.median(d)), 2), truth2mesh_p95_mm=round(1000 * float(np.percentile(d, 95)), 2),
                 vert_dz_rms_mm=round(1000 * float(np.sqrt(np.mean(ev ** 2))), 2), vert_dz_max_mm=round(1000 * float(ev.max()), 1))
elif which == "tls":
    # bench_mesh.heritage, the Poisson done once, then each k
    captured = {}
    import workstation.mesh as wm
    real = wm.mesh_cloud
    def grab(cloud, params, vp):
        p = replace(params, clean=None, decimate=None, quality=None, color=None, texture=None)
        r = real(cloud, p, vp)
        captured["cloud"], captured["raw"] = cloud, r.mesh
        return r
    wm.mesh_cloud = grab
    orig_mvt = bm.mesh_vs_truth
    bm.mesh_vs_truth = lambda mesh, truth: (captured.__setitem__("truth", truth), ({"rms": 0.0}, {}))[1]
    bm.emit = lambda **kw: None
    bm.heritage()
    wm.mesh_cloud = real
    for k in KS:
        m = captured["raw"]
        if k:
            m, _ = refine_to_cloud(m, captured["cloud"], RefineParams(k=k))
        m, _ = clean(m, CleanParams(min_piece_fraction=0.05, report_self_intersections=False))
        m, _ = decimate(m, DecimateParams(target_faces=200_000))
        m, _ = clean(m, CleanParams(report_self_intersections=False))
        m2t, t2m = orig_mvt(m, captured["truth"])
        emit(data="tls_heritage", k=k, faces=m.n_faces, mesh_to_truth_m={a: round(v, 4) for a, v in m2t.items()},
             truth_to_mesh_m={a: round(v, 4) for a, v in t2m.items()})
