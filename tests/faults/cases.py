"""The cases of the fault corpus, by family: damaged readers, bad options, bad outputs,
degenerate data and paths that leave their folder. See :mod:`tests.faults.corpus`."""

from __future__ import annotations

import importlib
import math
from pathlib import Path

import click
import numpy as np

from .corpus import (
    CLOUDS, NOT_UTF8, RANDOM, Case, both, flip, make_dir, poke, replace_text, truncate, write,
)

# A command line that succeeds on the good inputs, per command (the base the option cases
# and the output cases modify).
BASE = {
    "info": ("info", "cloud.laz"),
    "convert": ("convert", "cloud.laz", "out.las"),
    "ground": ("ground", "cloud.laz", "-o", "out.laz"),
    "classify": ("classify", "cloud.laz", "-o", "out.laz"),
    "dem": ("dem", "cloud.laz", "-o", "out.tif", "--resolution", "1"),
    "hillshade": ("hillshade", "dem.tif", "-o", "hs.tif"),
    "contours": ("contours", "dem.tif", "-o", "c.geojson"),
    "mesh": ("mesh", "cloud.laz", "-o", "out.ply", "--method", "delaunay25d"),
    "render": ("render", "cloud.laz", "-o", "out.png"),
    "evaluate": ("evaluate", "cloud.laz", "--reference", "cloud.laz"),
    "register": ("register", "moved.laz", "cloud.laz", "-o", "reg.laz"),
    "merge": ("merge", "cloud.laz", "moved.laz", "-o", "m.laz"),
    "colorize": ("colorize", "cloud.laz", "--reconstruction", ".", "-o", "col.laz"),
    "ortho": ("ortho", ".", "--dsm", "dem.tif", "-o", "ortho.tif"),
    "report": ("report", ".", "-o", "report.html"),
    "run": ("run", "project.toml", "--workers", "1"),
    "simulate": ("simulate", "tls", "-o", "sim.laz"),
    "plan-flight": ("plan-flight",),
    "sfm": ("sfm", "images", "-o", "sfm"),
    "dense": ("dense", "."),
    "train": ("train", "recipe.toml", "-o", "model.pt"),
    "demo": ("demo", "-o", "demo"),
    "crop": ("crop", "cloud.laz", "-o", "crop.laz", "--bounds", "500010,4000010,500040,4000040"),
    "filter": ("filter", "cloud.laz", "-o", "f.laz", "--expr", "Classification == 2"),
    "thin": ("thin", "cloud.laz", "-o", "t.laz", "--voxel", "2"),
    "tile": ("tile", "cloud.laz", "-o", "tiles_out", "--size", "30"),
    "qc": ("qc", "cloud.laz", "-o", "qcdir"),
}
# what ws qc writes into its report folder
QC_FILES = tuple(f"qcdir/{f}" for f in ("qc.json", "report.html", "density.tif", "voids.tif", "voids.geojson",
                                        "dz.tif", "dz_values.tif"))
# the file each command writes in BASE (for the output cases)
WRITES = {"convert": "out.las", "ground": "out.laz", "classify": "out.laz", "dem": "out.tif", "hillshade": "hs.tif",
          "contours": "c.geojson", "mesh": "out.ply", "render": "out.png", "register": "reg.laz", "merge": "m.laz",
          "colorize": "col.laz", "ortho": "ortho.tif", "report": "report.html", "crop": "crop.laz",
          "filter": "f.laz", "thin": "t.laz"}


# --- damaged readers -------------------------------------------------------------------------

def _las_mutations(name: str) -> list:
    """Header mutations of a LAS 1.4 file (offsets of the public header block)."""
    return [
        ("truncated-half", truncate(name, 0.5), "error"),
        ("truncated-end", truncate(name, 0.995), "error"),
        ("truncated-header", truncate(name, 100 / 25000), "error"),
        ("empty", write(name, b""), "error"),
        ("random-bytes", write(name, RANDOM), "error"),
        ("text", write(name, b"x y z\n1 2 3\n"), "error"),
        ("count-smaller", both(poke(name, 107, "I", 1000), poke(name, 247, "Q", 1000)), "error"),
        ("count-larger", both(poke(name, 107, "I", 0), poke(name, 247, "Q", 10**12)), "error"),
        ("scale-zero", poke(name, 131, "d", 0.0), "error"),
        ("scale-nan", poke(name, 139, "d", math.nan), "error"),
        ("scale-inf", poke(name, 147, "d", math.inf), "error"),
        ("offset-nan", poke(name, 155, "d", math.nan), "error"),
        ("pdrf-99", poke(name, 104, "B", 99), "error"),
        ("version-1.9", poke(name, 25, "B", 9), "error"),
        ("data-offset-past-end", poke(name, 96, "I", 10**9), "error"),
        ("record-length-3", poke(name, 105, "H", 3), "error"),
        ("flip-guid", flip(name, 8, 16), "any"),
        ("flip-bounds", flip(name, 179, 48), "any"),
        ("directory", make_dir(name), "error"),
    ]


