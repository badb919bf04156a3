"""Options valid alone but impossible for this data or machine: clear errors before the work."""

import numpy as np
import pytest

from workstation.cli.main import main
from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.ground.evaluate import evaluate_clouds
from workstation.io import write_cloud


@pytest.fixture
def laz(tmp_path, small_cloud):
    p = tmp_path / "a.laz"
    write_cloud(small_cloud, p)
    return p


def _run(capsys, *args):
    rc = main([str(a) for a in args])
    return rc, capsys.readouterr().err


def test_info_density_cell_too_fine_for_the_extent(capsys, laz):
    rc, err = _run(capsys, "info", laz, "--density-cell", "1e-9")
    assert rc == 1 and "--density-cell" in err


def test_info_default_density_cell_on_huge_extent_still_summarises(tmp_path, capsys):
    p = tmp_path / "far.xyz"
    p.write_text("x y z\n500000 4000000 100\n1e12 1e12 100\n500010 4000010 101\n")
    rc, _ = _run(capsys, "info", p)
    assert rc == 0


def test_render_unknown_background_is_a_usage_error(tmp_path, capsys, laz):
    rc, err = _run(capsys, "render", laz, "-o", tmp_path / "r.png", "--background", "notacolour")
    assert rc == 2 and "--background" in err and "#rrggbb" in err


def test_render_size_out_of_range_is_a_usage_error(tmp_path, capsys, laz):
    rc, err = _run(capsys, "render", laz, "-o", tmp_path / "r.png", "--size", "0x100")
    assert rc == 2 and "--size" in err


def test_classify_on_cuda_without_cuda_names_device(tmp_path, capsys, laz):
    import torch

    if torch.cuda.is_available():
        pytest.skip("this machine has CUDA")
    rc, err = _run(capsys, "classify", laz, "-o", tmp_path / "c.laz", "--device", "cuda")
    assert rc == 1 and "--device" in err
    assert not (tmp_path / "c.laz").exists()


def test_evaluate_refuses_a_small_matched_fraction(rng):
    xyz = rng.uniform(0, 100, (3000, 3))
    ref = Cloud(xyz, {"classification": np.full(3000, 2, np.uint8)}, meta={"source": "ref.laz"})
    pred = Cloud(np.vstack([xyz[:1], xyz[1:] + 50.0]), {"classification": np.full(3000, 2, np.uint8)},
                 meta={"source": "pred.laz"})
    with pytest.raises(InvalidInputError, match="only 1 of 3000 points matched") as e:
        evaluate_clouds(pred, ref)
    assert "pred.laz" in str(e.value) and "tolerance" in e.value.hint
    ev, _, _ = evaluate_clouds(pred, ref, min_matched=0.0)  # asked for explicitly
    assert ev.n_matched == 1
