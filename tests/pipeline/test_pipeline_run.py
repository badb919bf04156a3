"""``ws run PROJECT.toml`` end to end on a tiny survey: outputs, seams, re-runs from run.json,
a bad tile, refused inputs, an external Dask cluster on loopback and a killed worker.

Every ``ws`` call is a separate process (as a user runs it), each with its own
``PYTHONHASHSEED``, so state that does not survive from one process to the next shows. The
baseline run uses a local cluster (``--workers 2``); re-runs and the cluster tests use one
``dask scheduler`` with two ``dask worker`` processes started here, kept warm for the module.
Re-run tests start from a copy of the baseline's output folder (run.json's paths moved with it)
rather than from a run of their own, to keep the module near a minute on two cores.
"""

from __future__ import annotations

import itertools
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from pipeline_synth import BUILDINGS, CRS, X0, Y0, terrain, tile_points, write_project, write_tiles

from workstation.io import read_cloud

BIN = Path(sys.executable).parent
WS, DASK = BIN / "ws", BIN / "dask"
CELLS = ((0, 0), (0, 1), (1, 0), (1, 1))
CHUNKS = ["500000_4000000", "500000_4000100", "500100_4000000", "500100_4000100"]
_seeds = itertools.count(101)

pytestmark = [pytest.mark.slow, pytest.mark.timeout(180)]


def ws(*args, cwd=None, timeout=150) -> SimpleNamespace:
    """Run ``ws ARGS`` in a new process; .rc, .out, .err and .json (the --json document)."""
    env = dict(os.environ, PYTHONHASHSEED=str(next(_seeds)), WS_PROGRESS="0")
    r = subprocess.run([str(WS), *map(str, args)], capture_output=True, text=True, cwd=cwd, timeout=timeout, env=env)
    doc = None
    if "--json" in args and r.stdout.strip():
        doc = json.loads(r.stdout)
    return SimpleNamespace(rc=r.returncode, out=r.stdout, err=r.stderr, json=doc)


def run_json(out: Path) -> dict:
    return json.loads((out / "run.json").read_text())


def ran(doc: dict) -> dict:
    return {phase: c["run"] for phase, c in doc["phases"].items()}


def totals(doc: dict) -> dict:
    return {phase: c["total"] for phase, c in doc["phases"].items()}


def laz_files(out: Path) -> list[str]:
    """Names of the chunk LAZ files (not hidden temporary files)."""
    return sorted(p.name for p in (out / "ground").glob("*.laz") if not p.name.startswith("."))


def snapshot(folder: Path, skip=("run.json",)) -> dict:
    """Relative path -> (bytes, mtime_ns) of every file under ``folder``."""
    return {str(p.relative_to(folder)): (p.read_bytes(), p.stat().st_mtime_ns)
            for p in sorted(folder.rglob("*")) if p.is_file() and p.name not in skip}


def read_dem(path: Path):
    import rasterio

    with rasterio.open(path) as src:
        return src.read(1), src.transform, src.crs, src.nodata


def assert_same_points(a: Path, b: Path, names=None):
    names = names or laz_files(a)
    assert names and set(names) <= set(laz_files(b))
    for n in names:
        ca, cb = read_cloud(a / "ground" / n), read_cloud(b / "ground" / n)
        np.testing.assert_array_equal(ca.xyz, cb.xyz, err_msg=n)
        assert set(ca.attrs) == set(cb.attrs)
        for k in ca.attrs:
            np.testing.assert_array_equal(ca.attrs[k], cb.attrs[k], err_msg=f"{n} {k}")


def assert_same_outputs(a: Path, b: Path):
    assert laz_files(a) == laz_files(b) == sorted(f"{c}.laz" for c in CHUNKS)
    assert_same_points(a, b)
    for kind in ("dtm", "dsm"):
        xa, ta, _, _ = read_dem(a / "dem" / f"{kind}.tif")
        xb, tb, _, _ = read_dem(b / "dem" / f"{kind}.tif")
        assert ta == tb
        np.testing.assert_array_equal(xa, xb, err_msg=kind)


def copy_out(src: Path, dst: Path) -> Path:
    """A copy of a finished output folder: run.json records outputs relative to its folder, so
    the copy is up to date where it lies."""
    shutil.copytree(src, dst)
    return dst