def _text_mutations(name: str, count_key: bytes | None) -> list:
    out = [
        ("truncated-half", truncate(name, 0.5), "any" if name.endswith(".xyz") else "error"),
        ("empty", write(name, b""), "error"),
        ("random-bytes", write(name, RANDOM), "error"),
        ("not-utf8", write(name, NOT_UTF8), "error"),
        ("directory", make_dir(name), "error"),
    ]
    if name.endswith(".ply"):
        out += [("count-not-number", replace_text(name, b"element vertex 3000", b"element vertex abc"), "error"),
                ("count-huge", replace_text(name, b"element vertex 3000", b"element vertex 4000000000000"), "error"),
                ("binary-as-ascii", replace_text(name, b"format binary_little_endian", b"format ascii"), "error"),
                ("unknown-format", replace_text(name, b"format binary_little_endian", b"format binary_middle_endian"),
                 "error")]
    if name.endswith(".pcd"):
        out += [("count-huge", replace_text(name, b"POINTS 3000", b"POINTS 4000000000000"), "error"),
                ("width-huge", replace_text(name, b"WIDTH 3000", b"WIDTH 4000000000000"), "error"),
                ("binary-as-ascii", replace_text(name, b"DATA binary", b"DATA ascii"), "error")]
    if name.endswith(".xyz"):
        out += [("words", write(name, b"500000 4000000 100\nabc def ghi\n"), "error"),
                ("short-line", write(name, b"500000 4000000 100\n500001 4000000\n"), "error")]
    return out


def reader_cases() -> list:
    cases = []
    commands = {
        "info": lambda f: ("info", f),
        "convert": lambda f: ("convert", f, "out.laz"),
        "ground": lambda f: ("ground", f, "-o", "out.laz"),
        "dem": lambda f: ("dem", f, "-o", "out.tif", "--resolution", "1"),
        "qc": lambda f: ("qc", f, "-o", "qcdir"),
    }
    for name in ("cloud.las", "cloud.laz"):
        for mut, dmg, expect in _las_mutations(name):
            for cmd, argv in commands.items():
                cases.append(Case(f"read-{name}-{mut}-{cmd}", argv(name), dmg, expect, names=(name,),
                                  outputs=("out.laz", "out.tif", *QC_FILES)))
    for name in ("cloud.ply", "cloud.pcd", "cloud.xyz"):
        for mut, dmg, expect in _text_mutations(name, None):
            for cmd in ("info", "ground"):
                cases.append(Case(f"read-{name}-{mut}-{cmd}", commands[cmd](name), dmg, expect, names=(name,),
                                  outputs=("out.laz",)))
    for mut, dmg in (("truncated", truncate("dem.tif", 0.5)), ("random", write("dem.tif", RANDOM)),
                     ("empty", write("dem.tif", b"")), ("text", write("dem.tif", b"not a tiff\n"))):
        for cmd in ("hillshade", "contours", "ortho"):
            cases.append(Case(f"read-dem-{mut}-{cmd}", BASE[cmd], dmg, names=("dem.tif",)))
    for mut, dmg in (("truncated", truncate("mesh.ply", 0.5)), ("count-not-number",
                     replace_text("mesh.ply", b"element face", b"element face abc\nelement dummy"))):
        cases.append(Case(f"read-mesh-{mut}-render", ("render", "mesh.ply", "-o", "out.png"), dmg, names=("mesh.ply",)))
    return cases


