"""Ground filtering tile by tile: the layout covers every point once, and the classes match
the whole-cloud run where the grids line up, with the buildings still objects."""

from __future__ import annotations

import json

import numpy as np
import pytest
from ground_synth import terrain_with_boxes

from workstation.cli.main import main
from workstation.core.classes import ASPRSClass
from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, StageError
from workstation.ground.evaluate import ground_errors
from workstation.ground.methods import ground_filter
from workstation.ground.tiles import TileParams, tile_layout
from workstation.io import read_cloud, write_cloud


def test_layout_puts_each_point_in_one_core_and_the_buffer_around_it():
    rng = np.random.default_rng(1)
    xy = rng.uniform(0, [300, 170], (20000, 2))
    seen = np.zeros(len(xy), int)
    tiles = list(tile_layout(xy, 3000, 15.0))
    assert len(tiles) >= 6
    for core, sel in tiles:
        seen[core] += 1
        assert np.isin(core, sel).all() and np.all(np.diff(sel) > 0)
        # every point within 15 m (per axis) of the core's cell is in the buffered set
        lo, hi = xy[core].min(axis=0), xy[core].max(axis=0)
        near = np.all((xy >= lo - 14.9) & (xy <= hi + 14.9), axis=1)
        assert np.isin(np.flatnonzero(near), sel).all()
    assert (seen == 1).all()


@pytest.fixture(scope="module")
def big_scene():
    xyz, truth = terrain_with_boxes(seed=11, size=160.0, density=2.0)
    n = len(xyz)
    cls = np.where(np.arange(n) % 97 == 0, 6, 1).astype(np.uint8)  # some points already buildings
    cloud = Cloud(xyz, {"intensity": np.arange(n) % 5000, "classification": cls}, crs="EPSG:32632")
    return cloud, truth


@pytest.mark.parametrize("method", ["smrf", "auto"])
def test_tiled_filter_matches_the_whole_cloud(big_scene, method):
    cloud, truth = big_scene
    whole = ground_filter(cloud, method)
    tiled = ground_filter(cloud, method, tiles=TileParams(tile_points=12_000, buffer=40.0))
    rec = tiled.history[-1]
    assert rec.stage == whole.history[-1].stage and rec.params["tiles"] >= 4
    a = np.asarray(whole.attrs["classification"])
    b = np.asarray(tiled.attrs["classification"])
    assert np.mean(a == b) > 0.99
    # classes other than 0/1/2 kept, every other attribute carried
    assert np.array_equal(b[np.arange(cloud.n) % 97 == 0], np.full(b[::97].shape, 6))
    assert np.array_equal(np.asarray(tiled.attrs["intensity"]), np.arange(cloud.n) % 5000)
    plain = np.arange(cloud.n) % 97 != 0
    assert ground_errors(truth[plain], b[plain] == ASPRSClass.GROUND).total_error < 0.03


def test_small_cloud_is_filtered_whole_and_bad_tiles_are_refused(big_scene):
    cloud, _ = big_scene
    out = ground_filter(cloud, "smrf", tiles=TileParams(tile_points=cloud.n))
    assert "tiles" not in out.history[-1].params
    with pytest.raises(InvalidInputError, match="tile_points"):
        TileParams(tile_points=10)
    with pytest.raises(InvalidInputError, match="buffer"):
        TileParams(buffer=-1.0)
    with pytest.raises(InvalidInputError, match="workers"):
        TileParams(workers=0)


def test_a_tile_without_usable_points_keeps_its_classes_and_the_rest_is_filtered():
    xyz, truth = terrain_with_boxes(seed=12, size=120.0)
    cls = np.ones(len(xyz), np.uint8)
    noisy = xyz[:, 0] - xyz[:, 0].min() > 60.0  # half the area flagged low noise: its last tiles have no usable point
    cls[noisy] = ASPRSClass.LOW_POINT
    cloud = Cloud(xyz, {"classification": cls})
    out = ground_filter(cloud, "smrf", tiles=TileParams(tile_points=4000, buffer=0.0))
    got = np.asarray(out.attrs["classification"])
    assert (got[noisy] == ASPRSClass.LOW_POINT).all()
    assert out.history[-1].params["tiles_without_ground"] >= 1
    assert ground_errors(truth[~noisy], got[~noisy] == ASPRSClass.GROUND).total_error < 0.03
    # nothing usable anywhere: the same error as without tiles
    with pytest.raises(StageError, match="no ground"):
        ground_filter(cloud.with_attrs(classification=np.full(cloud.n, 7, np.uint8)), "smrf",
                      tiles=TileParams(tile_points=4000))


def test_cli_tiles_a_large_input_in_two_processes_as_in_one(tmp_path, capsys):
    xyz, truth = terrain_with_boxes(seed=13, size=100.0)
    write_cloud(Cloud(xyz, {"intensity": np.arange(len(xyz)) % 700}, crs="EPSG:32632"), tmp_path / "in.las")
    got = {}
    for w in (1, 2):
        rc = main(["ground", str(tmp_path / "in.las"), "-o", str(tmp_path / f"out{w}.las"), "--method", "smrf",
                   "--tile-points", "5000", "--tile-buffer", "30", "--tile-workers", str(w), "--json"])
        assert rc == 0 and json.loads(capsys.readouterr().out)["tiles"] >= 2
        out = read_cloud(tmp_path / f"out{w}.las")
        got[w] = np.asarray(out.attrs["classification"])
        assert np.array_equal(np.asarray(out.attrs["intensity"]), np.arange(out.n) % 700)
    assert np.array_equal(got[1], got[2])  # the same tiles, whichever process filters them
    assert ground_errors(truth, got[2] == 2).total_error < 0.03