# ----------------------------------------------------------------------------- fixtures
@pytest.fixture(scope="module")
def survey(tmp_path_factory) -> Path:
    """2 x 2 tiles of 90 m (40,500 points each) cut across by 100 m chunks, and the projects."""
    folder = tmp_path_factory.mktemp("survey")
    write_tiles(folder / "tiles", CELLS)
    write_project(folder)
    write_project(folder, "project_res2.toml", resolution=2.0)
    write_project(folder, "project_cell.toml", ground="cell = 1.5")
    return folder


@pytest.fixture(scope="module")
def baseline(survey, tmp_path_factory) -> SimpleNamespace:
    """``ws run project.toml --out OUT --workers 2 --json`` on a local cluster."""
    out = tmp_path_factory.mktemp("baseline") / "out"
    r = ws("run", survey / "project.toml", "--out", out, "--workers", "2", "--json")
    assert r.rc == 0, r.err[-3000:]
    r.path = out
    return r


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _stop(p: subprocess.Popen, wait: float = 20.0) -> None:
    if p.poll() is None:
        p.terminate()
        try:
            p.wait(wait)
        except subprocess.TimeoutExpired:
            pass
    try:  # the nanny's worker process and resource tracker share the session we started
        os.killpg(p.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass
    try:
        p.wait(5)
    except subprocess.TimeoutExpired:
        pass


@pytest.fixture(scope="module")
def cluster(tmp_path_factory):
    """``dask scheduler`` on 127.0.0.1 and two single-threaded ``dask worker`` (with nannies),
    as separate processes; the workers run in a folder of their own."""
    from distributed import Client

    base = tmp_path_factory.mktemp("cluster")
    cwd = base / "workers_cwd"
    cwd.mkdir()
    port = _free_port()
    addr = f"tcp://127.0.0.1:{port}"
    procs: list[subprocess.Popen] = []
    client = None

    def start(args, name):
        log = open(base / f"{name}.log", "w")
        procs.append(subprocess.Popen([str(DASK), *args], stdout=log, stderr=subprocess.STDOUT, cwd=cwd,
                                      start_new_session=True))
        log.close()

    try:
        start(["scheduler", "--host", "127.0.0.1", "--port", str(port), "--no-dashboard"], "scheduler")
        for i in range(2):
            start(["worker", addr, "--nthreads", "1", "--no-dashboard", "--local-directory", str(base / f"w{i}")],
                  f"worker{i}")
        deadline = time.monotonic() + 60
        while client is None:
            try:
                client = Client(addr, timeout="5s")
            except OSError:
                if time.monotonic() > deadline or procs[0].poll() is not None:
                    raise RuntimeError((base / "scheduler.log").read_text()[-2000:]) from None
                time.sleep(0.3)
        client.wait_for_workers(2, timeout=60)
        yield SimpleNamespace(address=addr, client=client, workers_cwd=cwd, logs=base)
    finally:
        if client is not None:
            client.close()
        for p in reversed(procs):  # workers first, then the scheduler
            _stop(p)


# ----------------------------------------------------------------------------- end to end
def test_run_writes_chunk_points_cog_dems_and_run_json(survey, baseline):
    from workstation.io.catalog import build_catalog
    from workstation.raster.grid import GridSpec

    out, doc = baseline.path, baseline.json
    assert doc["status"] == "complete" and doc["failures"] == []
    assert totals(doc) == {"index": 4, "points": 4, "rasters": 4, "mosaic": 2} == ran(doc)
    assert doc["catalog"]["files"] == 4 and doc["catalog"]["points"] == 162_000 and doc["chunks"]["count"] == 4
    assert doc["phases"]["points"]["points"] == 162_000
    rj = run_json(out)
    assert rj["status"] == "complete" and rj["phases"] == doc["phases"]
    assert len(rj["tasks"]) == 14 and all(t["status"] == "done" for t in rj["tasks"].values())

    # points: one LAZ per chunk, each holding its own points only; together exactly the inputs
    assert laz_files(out) == sorted(f"{c}.laz" for c in CHUNKS)
    parts = []
    for name in laz_files(out):
        c = read_cloud(out / "ground" / name)
        x0, y0 = (float(v) for v in name[:-4].split("_"))
        assert np.all((c.xyz[:, 0] >= x0) & (c.xyz[:, 0] < x0 + 100) & (c.xyz[:, 1] >= y0) & (c.xyz[:, 1] < y0 + 100))
        assert c.crs == CRS
        parts.append(c)
    keys = ("intensity", "return_number", "number_of_returns")

    def table(clouds):
        xyz = np.vstack([c.xyz for c in clouds])
        attrs = {k: np.concatenate([np.asarray(c.attrs[k]) for c in clouds]) for k in (*keys, "classification")}
        o = np.lexsort((xyz[:, 2], xyz[:, 1], xyz[:, 0]))
        return xyz[o], {k: v[o] for k, v in attrs.items()}, o

    inputs = [read_cloud(survey / "tiles" / f"t_{i}_{j}.laz") for i, j in CELLS]
    ix, ia, order = table(inputs)
    gx, ga, _ = table(parts)
    np.testing.assert_array_equal(gx, ix)
    for k in keys:
        np.testing.assert_array_equal(ga[k], ia[k], err_msg=k)
    # ground is class 2, the buildings are not
    truth = np.concatenate([tile_points(i, j)[1] for i, j in CELLS])[order]
    cls = ga["classification"]
    assert set(np.unique(cls).tolist()) <= {1, 2}
    assert np.mean(cls[truth] == 2) > 0.97
    assert np.mean(cls[~truth] == 2) < 0.02

    # DEMs: one COG each on the project grid, CRS set
    import rasterio

    cat = build_catalog(sorted((survey / "tiles").glob("*.laz")))
    grid = GridSpec.from_bounds(*cat.bounds, 1.0)
    for kind in ("dtm", "dsm"):
        path = out / "dem" / f"{kind}.tif"
        with rasterio.open(path) as src:
            assert src.crs.to_epsg() == 32633
            assert tuple(src.transform)[:6] == grid.transform and src.shape == grid.shape
            assert src.nodata == -9999.0 and src.dtypes[0] == "float32"
            with rasterio.Env() as env:
                if "COG" in env.drivers():
                    assert src.tags(ns="IMAGE_STRUCTURE").get("LAYOUT") == "COG"
    dtm, t, _, _ = read_dem(out / "dem" / "dtm.tif")
    rows, cols = np.mgrid[0 : dtm.shape[0], 0 : dtm.shape[1]]
    xc, yc = t.c + (cols + 0.5) * t.a, t.f + (rows + 0.5) * t.e
    ok = dtm != -9999.0
    assert ok.mean() > 0.95
    err = np.abs(dtm[ok] - terrain(xc[ok], yc[ok]))
    assert np.median(err) < 0.03 and np.percentile(err, 99) < 0.1
    dsm, _, _, _ = read_dem(out / "dem" / "dsm.tif")
    for (a, b), (c, d), h in BUILDINGS:
        r, k = int((t.f - (Y0 + (c + d) / 2)) // 1), int((X0 + (a + b) / 2 - t.c) // 1)
        roof = float(terrain(X0 + (a + b) / 2, Y0 + (c + d) / 2)) + h
        assert abs(dsm[r, k] - roof) < 0.1
        assert abs(dtm[r, k] - terrain(xc[r, k], yc[r, k])) < 0.15  # the building is not in the DTM


def test_chunked_dtm_matches_the_whole_area_dtm_at_the_seams(survey, baseline, tmp_path):
    from workstation.cli.main import main
    from workstation.core.cloud import concatenate
    from workstation.io import write_cloud
    from workstation.raster.dem import DemParams, build_dem

    merged = tmp_path / "merged.laz"
    write_cloud(concatenate([read_cloud(p) for p in sorted((survey / "tiles").glob("*.laz"))]), merged)
    assert main(["ground", str(merged), "-o", str(tmp_path / "ground.laz"), "--method", "smrf"]) == 0
    whole = read_cloud(tmp_path / "ground.laz")
    ref = build_dem(whole, DemParams(kind="dtm", resolution=1.0))
    mos, t, _, _ = read_dem(baseline.path / "dem" / "dtm.tif")
    mos = np.where(mos == -9999.0, np.nan, mos)
    # place the mosaic's cells on the reference grid through the two transforms
    ra, rc_, rf = ref.transform[0], ref.transform[2], ref.transform[5]
    assert ra == t.a == 1.0
    dc, dr = round((t.c - rc_) / ra), round((rf - t.f) / ra)
    rows, cols = np.mgrid[0 : mos.shape[0], 0 : mos.shape[1]]
    rr, cc = rows + dr, cols + dc
    inside = (rr >= 0) & (rr < ref.array.shape[0]) & (cc >= 0) & (cc < ref.array.shape[1])
    refv = np.full(mos.shape, np.nan)
    refv[inside] = ref.array[rr[inside], cc[inside]]
    xc, yc = t.c + (cols + 0.5), t.f - (rows + 0.5)
    near = (np.abs(xc - 500100.0) < 5.0) | (np.abs(yc - 4000100.0) < 5.0)  # the inner chunk edges
    both = near & np.isfinite(mos) & np.isfinite(refv)
    assert both.sum() > 0.9 * near.sum() > 3000
    d = mos[both] - refv[both]
    assert np.sqrt(np.mean(d**2)) < 0.01
    # and the chunked ground classes are those of the whole-area run
    parts = concatenate([read_cloud(baseline.path / "ground" / n) for n in laz_files(baseline.path)])
    oa = np.lexsort(parts.xyz.T[::-1])
    ob = np.lexsort(whole.xyz.T[::-1])
    np.testing.assert_array_equal(parts.xyz[oa], whole.xyz[ob])
    assert np.mean(parts.attrs["classification"][oa] != whole.attrs["classification"][ob]) < 1e-3


# ----------------------------------------------------------------------------- re-runs
def test_rerun_with_nothing_changed_runs_nothing(survey, baseline, tmp_path):
    out = copy_out(baseline.path, tmp_path / "out")
    before = snapshot(out)
    r = ws("run", survey / "project.toml", "--out", out, "--workers", "1", "--json")
    assert r.rc == 0, r.err[-2000:]
    assert r.json["status"] == "complete"
    assert set(ran(r.json).values()) == {0} and totals(r.json) == totals(baseline.json)
    assert all(c["seconds"] == 0 for c in r.json["phases"].values())
    assert set(ran(run_json(out)).values()) == {0} and run_json(out)["status"] == "complete"
    assert snapshot(out) == before  # bytes and mtimes of every output and cache file
    # stopping after ground: only index and points are planned, both up to date
    r = ws("run", survey / "project.toml", "--out", out, "--end-with", "ground", "--json")
    assert r.rc == 0 and r.json["status"] == "complete"
    assert ran(r.json) == {"index": 0, "points": 0}
    assert snapshot(out) == before


def test_changed_dem_resolution_reruns_rasters_and_mosaics_only(survey, baseline, cluster, tmp_path):
    out = copy_out(baseline.path, tmp_path / "out")
    before = snapshot(out)
    r = ws("run", survey / "project_res2.toml", "--out", out, "--scheduler", cluster.address, "--json")
    assert r.rc == 0, r.err[-2000:]
    assert r.json["status"] == "complete"
    assert ran(r.json) == {"index": 0, "points": 0, "rasters": 4, "mosaic": 2}
    after = snapshot(out)
    kept = [k for k in before if k.startswith(("ground/", ".ws-cache/"))]
    assert kept and all(after[k] == before[k] for k in kept)
    assert after["dem/dtm.tif"][1] != before["dem/dtm.tif"][1]
    _, t, _, _ = read_dem(out / "dem" / "dtm.tif")
    assert t.a == 2.0 and t.c % 2.0 == 0


def test_changed_ground_parameters_rerun_points_rasters_and_mosaics(survey, baseline, cluster, tmp_path):
    out = copy_out(baseline.path, tmp_path / "out")
    before = snapshot(out)
    r = ws("run", survey / "project_cell.toml", "--out", out, "--scheduler", cluster.address, "--json")
    assert r.rc == 0, r.err[-2000:]
    assert ran(r.json) == {"index": 0, "points": 4, "rasters": 4, "mosaic": 2}
    assert r.json["failures"] == [] and r.json["status"] == "complete"
    after = snapshot(out)
    assert all(after[f"ground/{n}"][1] != before[f"ground/{n}"][1] for n in laz_files(out))
    assert all(after[k] == before[k] for k in before if k.startswith(".ws-cache/index/"))


def test_rerun_from_dem_forces_rasters_and_mosaics(survey, baseline, cluster, tmp_path):
    out = copy_out(baseline.path, tmp_path / "out")
    before = snapshot(out)
    r = ws("run", survey / "project.toml", "--out", out, "--scheduler", cluster.address, "--rerun-from", "dem",
           "--json")
    assert r.rc == 0, r.err[-2000:]
    assert r.json["status"] == "complete"
    assert ran(r.json) == {"index": 0, "points": 0, "rasters": 4, "mosaic": 2}
    after = snapshot(out)
    assert all(after[k] == before[k] for k in before if k.startswith(("ground/", ".ws-cache/")))
    for kind in ("dtm", "dsm"):
        assert after[f"dem/{kind}.tif"][1] != before[f"dem/{kind}.tif"][1]
    assert_same_outputs(baseline.path, out)


def test_dry_run_runs_nothing_and_writes_nothing(survey, baseline, tmp_path):
    out = copy_out(baseline.path, tmp_path / "out")
    before = snapshot(out, skip=())
    r = ws("run", survey / "project_cell.toml", "--out", out, "--dry-run", "--json")
    assert r.rc == 0, r.err[-2000:]
    assert ran(r.json) == {"index": 0, "points": 4, "rasters": 4, "mosaic": 2}
    assert snapshot(out, skip=()) == before  # run.json included
    fresh = tmp_path / "fresh"
    r = ws("run", survey / "project.toml", "--out", fresh, "--dry-run", "--json")
    assert r.rc == 0
    assert ran(r.json) == totals(r.json) == {"index": 4, "points": 4, "rasters": 4, "mosaic": 2}
    assert not fresh.exists() or not [p for p in fresh.rglob("*") if p.is_file()]
    assert "dry run" in r.err


def test_dry_run_json_says_planned(survey, tmp_path):
    r = ws("run", survey / "project.toml", "--out", tmp_path / "out", "--dry-run", "--json")
    assert r.rc == 0 and r.json["phases"]["points"]["run"] == 4
    assert r.json["status"] == "planned"


def test_deleted_chunk_output_is_made_again_with_its_rasters(survey, baseline, cluster, tmp_path):
    out = copy_out(baseline.path, tmp_path / "out")
    gone = out / "ground" / f"{CHUNKS[0]}.laz"
    rec = run_json(out)["tasks"][f"points/{CHUNKS[0]}"]
    assert rec["status"] == "done" and str(gone.relative_to(out)) in rec["outputs"]  # relative to OUT
    before = snapshot(out)
    gone.unlink()
    r = ws("run", survey / "project.toml", "--out", out, "--scheduler", cluster.address, "--json")
    assert r.rc == 0, r.err[-2000:]
    # the chunk, every raster task whose buffer reaches it (all four here) and the mosaics
    assert ran(r.json) == {"index": 0, "points": 1, "rasters": 4, "mosaic": 2}
    assert r.json["failures"] == [] and r.json["status"] == "complete"
    after = snapshot(out)
    assert all(after[f"ground/{c}.laz"] == before[f"ground/{c}.laz"] for c in CHUNKS[1:])
    assert_same_outputs(baseline.path, out)


def test_corrupt_run_json_reruns_everything(survey, baseline, cluster, tmp_path):
    out = copy_out(baseline.path, tmp_path / "out")
    (out / "run.json").write_bytes(b"\x89PNG\r\n\x1a\n" + bytes(range(256)) * 4)
    r = ws("run", survey / "project.toml", "--out", out, "--scheduler", cluster.address, "--json")
    assert r.rc == 0, r.err[-2000:]
    assert "Traceback" not in r.err
    assert r.json["status"] == "complete" and ran(r.json) == totals(r.json)
    assert run_json(out)["status"] == "complete"
    assert_same_outputs(baseline.path, out)


# ----------------------------------------------------------------------------- bad inputs
@pytest.fixture(scope="module")
def bad_tile_run(survey, tmp_path_factory) -> SimpleNamespace:
    """The four good tiles and a fifth, 270 m east of them, whose LAZ point data is cut short."""
    folder = tmp_path_factory.mktemp("badtile")
    (folder / "tiles").mkdir()
    for p in (survey / "tiles").glob("*.laz"):
        shutil.copy2(p, folder / "tiles" / p.name)
    bad = write_tiles(folder / "tiles", ((4, 0),))[0]
    data = bad.read_bytes()
    bad.write_bytes(data[: int(len(data) * 0.6)])
    write_project(folder)
    r = ws("run", folder / "project.toml", "--out", folder / "out", "--workers", "1", "--json")
    r.path, r.bad = folder / "out", bad
    return r


def test_bad_tile_fails_alone_and_is_reported(bad_tile_run, baseline):
    r = bad_tile_run
    assert r.json is not None, r.err[-3000:]
    assert r.json["status"] == "incomplete"
    (fail,) = r.json["failures"]
    assert fail["task"] == "index/t_4_0.laz" and str(r.bad) in fail["error"]
    rj = run_json(r.path)
    assert rj["status"] == "incomplete"
    rec = rj["tasks"]["index/t_4_0.laz"]
    assert rec["status"] == "failed" and "t_4_0.laz" in rec["error"]
    assert rj["failures"] == r.json["failures"]
    # the four chunks of the bad tile are skipped, the four of the good tiles written as without it
    assert r.json["phases"]["points"]["failed"] == 4 and r.json["phases"]["points"]["total"] == 8
    assert laz_files(r.path) == sorted(f"{c}.laz" for c in CHUNKS)
    assert_same_points(baseline.path, r.path, laz_files(r.path))
    dtm, t, _, _ = read_dem(r.path / "dem" / "dtm.tif")
    good = dtm[int((t.f - 4000190) // 1), : int((500190 - t.c) // 1)]
    assert np.all(good != -9999.0)
    assert rj["tasks"]["mosaic/dtm"]["status"] == "partial"  # made of the tiles there are; re-run next time
    assert "failed index/t_4_0.laz" in r.err.replace("\n", " ")


def test_bad_tile_exit_code_is_3(bad_tile_run):
    assert bad_tile_run.json["status"] == "incomplete"
    assert bad_tile_run.rc == 3


def test_bad_tile_leaves_no_traceback_on_stderr(bad_tile_run):
    assert bad_tile_run.json["status"] == "incomplete"
    assert "Traceback" not in bad_tile_run.err and 'File "' not in bad_tile_run.err


def test_cli_refuses_mixed_crs_and_bad_keys_naming_them(survey, tmp_path):
    (tmp_path / "tiles").mkdir()
    for p in (survey / "tiles").glob("t_0_*.laz"):
        shutil.copy2(p, tmp_path / "tiles" / p.name)
    write_tiles(tmp_path / "tiles", ((1, 0),), crs="EPSG:32634")
    write_project(tmp_path)
    r = ws("run", tmp_path / "project.toml", "--out", tmp_path / "out", "--workers", "1")
    assert r.rc == 1
    assert "t_1_0.laz" in r.err and "EPSG:32634" in r.err and "EPSG:32633" in r.err
    assert "Traceback" not in r.err
    assert not (tmp_path / "out" / "run.json").exists()
    # a misspelt stage key is refused naming the table and the key
    write_project(survey, "project_typo.toml", ground="cel = 1.5")
    r = ws("run", survey / "project_typo.toml", "--out", tmp_path / "out2", "--dry-run")
    assert r.rc == 1 and "stages.ground" in r.err and "cel" in r.err and "Traceback" not in r.err
    # --workers sizes a local cluster: refused with --scheduler (usage error)
    r = ws("run", survey / "project.toml", "--scheduler", "tcp://127.0.0.1:9", "--workers", "2")
    assert r.rc == 2 and "--workers" in r.err


# ----------------------------------------------------------------------------- Dask clusters
def test_external_scheduler_gives_the_same_outputs(survey, baseline, cluster, tmp_path):
    out = tmp_path / "out"
    r = ws("run", survey / "project.toml", "--out", out, "--scheduler", cluster.address, "--json")
    assert r.rc == 0, r.err[-2000:]
    assert r.json["status"] == "complete" and ran(r.json) == totals(r.json)
    assert_same_outputs(baseline.path, out)
    # nothing was written where the workers run
    assert not [p for p in cluster.workers_cwd.rglob("*") if p.is_file()]


def test_relative_out_with_an_external_scheduler(survey, baseline, cluster):
    r = ws("run", "project.toml", "--out", "relout", "--scheduler", cluster.address, "--json", cwd=survey)
    assert r.rc == 0, r.err[-2000:]
    assert r.json["status"] == "complete"
    assert laz_files(survey / "relout") == laz_files(baseline.path)
    assert (survey / "relout" / "dem" / "dtm.tif").exists()
    assert not (cluster.workers_cwd / "relout").exists()


def test_killed_worker_gives_the_same_outputs(survey, baseline, cluster, tmp_path):
    client = cluster.client
    client.wait_for_workers(2, timeout=60)
    pids = client.run(os.getpid)  # worker address -> pid of the worker process under its nanny
    out = tmp_path / "out"
    env = dict(os.environ, PYTHONHASHSEED="7", WS_PROGRESS="0")
    with open(tmp_path / "stdout", "w") as so, open(tmp_path / "stderr", "w") as se:
        proc = subprocess.Popen([str(WS), "run", str(survey / "project.toml"), "--out", str(out), "--scheduler",
                                 cluster.address, "--json"], stdout=so, stderr=se, env=env)
    killed = None
    try:
        deadline = time.monotonic() + 60
        while killed is None and proc.poll() is None and time.monotonic() < deadline:
            for worker, keys in client.processing().items():
                if worker in pids and any(str(k).startswith("points/") for k in keys):
                    os.kill(pids[worker], signal.SIGKILL)  # mid-chunk; the nanny starts a new one
                    killed = (worker, keys)
                    break
            time.sleep(0.01)
        rc = proc.wait(timeout=150)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait(10)
    err = (tmp_path / "stderr").read_text()
    assert killed is not None, "the run ended before a worker could be killed"
    assert rc == 0, err[-3000:]
    doc = json.loads((tmp_path / "stdout").read_text())
    assert doc["status"] == "complete" and doc["failures"] == [] and ran(doc) == totals(doc)
    assert_same_outputs(baseline.path, out)
    client.wait_for_workers(2, timeout=60)
    assert pids[killed[0]] not in client.run(os.getpid).values()


@pytest.mark.parametrize("sig, code", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_interrupted_run_leaves_nothing_half_written_and_resumes(survey, baseline, cluster, tmp_path, sig, code):
    """Ctrl-C (or SIGTERM) once the first task is done: exit 128 + n, no temporary file left,
    run.json keeps the finished tasks, and the next run does only the rest, with the same outputs."""
    out = tmp_path / "out"
    env = dict(os.environ, WS_PROGRESS="0")
    p = subprocess.Popen([str(WS), "run", str(survey / "project.toml"), "--out", str(out), "--scheduler",
                          cluster.address], stderr=subprocess.PIPE, text=True, env=env)
    t0 = time.monotonic()
    # as soon as the runner has recorded a first finished task (it saves run.json at once then)
    def recorded():
        try:
            return '"status": "done"' in (out / "run.json").read_text()
        except OSError:
            return False

    while not recorded() and p.poll() is None and time.monotonic() - t0 < 120:
        time.sleep(0.02)
    p.send_signal(sig)
    _, err = p.communicate(timeout=60)
    if p.returncode == 0:
        pytest.skip("the run finished before the signal arrived")
    assert p.returncode == code, err[-2000:]
    assert "Traceback" not in err
    def hidden():
        h = [q for q in out.rglob(".*") if q.is_file() and ".ws-cache" not in q.parts]
        return h + ([q for q in (out / ".ws-cache").rglob(".*")] if (out / ".ws-cache").exists() else [])

    # A task already running on the external workers when the run stopped goes on to its end (Dask
    # cannot stop a running thread) and publishes or removes its temporary output then.
    t1 = time.monotonic()
    while hidden() and time.monotonic() - t1 < 30:
        time.sleep(0.1)
    assert not hidden(), hidden()
    done = [t for t, rec in run_json(out)["tasks"].items() if rec["status"] == "done"]
    assert done  # the chunks finished before the signal are recorded
    r = ws("run", survey / "project.toml", "--out", out, "--scheduler", cluster.address, "--json")
    assert r.rc == 0 and r.json["status"] == "complete", r.err[-2000:]
    assert sum(ran(r.json).values()) <= sum(totals(r.json).values()) - len(done)
    assert_same_outputs(out, baseline.path)