def text_file_cases() -> list:
    """JSON, CSV and TOML inputs that are not UTF-8, not parseable or not what is expected."""
    bad = {"not-utf8": b"\xff\xfe{\"a\": 1}\n\xff", "not-json": b"{ this is not json", "empty": b""}
    cases = []
    for mut, data in bad.items():
        cases += [
            Case(f"camera-{mut}-sfm", ("sfm", "images", "-o", "sfm", "--camera", "camera.json"),
                 write("camera.json", data), names=("camera.json",)),
            Case(f"cameras-{mut}-colorize", BASE["colorize"], write("cameras.json", data), names=("cameras.json",)),
            Case(f"cameras-{mut}-ortho", BASE["ortho"], write("cameras.json", data), names=("cameras.json",)),
            Case(f"poses-{mut}-merge", (*BASE["merge"], "--poses", "poses.json"), write("poses.json", data),
                 names=("poses.json",)),
            Case(f"pairs-{mut}-register", (*BASE["register"], "--pairs", "pairs.csv", "--method", "pairs"),
                 write("pairs.csv", data), names=("pairs.csv",)),
            Case(f"matrix-{mut}-register", (*BASE["register"], "--init", "matrix.txt"), write("matrix.txt", data),
                 names=("matrix.txt",)),
            Case(f"project-{mut}-run", BASE["run"], write("project.toml", data), names=("project.toml",)),
            *([Case(f"recipe-{mut}-train", BASE["train"], write("recipe.toml", data), names=("recipe.toml",))]
              if data else []),  # an empty recipe is all defaults: valid
            Case(f"gcp-{mut}-sfm", ("sfm", "images", "-o", "sfm", "--gcp", "gcp.csv"), write("gcp.csv", data),
                 names=("gcp.csv",)),
            Case(f"dlt-{mut}-calibrate", ("calibrate", "dlt", "points.csv", "--image-size", "640x480", "-o", "cam.json"),
                 write("points.csv", data), names=("points.csv",)),
            Case(f"checkpoints-{mut}-qc", (*BASE["qc"], "--checkpoints", "cps.csv"), write("cps.csv", data),
                 names=("cps.csv",)),
        ]
    cases += [
        Case("pairs-two-register", (*BASE["register"], "--pairs", "pairs.csv", "--method", "pairs"),
             write("pairs.csv", b"0 0 0 1 1 1\n1 0 0 2 1 1\n"), names=("pairs.csv",)),
        Case("pairs-collinear-register", (*BASE["register"], "--pairs", "pairs.csv", "--method", "pairs"),
             write("pairs.csv", b"0 0 0 1 0 0\n1 0 0 2 0 0\n2 0 0 3 0 0\n3 0 0 4 0 0\n"), names=("pairs.csv",)),
        Case("matrix-3x3-register", (*BASE["register"], "--init", "matrix.txt"),
             write("matrix.txt", b"1 0 0\n0 1 0\n0 0 1\n"), names=("matrix.txt",)),
        Case("matrix-nan-register", (*BASE["register"], "--init", "matrix.txt"),
             write("matrix.txt", b"nan 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n"), names=("matrix.txt",)),
        Case("poses-count-merge", (*BASE["merge"], "--poses", "poses.json"), write("poses.json", b"[]"),
             names=("poses.json",)),
        Case("project-no-inputs-run", BASE["run"], write("project.toml", b"[chunks]\nsize = 100\n"),
             names=("project.toml",)),
        Case("project-bad-key-run", BASE["run"], write("project.toml", b"[inputs]\nclouds = ['tiles/*.laz']\n"
                                                                     b"[stages.dem]\nresolutoin = 1\n"),
             names=("project.toml",)),
        Case("project-no-match-run", BASE["run"], write("project.toml", b"[inputs]\nclouds = ['none/*.laz']\n"),
             names=("project.toml",)),
        Case("checkpoints-words-qc", (*BASE["qc"], "--checkpoints", "cps.csv"),
             write("cps.csv", b"id,x,y,z,cover\ncp1,abc,4000020,100,open terrain\n"), names=("cps.csv",)),
        Case("checkpoints-cover-qc", (*BASE["qc"], "--checkpoints", "cps.csv"),
             write("cps.csv", b"id,x,y,z,cover\ncp1,500020,4000020,100,lava lamp\n"), names=("cps.csv",)),
        Case("spec-unknown-qc", (*BASE["qc"], "--spec", "usgs-ql9"), names=("--spec",)),
        Case("dlt-degenerate-calibrate", ("calibrate", "dlt", "points.csv", "--image-size", "640x480", "-o", "cam.json"),
             write("points.csv", b"".join(b"p%d %d 0 0 %d 0\n" % (i, i, i) for i in range(12))), names=("points.csv",)),
    ]
    return cases


