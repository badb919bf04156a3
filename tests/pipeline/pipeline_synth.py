"""Tiny synthetic survey tiles for the ``ws run`` pipeline tests: a gently sloping, undulating
terrain with box buildings, cut into adjacent square LAZ tiles."""

from __future__ import annotations

from pathlib import Path

import numpy as np

X0, Y0 = 500020.0, 4000020.0  # south-west corner of the survey (not on a 100 m chunk edge)
TILE = 90.0  # tile side, metres: tile edges at +90 m cut across the 100 m chunks
CRS = "EPSG:32633"

# (x range, y range, height) of the buildings, metres from (X0, Y0); one straddles the chunk
# edge x = 500100 (local 80) and one the edge y = 4000100
BUILDINGS = [((10.0, 24.0), (20.0, 34.0), 7.0), ((72.0, 88.0), (40.0, 52.0), 9.0),
             ((120.0, 134.0), (74.0, 90.0), 6.0), ((30.0, 44.0), (130.0, 146.0), 8.0)]


def terrain(x, y):
    """Bare-earth height (m) at world (x, y)."""
    lx, ly = np.asarray(x) - X0, np.asarray(y) - Y0
    return 100.0 + 0.04 * lx + 1.2 * np.sin(ly / 23.0) + 0.6 * np.cos(lx / 31.0)


def tile_points(ix: int, iy: int, density: float = 5.0, seed: int = 0, x0: float = X0, y0: float = Y0):
    """xyz (n, 3) rounded to 1 cm and truth ground (n,) of the tile at column ix, row iy."""
    rng = np.random.default_rng([seed, ix + 50, iy + 50])
    n = int(TILE * TILE * density)
    # coordinates on the 1 cm LAS scale, strictly inside the tile's [x0, x0 + TILE) range
    x = x0 + ix * TILE + rng.integers(0, int(TILE * 100), n) / 100.0
    y = y0 + iy * TILE + rng.integers(0, int(TILE * 100), n) / 100.0
    z = terrain(x, y) + rng.normal(0.0, 0.02, n)
    ground = np.ones(n, bool)
    for (a, b), (c, d), h in BUILDINGS:
        m = (x - X0 >= a) & (x - X0 <= b) & (y - Y0 >= c) & (y - Y0 <= d)
        z[m] = float(terrain(X0 + (a + b) / 2, Y0 + (c + d) / 2)) + h + rng.normal(0.0, 0.02, m.sum())
        ground[m] = False
    return np.column_stack([x, y, np.round(z, 2)]), ground


def tile_cloud(ix: int, iy: int, density: float = 5.0, seed: int = 0, crs: str | None = CRS, x0=X0, y0=Y0):
    from workstation.core.cloud import Cloud

    xyz, _ = tile_points(ix, iy, density, seed, x0, y0)
    n = len(xyz)
    rng = np.random.default_rng([seed, ix + 50, iy + 50, 7])
    return Cloud(xyz, {"classification": np.ones(n, np.uint8), "return_number": np.ones(n, np.uint8),
                       "number_of_returns": np.ones(n, np.uint8),
                       "intensity": rng.integers(0, 4000, n).astype(np.uint16)}, crs=crs)


def write_tiles(folder: Path, cells=((0, 0), (0, 1), (1, 0), (1, 1)), density: float = 5.0, crs=CRS, **kw) -> list:
    """Write the tiles ``cells`` as ``folder/t_<ix>_<iy>.laz``; returns their paths."""
    from workstation.io import write_cloud

    folder.mkdir(parents=True, exist_ok=True)
    out = []
    for ix, iy in cells:
        p = folder / f"t_{ix}_{iy}.laz"
        write_cloud(tile_cloud(ix, iy, density, crs=crs, **kw), p, overwrite=True)
        out.append(p)
    return out


PROJECT = """\
[inputs]
clouds = ["tiles/*.laz"]

[chunks]
size = 100.0
buffer = 30.0

[stages.ground]
method = "smrf"
{ground}
[stages.dem]
kinds = ["dtm", "dsm"]
resolution = {resolution}
"""


def write_project(folder: Path, name: str = "project.toml", ground: str = "", resolution: float = 1.0) -> Path:
    p = folder / name
    p.write_text(PROJECT.format(ground=ground, resolution=resolution))
    return p
