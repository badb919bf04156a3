"""`ws ground` and `ws evaluate` end to end on small files."""

from __future__ import annotations

import json

import numpy as np
import pytest
from ground_synth import terrain_with_boxes

from workstation.cli.main import main
from workstation.core.cloud import Cloud
from workstation.io import read_cloud, write_cloud


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    d = tmp_path_factory.mktemp("ground_cli")
    xyz, truth = terrain_with_boxes(seed=5, size=60.0)
    n = xyz.shape[0]
    src = Cloud(xyz, {"intensity": np.arange(n) % 1000}, crs="EPSG:32632")
    write_cloud(src, d / "in.las")
    ref = src.with_attrs(classification=np.where(truth, 2, 1))
    write_cloud(ref, d / "ref.las")
    # the same reference as an ISPRS text sample (label 0 ground, 1 object)
    np.savetxt(d / "ref.txt", np.column_stack([xyz, (~truth).astype(int)]), fmt="%.3f\t%.3f\t%.3f\t%d")
    return d, truth


def test_ground_then_evaluate_json(files, capsys):
    d, truth = files
    rc = main(["ground", str(d / "in.las"), "-o", str(d / "out.las"), "--method", "smrf", "--json"])
    assert rc == 0
    info = json.loads(capsys.readouterr().out)
    assert info["method"] == "smrf" and info["params"]["window"] == 18.0
    assert info["ground_count"] == pytest.approx(int(truth.sum()), rel=0.03)
    out = read_cloud(d / "out.las")
    assert np.array_equal(np.asarray(out.attrs["intensity"]), np.arange(out.n) % 1000)
    rc = main(["evaluate", str(d / "out.las"), "--reference", str(d / "ref.las"), "--json",
               "--plot-dir", str(d / "plots")])
    assert rc == 0
    ev = json.loads(capsys.readouterr().out)
    for k in ("type1", "type2", "total_error", "kappa", "confusion", "classes"):
        assert k in ev
    assert ev["total_error"] < 0.02 and ev["kappa"] > 0.9
    assert ev["classes"] == [1, 2, 7]  # the scene's 30 m deep outlier: class 7 from the low-noise step
    assert sum(map(sum, ev["confusion"])) == out.n
    assert (d / "plots" / "errors_plan.png").stat().st_size > 1000
    assert (d / "plots" / "confusion.png").stat().st_size > 1000
    # ISPRS text reference gives the same figures
    rc = main(["evaluate", str(d / "out.las"), "--reference", str(d / "ref.txt"), "--json"])
    assert rc == 0
    ev2 = json.loads(capsys.readouterr().out)
    assert ev2["total_error"] == pytest.approx(ev["total_error"])


def test_ground_preset_options_and_refusals(files, capsys):
    d, _ = files
    out = d / "out_pmf.laz"
    rc = main(["ground", str(d / "in.las"), "-o", str(out), "--method", "pmf", "--preset", "urban",
               "--slope", "0.4", "--hag", "--json"])
    assert rc == 0
    info = json.loads(capsys.readouterr().out)
    assert info["params"]["slope"] == 0.4 and info["params"]["max_window"] == 49.0
    c = read_cloud(out)
    assert "hag" in c.attrs
    # refuses to overwrite, and rejects an option of another method (usage error)
    assert main(["ground", str(d / "in.las"), "-o", str(out), "--method", "pmf"]) == 1
    assert main(["ground", str(d / "in.las"), "-o", str(d / "x.las"), "--method", "pmf", "--rigidness", "2"]) == 2
    assert main(["ground", str(d / "in.las"), "-o", str(d / "x.las"), "--method", "pmf", "--trend-slope", "1"]) == 2
    capsys.readouterr()
    rc = main(["ground", str(d / "in.las"), "-o", str(d / "out_smrf.laz"), "--method", "smrf", "--trend-slope", "1",
               "--json"])
    assert rc == 0 and json.loads(capsys.readouterr().out)["params"]["trend_slope"] == 1.0
    # the understorey step is auto's, on by default
    assert main(["ground", str(d / "in.las"), "-o", str(d / "x.las"), "--method", "smrf", "--no-understorey"]) == 2
    rc = main(["ground", str(d / "in.las"), "-o", str(d / "out_auto_nu.laz"), "--method", "auto", "--no-understorey",
               "--json"])
    info = json.loads(capsys.readouterr().out)
    assert rc == 0 and info["params"]["understorey"] is False and info["params"]["understorey_params"]["threshold"] == 0.2
    assert info["params"]["raised_patches"] is True and info["params"]["patch_params"]["step"] == 1.0
    # so is the raised-patch test
    assert main(["ground", str(d / "in.las"), "-o", str(d / "x.las"), "--method", "csf", "--no-raised-patches"]) == 2
    rc = main(["ground", str(d / "in.las"), "-o", str(d / "out_auto_np.laz"), "--method", "auto", "--no-raised-patches",
               "--json"])
    assert rc == 0 and json.loads(capsys.readouterr().out)["params"]["raised_patches"] is False
    # and the riser fill
    assert main(["ground", str(d / "in.las"), "-o", str(d / "x.las"), "--method", "ptd", "--no-risers"]) == 2
    rc = main(["ground", str(d / "in.las"), "-o", str(d / "out_auto_nr.laz"), "--method", "auto", "--no-risers",
               "--json"])
    info = json.loads(capsys.readouterr().out)
    assert rc == 0 and info["params"]["risers"] is False and info["params"]["riser_params"]["min_gradient"] == 1.0


def test_evaluate_text_output(files, capsys):
    d, _ = files
    assert main(["ground", str(d / "in.las"), "-o", str(d / "out_auto.las"), "--method", "auto"]) == 0
    capsys.readouterr()
    assert main(["evaluate", str(d / "out_auto.las"), "--reference", str(d / "ref.las")]) == 0
    text = capsys.readouterr().out
    assert "Type I" in text and "kappa" in text and "Ground" in text


def test_ground_water_option(tmp_path, capsys):
    """ws ground --water: the filter's ground on a level pond in its basin becomes class 9; the
    banks stay ground; without the flag the pond is ground."""
    from test_ground_water import pond_scene

    xyz, pond = pond_scene(seed=10)
    src = tmp_path / "pond.laz"
    write_cloud(Cloud(xyz + [500000, 5000000, 0], crs="EPSG:32632"), src)
    for method in ("smrf", "ml"):  # the classifier's ground keeps water as bare earth, as the filters do
        out = tmp_path / f"w_{method}.laz"
        assert main(["ground", str(src), "-o", str(out), "--method", method, "--water", "--json"]) == 0
        res = json.loads(capsys.readouterr().out)
        cls = np.asarray(read_cloud(out).attrs["classification"])
        assert (cls[pond] == 9).mean() > 0.9 and res["water_count"] == int((cls == 9).sum())
        assert (cls[~pond] == 2).mean() > 0.98
    plain = tmp_path / "g.laz"
    assert main(["ground", str(src), "-o", str(plain)]) == 0
    assert not (np.asarray(read_cloud(plain).attrs["classification"]) == 9).any()