# --- paths written inside files ----------------------------------------------------------

def _cameras_path(new: bytes):
    return replace_text("cameras.json", b'"images/img_1.png"', new)


def path_cases() -> list:
    out = []
    for label, p in (("dotdot", b'"../../../../etc/hostname"'), ("absolute", b'"/etc/hostname"')):
        out += [Case(f"escape-{label}-ortho", BASE["ortho"], _cameras_path(p), names=("cameras.json",)),
                Case(f"escape-{label}-colorize", BASE["colorize"], _cameras_path(p), names=("cameras.json",))]
    out.append(Case("escape-survey-scene-simulate", ("simulate", "tls", "-o", "sim.laz", "--config", "sub/survey.toml"),
                    both(make_dir("sub"), write("sub/survey.toml", b'[survey]\nscene = "../../evil.toml"\n')),
                    names=("survey.toml",)))
    out.append(Case("escape-project-run", ("run", "sub/project.toml", "--workers", "1"),
                    both(make_dir("sub"), write("sub/project.toml", b"[inputs]\nclouds = ['../tiles/*.laz']\n")),
                    names=("project.toml",)))
    return out


# --- bad options -------------------------------------------------------------------------------

def _bad_values(t) -> list:
    """Values a numeric option type must refuse: NaN, a word, and one past each bound."""
    vals = ["nan", "abc"]
    if getattr(t, "sentinel", None) is not None:  # min - 1 is the sentinel's meaning (-1 = full size)
        return vals
    lo, hi = getattr(t, "min", None), getattr(t, "max", None)
    if lo is not None:
        vals.append(str(lo - 1) if isinstance(lo, int) else repr(lo - 1.0 if not getattr(t, "min_open", False) else lo))
    if hi is not None:
        vals.append(str(hi + 1) if isinstance(hi, int) else repr(hi + 1.0 if not getattr(t, "max_open", False) else hi))
    return vals


def option_cases() -> list:
    from workstation.cli.main import COMMANDS

    cases = []
    for name, (target, _) in sorted(COMMANDS.items()):
        if name not in BASE or name in ("demo",):
            continue
        mod, attr = target.split(":")
        cmd = getattr(importlib.import_module(mod), attr)
        for p in cmd.params:
            if not isinstance(p, click.Option) or not isinstance(p.type, (click.types.IntParamType,
                                                                          click.types.FloatParamType)):
                continue
            opt = max(p.opts, key=len)
            for v in _bad_values(p.type):
                argv = (*BASE[name], opt, *([v] * max(p.nargs, 1)))
                cases.append(Case(f"option-{name}{opt}={v}", argv, names=(opt,)))
    return cases


def data_option_cases() -> list:
    """Options valid in general but absurd for this data: refused from an estimate, quickly."""
    return [
        Case("dem-resolution-tiny", ("dem", "cloud.laz", "-o", "out.tif", "--resolution", "1e-6"), names=("--resolution",)),
        Case("ground-cell-tiny", ("ground", "cloud.laz", "-o", "out.laz", "--cell", "1e-6"), names=("--cell",)),
        Case("ground-window-huge", ("ground", "cloud.laz", "-o", "out.laz", "--window", "1e9"), expect="any",
             outputs=("out.laz",), timeout=60),
        Case("info-density-cell-tiny", ("info", "cloud.laz", "--density-cell", "1e-9"), names=("--density-cell",)),
        Case("merge-voxel-tiny", (*BASE["merge"], "--voxel-size", "1e-12"), expect="any", outputs=("m.laz",),
             names=("--voxel-size",)),
        Case("register-voxel-tiny", (*BASE["register"], "--voxel-size", "1e-7"), names=("--voxel-size",)),
        Case("classify-cuda", (*BASE["classify"], "--device", "cuda"), names=("--device",)),
        Case("dem-png-output", ("dem", "cloud.laz", "-o", "out.png", "--resolution", "1"), names=("out.png",)),
        Case("render-colour-unknown", (*BASE["render"], "--background", "notacolour"), names=("--background",)),
    ]


# --- degenerate data -------------------------------------------------------------------------

