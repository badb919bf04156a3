"""The streamed LAS/LAZ statistics of ``ws info`` against a full read of the same file."""

import laspy
import numpy as np
import pytest

from workstation.io import read_cloud
from workstation.qc import summary as summary_mod
from workstation.qc.density import DensityAccumulator, density
from workstation.qc.las_stats import las_statistics
from workstation.qc.summary import summarize


def _write(path, fmt: int, n: int = 5000, seed: int = 7, extras: bool = False):
    """A LAS/LAZ file of ``n`` points of point format ``fmt`` with every field varied; with
    ``extras``, a scaled extra-byte dimension of negative scale and a 3-element float one."""
    rng = np.random.default_rng(seed)
    h = laspy.LasHeader(point_format=fmt, version="1.4" if fmt >= 6 else "1.2")
    h.scales = np.array([0.01, 0.01, 0.001])
    h.offsets = np.array([500000.0, 4000000.0, 0.0])
    if extras:
        h.add_extra_dims([laspy.ExtraBytesParams("depth", "i2", scales=np.array([-0.5]), offsets=np.array([3.0])),
                          laspy.ExtraBytesParams("normal", "3f4")])
    las = laspy.LasData(h)
    # three patches far apart, so the chunks differ in extent and the hull spans chunks
    sizes = [n // 2, n // 4, n - n // 2 - n // 4]
    centre = np.repeat(np.array([[0, 0], [400, 50], [150, 300]]), sizes, axis=0)
    las.x = 500000 + centre[:, 0] + rng.uniform(0, 60, n)
    las.y = 4000000 + centre[:, 1] + rng.uniform(0, 40, n)
    las.z = rng.uniform(-5, 80, n)
    las.intensity = rng.integers(0, 65536, n)
    nr = rng.integers(1, 6 if fmt < 6 else 16, n)
    las.number_of_returns = nr
    las.return_number = rng.integers(1, nr + 1)
    las.classification = rng.choice([1, 2, 5, 6, 9, 17 if fmt < 6 else 64], n)
    las.synthetic = rng.integers(0, 2, n)
    las.withheld = rng.integers(0, 2, n)
    las.scan_direction_flag = rng.integers(0, 2, n)
    las.user_data = rng.integers(3, 200, n)
    las.point_source_id = rng.integers(10, 900, n)
    if fmt >= 6:
        las.scanner_channel = rng.integers(0, 4, n)
        las.scan_angle = rng.integers(-15000, 15000, n)
    else:
        las.scan_angle_rank = rng.integers(-90, 91, n)
    if "gps_time" in las.point_format.dimension_names:
        t = rng.uniform(1e5, 2e5, n)
        t[rng.integers(0, n, 20)] = np.nan  # NaN is ignored by the extremes, as on a full read
        las.gps_time = t
    if "red" in las.point_format.dimension_names:
        for c in ("red", "green", "blue"):
            las[c] = rng.integers(0, 65536, n)
    if extras:
        las.points.array["depth"] = rng.integers(-300, 300, n)  # stored; laspy refuses scaled values of a negative scale
        las.normal = rng.normal(size=(n, 3)).astype("f4")
    las.write(path)
    return path


def _expected(path) -> dict:
    """The figures of ``ws info`` computed on the whole file read at once."""
    c = read_cloud(path)
    dims = {}
    for k, a in c.attrs.items():
        fmin, fmax = (np.nanmin, np.nanmax) if a.dtype.kind == "f" else (np.min, np.max)
        lo, hi = fmin(a, axis=0), fmax(a, axis=0)
        dims[k] = {"dtype": str(a.dtype) + ("" if a.ndim == 1 else f"x{a.shape[1]}"),
                   "min": lo.tolist(), "max": hi.tolist()}
    cls, cnt = np.unique(c.attrs["classification"], return_counts=True)
    rn, nr = c.attrs["return_number"], c.attrs["number_of_returns"]
    pairs, pc = np.unique(rn.astype(np.int32) * 256 + nr, return_counts=True)
    return {
        "point_count": c.n,
        "bounds": {"min": c.xyz.min(axis=0).tolist(), "max": c.xyz.max(axis=0).tolist()},
        "dimensions": dims,
        "classification": {str(k): int(v) for k, v in zip(cls, cnt)},
        "returns": dict(sorted({f"{p // 256}/{p % 256}": int(v) for p, v in zip(pairs, pc)}.items())),
        "density": density(c.xyz[:, :2]),
    }


@pytest.mark.parametrize("fmt,extras,suffix", [(1, False, ".las"), (3, True, ".laz"), (6, True, ".las"),
                                               (8, False, ".laz")])
def test_streamed_statistics_equal_a_full_read(tmp_path, fmt, extras, suffix):
    p = _write(tmp_path / f"f{fmt}{suffix}", fmt, extras=extras)
    want = _expected(p)
    # 6 chunks of at most 900 records, each cut into slices of 256 records (the last ones short)
    got = summarize(p, chunk_size=900)
    st = las_statistics(p, 900, DensityAccumulator(1.0), slice_size=256)
    for s in (got, {"point_count": st.count, "bounds": {"min": st.lo.tolist(), "max": st.hi.tolist()}}):
        assert s["point_count"] == want["point_count"]
        assert s["bounds"] == want["bounds"]
    assert got["dimensions"] == want["dimensions"]
    assert got["classification"] == want["classification"]
    assert got["returns"] == want["returns"]
    for k in ("points", "occupied_cells", "cell_size", "occupied_area_m2"):
        assert got["density"][k] == want["density"][k], k
    assert got["density"]["footprint_area_m2"] == pytest.approx(want["density"]["footprint_area_m2"], rel=1e-12)
    assert {k: {"dtype": st.dtypes[k], "min": lo.tolist(), "max": hi.tolist()} for k, (lo, hi) in st.ranges.items()} \
        == want["dimensions"]
    assert {str(k): int(v) for k, v in enumerate(st.classes) if v} == want["classification"]
    assert dict(sorted(st.returns.items())) == want["returns"]


def test_streamed_statistics_equal_the_cloud_stream(tmp_path):
    """The raw-record path and the cloud path of :func:`summarize` give the same report."""
    p = _write(tmp_path / "a.laz", 3, n=3000, extras=True)
    fast = summarize(p, chunk_size=700)
    stats, crs, info, meta, acc = summary_mod._chunk_stats(p, 700, 1.0, True, {})
    assert fast["point_count"] == stats.count
    assert fast["bounds"] == {"min": stats.lo.tolist(), "max": stats.hi.tolist()}
    assert fast["dimensions"] == {k: {"dtype": stats.dtypes[k], "min": summary_mod._py(lo), "max": summary_mod._py(hi)}
                                  for k, (lo, hi) in stats.ranges.items()}
    assert fast["returns"] == dict(sorted(stats.returns.items()))
    assert fast["density"] == acc.result()


def test_empty_file_reports_no_points(tmp_path):
    p = tmp_path / "e.las"
    laspy.LasData(laspy.LasHeader(point_format=3, version="1.2")).write(p)
    s = summarize(p)
    assert s["point_count"] == 0 and s["bounds"] is None and s["dimensions"] == {} and s["density"] is None


def test_truncated_laz_is_an_error_naming_the_file(tmp_path):
    from workstation.core.errors import InvalidInputError

    p = _write(tmp_path / "t.laz", 3, n=200_000)
    data = p.read_bytes()
    p.write_bytes(data[: len(data) // 2])
    with pytest.raises(InvalidInputError, match="t.laz"):
        summarize(p)
