import json

from workstation.cli.main import main
from workstation.io import read_cloud
from workstation.photogrammetry.rigs import box_wall_rig


def test_sfm_dense_flag_orients_then_densifies(tmp_path, capsys):
    box_wall_rig(tmp_path / "rig", n=8, width=320, height=240, focal_px=300.0)
    wd = tmp_path / "wd"
    rc = main(["sfm", str(tmp_path / "rig" / "images"), "-o", str(wd), "--dense", "--device", "cpu", "--json"])
    assert rc == 0
    out = json.loads(capsys.readouterr().out)
    assert out["registered"] == 8
    assert out["dense"]["device"] == "cpu" and out["dense"]["points"] > 5000
    fused = read_cloud(wd / "dense" / "fused.ply")
    assert fused.n == out["dense"]["points"]
    assert "rgb" in fused.attrs and "normal" in fused.attrs
    # the dense cloud sits where the sparse one does (same SfM frame)
    sparse = read_cloud(wd / "sparse.ply")
    lo, hi = sparse.xyz.min(axis=0), sparse.xyz.max(axis=0)
    pad = 0.2 * (hi - lo)
    inside = ((fused.xyz > lo - pad) & (fused.xyz < hi + pad)).all(axis=1)
    assert inside.mean() > 0.95