def _cloud_file(name: str, xyz: np.ndarray):
    def f(d: Path):
        from workstation.core.cloud import Cloud
        from workstation.io import write_cloud

        n = len(xyz)
        write_cloud(Cloud(xyz, {"classification": np.full(n, 2, np.uint8)}, crs="EPSG:32632"), d / name,
                    overwrite=True)
    return f


def degenerate_cases() -> list:
    n = 3000
    same = np.tile([500_000.0, 4_000_000.0, 100.0], (n, 1))
    line = np.column_stack([500_000 + np.linspace(0, 50, n), np.full(n, 4e6), np.full(n, 100.0)])
    plane = np.column_stack([500_000 + np.random.default_rng(1).uniform(0, 50, (n, 2)) * [1, 0] + [0, 4e6],
                             np.random.default_rng(2).uniform(100, 110, n)])
    far = np.array([[500_000.0, 4e6, 100.0], [1e12, 1e12, 100.0], [500_010.0, 4e6 + 10, 101.0]])
    few = same[:2] + [[0, 0, 0], [1, 1, 1]]
    cases = []
    for label, xyz in (("identical", same), ("collinear", line), ("vertical-plane", plane), ("far", far),
                       ("two-points", few)):
        dmg = _cloud_file("bad.ply", xyz)
        for cmd, argv in (("ground", ("ground", "bad.ply", "-o", "out.laz")),
                          ("dem", ("dem", "bad.ply", "-o", "out.tif", "--resolution", "1")),
                          ("poisson", ("mesh", "bad.ply", "-o", "out.ply", "--method", "poisson")),
                          ("bpa", ("mesh", "bad.ply", "-o", "out.ply", "--method", "bpa")),
                          ("register", ("register", "bad.ply", "cloud.laz", "-o", "reg.laz")),
                          ("info", ("info", "bad.ply"))):
            expect = "ok" if cmd == "info" else "any"
            cases.append(Case(f"degenerate-{label}-{cmd}", argv, dmg, expect, names=("bad.ply",),
                              outputs=("out.laz", "out.tif", "out.ply", "reg.laz")))
    cases.append(Case("evaluate-unmatched", ("evaluate", "cloud.laz", "--reference", "moved.laz"),
                      names=("moved.laz", "cloud.laz")))
    return cases


# --- bad outputs -------------------------------------------------------------------------------

def _with_output(argv: tuple, old: str, new: str) -> tuple:
    return tuple(new if a == old else a for a in argv)


def output_cases() -> list:
    cases = []
    for cmd, out in WRITES.items():
        base = BASE[cmd]
        src = "dem.tif" if cmd in ("hillshade", "contours") else "cloud.laz"
        cases += [
            Case(f"output-is-input-{cmd}", _with_output(base, out, src if cmd != "ortho" else "dem.tif"),
                 names=(src if cmd != "ortho" else "dem.tif",)),
            Case(f"output-exists-{cmd}", base, write(out, b"precious"), names=(out,)),
            Case(f"output-folder-missing-{cmd}", _with_output(base, out, f"missing/{out}"), names=("missing",)),
            Case(f"output-is-folder-{cmd}", base, make_dir(out), names=(out,)),
        ]
    cases += [
        Case("hillshade-png-bad-folder", (*BASE["hillshade"], "--png", "missing/hs.png"), names=("missing",)),
        Case("hillshade-png-is-input", (*BASE["hillshade"], "--png", "dem.tif"), names=("dem.tif",)),
        Case("hillshade-png-is-output", (*BASE["hillshade"], "--png", "hs.tif"), names=("hs.tif",)),
        Case("merge-poses-out-is-input", (*BASE["merge"], "--register", "--poses-out", "cloud.laz"),
             names=("cloud.laz",)),
        Case("register-matrix-out-is-input", (*BASE["register"], "--matrix-out", "moved.laz"), names=("moved.laz",)),
        Case("evaluate-plot-dir-is-file", (*BASE["evaluate"], "--plot-dir", "dem.tif"), names=("dem.tif",)),
        Case("convert-unknown-extension", ("convert", "cloud.laz", "out.xyzw"), names=("out.xyzw",)),
        Case("convert-las-version-1.0", ("convert", "cloud.laz", "out.las", "--las-version", "1.0"),
             names=("--las-version", "1.0")),
        Case("simulate-trajectory-is-output", ("simulate", "tls", "-o", "sim.laz", "--trajectory", "sim.laz"),
             names=("sim.laz",)),
        Case("sfm-not-images", ("sfm", "tiles", "-o", "sfm"), names=("tiles",)),
        Case("sfm-output-exists-file", ("sfm", "images", "-o", "cloud.laz"), names=("cloud.laz",)),
        Case("dense-not-workdir", ("dense", "tiles"), names=("tiles",)),
        Case("output-exists-overwrite-ok", (*BASE["hillshade"], "--overwrite"), write("hs.tif", b"old"), "ok",
             outputs=("hs.tif",)),
        Case("convert-ok", BASE["convert"], None, "ok", outputs=("out.las",)),
    ]
    return cases


def missing_input_cases() -> list:
    cases = []
    for cmd, argv in BASE.items():
        if cmd in ("plan-flight", "demo", "simulate"):
            continue
        first = next((a for a in argv[1:] if not a.startswith("-") and a != "."), None)
        if first is None:
            continue
        cases.append(Case(f"missing-input-{cmd}", _with_output(argv, first, "nothere.laz"), names=("nothere.laz",)))
    return cases


def _raster(name: str, array):
    def f(d: Path):
        from workstation.core.products import Raster
        from workstation.io.geotiff import write_raster

        a = np.asarray(array, np.float32)
        transform = (1.0, 0.0, 500_000.0, 0.0, -1.0, 4_000_000.0 + a.shape[0])
        write_raster(Raster(a, transform, "EPSG:32632", nodata=-9999.0), d / name, overwrite=True)
    return f


ASCII_PLY_AS_BINARY = (b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\n"
                       b"property double y\nproperty double z\nend_header\n1 2 3\n4 5 6\n7 8 9\n")


def issue_cases() -> list:
    """The failures listed in the reliability issue that the families above do not cover."""
    rgb = _rgb_cloud("rgb.laz")
    return [
        Case("convert-rgb-to-pdrf1", ("convert", "rgb.laz", "out.las", "--point-format", "1"), rgb, "any",
             names=("--point-format", "rgb.laz"), outputs=("out.las",), then=("info", "out.las")),
        Case("ply-ascii-labelled-binary-info", ("info", "bad.ply"), write("bad.ply", ASCII_PLY_AS_BINARY),
             names=("bad.ply",)),
        Case("hillshade-all-nodata", ("hillshade", "nan.tif", "-o", "hs.tif"), _raster("nan.tif", np.full((20, 20), np.nan)),
             names=("nan.tif",)),
        Case("hillshade-1x1", ("hillshade", "one.tif", "-o", "hs.tif"), _raster("one.tif", [[5.0]]), "any",
             names=("one.tif",), outputs=("hs.tif",)),
        Case("contours-1x1", ("contours", "one.tif", "-o", "c.geojson"), _raster("one.tif", [[5.0]]), "any",
             names=("one.tif",), outputs=("c.geojson",)),
        Case("sfm-featureless-images", ("sfm", "images", "-o", "sfm"), None, names=("images",)),
        Case("sfm-text-as-jpg", ("sfm", "images", "-o", "sfm"),
             both(write("images/img_1.png", b"not an image"), write("images/img_2.png", b"nor this")),
             names=("img_1.png",)),
        Case("classify-model-random", (*BASE["classify"], "--model", "model.pt"), write("model.pt", RANDOM),
             names=("model.pt",)),
        Case("classify-model-text", (*BASE["classify"], "--model", "model.pt"), write("model.pt", b"{}"),
             names=("model.pt",)),
        Case("classify-model-pickle", (*BASE["classify"], "--model", "model.pt"),
             write("model.pt", b"\x80\x04\x95\x0b\x00\x00\x00\x00\x00\x00\x00}\x94\x8c\x01a\x94K\x01s."),
             names=("model.pt",)),
        Case("simulate-scene-not-utf8", ("simulate", "tls", "-o", "sim.laz", "--scene", "scene.toml"),
             write("scene.toml", NOT_UTF8), names=("scene.toml",)),
        Case("simulate-config-not-toml", ("simulate", "tls", "-o", "sim.laz", "--config", "survey.toml"),
             write("survey.toml", b"[survey\nscene = "), names=("survey.toml",)),
        Case("dense-cuda", ("dense", ".", "--device", "cuda"), names=("--device", "CUDA")),
        Case("classify-identical", ("classify", "bad.ply", "-o", "out.laz"),
             _cloud_file("bad.ply", np.tile([500_000.0, 4e6, 100.0], (3000, 1))), "any", names=("bad.ply",),
             outputs=("out.laz",)),
    ]


def _rgb_cloud(name: str):
    def f(d: Path):
        from workstation.io import read_cloud, write_cloud

        c = read_cloud(d / "cloud.laz")
        rgb = np.random.default_rng(0).integers(0, 65535, (c.n, 3)).astype(np.uint16)
        write_cloud(c.with_attrs(rgb=rgb), d / name)
    return f


def operation_cases() -> list:
    """The everyday operations (crop, filter, thin, tile) on bad arguments."""
    crop, flt = BASE["crop"][:4], BASE["filter"][:4]
    return [
        Case("crop-bounds-words", (*crop, "--bounds", "a,b,c,d"), names=("bounds",)),
        Case("crop-bounds-three", (*crop, "--bounds", "1,2,3"), names=("bounds",)),
        Case("crop-bounds-inverted", (*crop, "--bounds", "500040,4000040,500010,4000010"), names=("bounds",)),
        Case("crop-bounds-nan", (*crop, "--bounds", "nan,0,1,1"), names=("bounds",)),
        Case("crop-polygon-not-json", (*crop, "--polygon", "poly.geojson"), write("poly.geojson", b"{ nope"),
             names=("poly.geojson",)),
        Case("crop-polygon-not-utf8", (*crop, "--polygon", "poly.geojson"), write("poly.geojson", NOT_UTF8),
             names=("poly.geojson",)),
        Case("crop-polygon-no-polygon", (*crop, "--polygon", "poly.geojson"),
             write("poly.geojson", b'{"type": "Point", "coordinates": [0, 0]}'), names=("poly.geojson",)),
        Case("crop-polygon-gpkg-random", (*crop, "--polygon", "poly.gpkg"), write("poly.gpkg", RANDOM),
             names=("poly.gpkg",)),
        Case("filter-unknown-dimension", (*flt, "--expr", "Colour == 2"), names=("Colour",)),
        Case("filter-syntax", (*flt, "--expr", "Classification == == 2"), names=("expr",)),
        Case("filter-python-injection", (*flt, "--expr", "__import__('os').system('touch pwned')"),
             names=("expr",)),
        Case("filter-empty", (*flt, "--expr", ""), names=("expr",)),
        Case("filter-unbalanced", (*flt, "--expr", "(Classification == 2"), names=("expr",)),
        Case("thin-both", (*BASE["thin"], "--poisson", "1"), names=("--voxel", "--poisson")),
        Case("thin-none", BASE["thin"][:4], names=("--voxel", "--poisson")),
        Case("thin-voxel-tiny", ("thin", "cloud.laz", "-o", "t.laz", "--voxel", "1e-12"), None, "any",
             names=("--voxel",),
             outputs=("t.laz",)),
        Case("tile-output-is-file", ("tile", "cloud.laz", "-o", "cloud.las", "--size", "30"), names=("cloud.las",)),
        Case("tile-fractional-size", ("tile", "cloud.laz", "-o", "tiles_out", "--size", "7.5"), None, "ok",
             outputs=("tiles_out/",)),
        Case("convert-scale-zero", ("convert", "cloud.laz", "out.las", "--scale", "0"), names=("--scale",)),
        Case("convert-scale-words", ("convert", "cloud.laz", "out.las", "--scale", "a,b,c"), names=("--scale",)),
        Case("convert-offset-nan", ("convert", "cloud.laz", "out.las", "--offset", "nan,0,0"), names=("--offset",)),
        Case("convert-scale-too-fine", ("convert", "cloud.laz", "out.las", "--scale", "1e-12"),
             names=("--scale", "scale")),
        Case("convert-to-crs-unknown", ("convert", "cloud.laz", "out.las", "--to-crs", "EPSG:999999"),
             names=("--to-crs", "EPSG:999999")),
        Case("convert-geocentric-roundtrip-ok", ("convert", "cloud.laz", "geo.laz", "--to-crs", "EPSG:4326"), None,
             "ok", outputs=("geo.laz",), then=("info", "geo.laz")),
    ]


def cases() -> list:
    """The whole corpus."""
    return [*reader_cases(), *text_file_cases(), *path_cases(), *option_cases(), *data_option_cases(),
            *degenerate_cases(), *output_cases(), *missing_input_cases(), *issue_cases(),
            *operation_cases()]
