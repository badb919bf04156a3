"""Every point cloud reader ends cleanly on bad input.

Small valid files are written with the package's own writers and then damaged: truncated,
header bytes zeroed or flipped at seeded positions, counts changed, LAS scales/offsets and
point formats made invalid, ascii and binary labels swapped, non-UTF-8 bytes inserted; then
hypothesis feeds random bytes and random byte changes. Each read must either return a cloud
whose point count the file can hold, or raise :class:`InvalidInputError` naming the file; it
must never raise anything else, hang, or change the file.
"""

from __future__ import annotations

import hashlib
import re
import signal
import struct
from contextlib import contextmanager
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.io import read_cloud, write_cloud

N = 40
#: (name, file extension, writer options) of every variant fuzzed.
VARIANTS = [
    ("las", ".las", {}),
    ("laz", ".laz", {}),
    ("las_pf1", ".las", {"point_format": 1}),
    ("laz_pf3", ".laz", {"point_format": 3}),
    ("ply_bin", ".ply", {}),
    ("ply_ascii", ".ply", {"ascii": True}),
    ("ply_be", ".ply", {"big_endian": True}),
    ("pcd_bin", ".pcd", {}),
    ("pcd_ascii", ".pcd", {"ascii": True}),
    ("xyz", ".xyz", {}),
    ("csv", ".csv", {}),
    ("txt", ".txt", {}),
    ("pts", ".pts", {}),
    ("e57", ".e57", {}),
]
_IDS = [v[0] for v in VARIANTS]
#: Fewest bytes one point takes in each (uncompressed) format, bounding a plausible count.
_MIN_POINT_BYTES = {".las": 20, ".ply": 3, ".pcd": 3, ".xyz": 6, ".csv": 6, ".txt": 6, ".pts": 6}


def _cloud() -> Cloud:
    rng = np.random.default_rng(7)
    return Cloud(
        np.round(rng.uniform([500_000, 4_100_000, 50], [500_100, 4_100_100, 80], (N, 3)), 3),
        {
            "intensity": rng.integers(0, 4096, N).astype(np.uint16),
            "rgb": (rng.integers(0, 256, (N, 3)) * 257).astype(np.uint16),
            "gps_time": rng.uniform(0, 100, N),
        },
    )


@pytest.fixture(scope="module")
def originals(tmp_path_factory) -> dict[str, bytes]:
    """The bytes of one small valid file per variant."""
    folder = tmp_path_factory.mktemp("originals")
    out = {}
    cloud = _cloud()
    for name, ext, opts in VARIANTS:
        p = folder / f"{name}{ext}"
        write_cloud(cloud, p, **opts)
        out[name] = p.read_bytes()
    return out


class _Hang(Exception):
    pass


@contextmanager
def _deadline(seconds: float):
    """Raise _Hang when the block runs longer than ``seconds`` (a reader must never hang)."""

    def fire(*_):
        raise _Hang(f"read took more than {seconds} s")

    old = signal.signal(signal.SIGALRM, fire)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


def _max_points(path: Path, data: bytes) -> int | None:
    """Most points the file can hold (None for compressed formats)."""
    per = _MIN_POINT_BYTES.get(path.suffix)
    return None if per is None else len(data) // per + 1


def check_read(path: Path, data: bytes, expect_n: int | None = None) -> Cloud | None:
    """Write ``data`` to ``path`` and read it: a plausible cloud or an InvalidInputError naming
    the file; the file is unchanged afterwards. Returns the cloud, or None on an error."""
    path.write_bytes(data)
    digest = hashlib.sha256(data).hexdigest()
    cloud = None
    try:
        with _deadline(10.0):
            cloud = read_cloud(path)
    except InvalidInputError as e:
        assert path.name in str(e), f"error does not name the file: {e}"
    assert hashlib.sha256(path.read_bytes()).hexdigest() == digest, "the reader changed its input"
    if cloud is not None:
        assert cloud.xyz.shape == (cloud.n, 3)
        bound = _max_points(path, data)
        assert bound is None or cloud.n <= bound, f"{cloud.n} points from {len(data)} bytes"
    if expect_n is not None:
        assert cloud is not None and cloud.n == expect_n
    return cloud


def _name(variant: str) -> str:
    return dict((v[0], v[0] + v[1]) for v in VARIANTS)[variant]


# ---------------------------------------------------------------------------------------
# structured mutations


def _header_end(variant: str, data: bytes) -> int:
    """Byte length of the header of a variant's file (all of a text file's first line)."""
    if variant.startswith(("las", "laz")):
        return struct.unpack_from("<I", data, 96)[0]
    if variant.startswith("ply"):
        return data.index(b"end_header") + 11
    if variant.startswith("pcd"):
        return data.index(b"\nDATA") + data[data.index(b"\nDATA") + 1 :].index(b"\n") + 2
    if variant == "e57":
        return 48
    return data.index(b"\n") + 1


@pytest.mark.parametrize("variant", _IDS)
def test_originals_read_back(tmp_path, originals, variant):
    check_read(tmp_path / _name(variant), originals[variant], expect_n=N)


@pytest.mark.parametrize("variant", _IDS)
def test_truncated_files(tmp_path, originals, variant):
    data = originals[variant]
    h = _header_end(variant, data)
    cuts = sorted({1, 3, 4, 8, 30, h - 1, h, h + 1, len(data) // 2, len(data) - 30, len(data) - 1} & set(range(1, len(data))))
    for cut in cuts:
        cloud = check_read(tmp_path / _name(variant), data[:cut])
        if cloud is not None and not variant.startswith(("xyz", "csv", "txt", "pts", "ply_ascii", "pcd_ascii")):
            # a binary file cut short cannot keep every point
            pytest.fail(f"{variant} cut at {cut} of {len(data)} bytes read as {cloud.n} points")


@pytest.mark.parametrize("variant", _IDS)
def test_header_bytes_zeroed_or_flipped(tmp_path, originals, variant):
    data = originals[variant]
    h = _header_end(variant, data)
    rng = np.random.default_rng(sum(map(ord, variant)))
    for pos in rng.integers(0, h, 24):
        for new in (0, data[pos] ^ 0xFF, data[pos] ^ 0x01):
            mutated = bytearray(data)
            mutated[pos] = new
            check_read(tmp_path / _name(variant), bytes(mutated))


def _set_count(variant: str, data: bytes, n) -> bytes:
    """The file with its header point count set to ``n`` (an int or any text)."""
    if variant.startswith(("las", "laz")):
        b = bytearray(data)
        struct.pack_into("<I", b, 107, int(n) if 0 <= int(n) < 2**32 else 0)
        if b[25] >= 4:
            struct.pack_into("<Q", b, 247, int(n) % 2**64)
        return bytes(b)
    if variant.startswith("ply"):
        return re.sub(rb"element vertex \S+", b"element vertex " + str(n).encode(), data, count=1)
    if variant.startswith("pcd"):
        data = re.sub(rb"\nWIDTH \S+", b"\nWIDTH " + str(n).encode(), data, count=1)
        return re.sub(rb"\nPOINTS \S+", b"\nPOINTS " + str(n).encode(), data, count=1)
    if variant == "pts":
        return str(n).encode() + b"\n" + data
    raise ValueError(variant)


_COUNTED = ["las", "laz", "las_pf1", "laz_pf3", "ply_bin", "ply_ascii", "ply_be", "pcd_bin", "pcd_ascii"]


@pytest.mark.parametrize("variant", _COUNTED)
@pytest.mark.parametrize("count", [0, N - 1, N + 1, 2 * N, 2**31, 4 * 10**12, 2**64 - 1])
def test_wrong_point_counts_are_refused(tmp_path, originals, variant, count):
    path = tmp_path / _name(variant)
    if variant == "laz_pf3" and count == N - 1:
        # formats 0-5 of LAZ store no count per chunk: a count within the last chunk is read as given
        check_read(path, _set_count(variant, originals[variant], count))
        return
    with pytest.raises(InvalidInputError, match=re.escape(path.name)):
        with _deadline(10.0):
            path.write_bytes(_set_count(variant, originals[variant], count))
            read_cloud(path)


@pytest.mark.parametrize("variant", ["ply_bin", "ply_ascii", "pcd_bin", "pcd_ascii"])
@pytest.mark.parametrize("count", ["-1", "abc", "1e3", "nan", "", "0x10", "99999999999999999999999"])
def test_counts_that_are_not_numbers_are_refused(tmp_path, originals, variant, count):
    path = tmp_path / _name(variant)
    data = _set_count(variant, originals[variant], count)
    with pytest.raises(InvalidInputError, match=re.escape(path.name)):
        path.write_bytes(data)
        read_cloud(path)


@pytest.mark.parametrize("variant", ["las", "laz"])
@pytest.mark.parametrize("field, at", [("scale", 131), ("offset", 155)])
@pytest.mark.parametrize("axis", [0, 2])
@pytest.mark.parametrize("value", [0.0, float("nan"), float("inf"), -float("inf")])
def test_las_scale_and_offset_must_be_finite(tmp_path, originals, variant, field, at, axis, value):
    if field == "offset" and value == 0.0:
        return  # a zero offset is valid
    b = bytearray(originals[variant])
    struct.pack_into("<d", b, at + 8 * axis, value)
    path = tmp_path / _name(variant)
    path.write_bytes(bytes(b))
    with pytest.raises(InvalidInputError, match=f"{'xyz'[axis]}_{field}") as info:
        read_cloud(path)
    assert path.name in str(info.value)


@pytest.mark.parametrize("variant", ["las", "laz"])
@pytest.mark.parametrize("pdrf", [11, 35, 63, 99])
def test_las_unknown_point_format(tmp_path, originals, variant, pdrf):
    b = bytearray(originals[variant])
    b[104] = pdrf | (b[104] & 0x80)
    path = tmp_path / _name(variant)
    path.write_bytes(bytes(b))
    with pytest.raises(InvalidInputError, match=rf"point data record format {pdrf} is unknown \(valid formats: 0-10\)"):
        read_cloud(path)


@pytest.mark.parametrize("variant, swaps", [
    ("ply_ascii", [(b"format ascii", b"format binary_little_endian"), (b"format ascii", b"format binary_big_endian")]),
    ("ply_bin", [(b"format binary_little_endian", b"format ascii")]),
    ("ply_be", [(b"format binary_big_endian", b"format ascii")]),
    ("pcd_ascii", [(b"DATA ascii", b"DATA binary"), (b"DATA ascii", b"DATA binary_compressed")]),
    ("pcd_bin", [(b"DATA binary", b"DATA ascii")]),
])
def test_ascii_binary_mismatch_is_refused(tmp_path, originals, variant, swaps):
    path = tmp_path / _name(variant)
    for old, new in swaps:
        path.write_bytes(originals[variant].replace(old, new, 1))
        with pytest.raises(InvalidInputError, match=re.escape(path.name)):
            read_cloud(path)


@pytest.mark.parametrize("variant", ["xyz", "csv", "txt", "pts", "ply_ascii", "pcd_ascii"])
@pytest.mark.parametrize("where", ["first", "middle", "last"])
def test_non_utf8_text_is_refused(tmp_path, originals, variant, where):
    data = originals[variant]
    h = _header_end(variant, data)
    at = {"first": 0 if variant in ("xyz",) else h, "middle": (h + len(data)) // 2, "last": len(data) - 2}[where]
    path = tmp_path / _name(variant)
    path.write_bytes(data[:at] + b"\xff\xfe\xc3" + data[at:])
    with pytest.raises(InvalidInputError, match=re.escape(path.name)):
        read_cloud(path)


@pytest.mark.parametrize("ext", sorted({v[1] for v in VARIANTS}))
def test_empty_file_folder_and_random_bytes(tmp_path, ext):
    empty = tmp_path / f"empty{ext}"
    empty.write_bytes(b"")
    with pytest.raises(InvalidInputError, match="empty"):
        read_cloud(empty)
    folder = tmp_path / f"folder{ext}"
    folder.mkdir()
    with pytest.raises(InvalidInputError, match="folder"):
        read_cloud(folder)
    rng = np.random.default_rng(3)
    for size in (1, 7, 100, 4096):
        check_read(tmp_path / f"random{ext}", rng.integers(0, 256, size, dtype=np.uint8).tobytes())


# ---------------------------------------------------------------------------------------
# random bytes and random mutations (hypothesis)

_FUZZ = settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture], database=None,
                 derandomize=True)  # the same examples every run (CI); explore with derandomize=False


@pytest.mark.parametrize("variant", _IDS)
@_FUZZ
@given(data=st.binary(min_size=1, max_size=600))
def test_random_bytes_behind_the_magic(tmp_path, originals, variant, data):
    """Random bytes after the first bytes of a valid file (so parsing gets past the magic)."""
    head = originals[variant][: min(16, _header_end(variant, originals[variant]) // 2)]
    check_read(tmp_path / _name(variant), head + data)


@pytest.mark.parametrize("variant", _IDS)
@_FUZZ
@given(edits=st.lists(st.tuples(st.floats(0, 1, exclude_max=True), st.integers(0, 255)), min_size=1, max_size=6),
       cut=st.none() | st.floats(0.05, 1))
def test_random_mutations_of_valid_files(tmp_path, originals, variant, edits, cut):
    data = bytearray(originals[variant])
    for where, value in edits:
        data[int(where * len(data))] = value
    if cut is not None:
        data = data[: max(1, int(cut * len(data)))]
    check_read(tmp_path / _name(variant), bytes(data))


# ---------------------------------------------------------------------------------------
# targeted tests of the fixed bugs


def test_laz_header_count_smaller_than_data_is_refused(tmp_path, originals):
    path = tmp_path / "small.laz"
    path.write_bytes(_set_count("laz", originals["laz"], N - 5))
    with pytest.raises(InvalidInputError, match=rf"header says {N - 5} points but the file holds {N}") as info:
        read_cloud(path)
    assert info.value.field == "point_count"


def test_las_version_1_0_is_refused_on_writing(tmp_path):
    with pytest.raises(InvalidInputError, match=r"LAS version 1\.0 cannot be written.*1\.1, 1\.2, 1\.3, 1\.4"):
        write_cloud(_cloud(), tmp_path / "v.las", point_format=0, version="1.0")
    write_cloud(_cloud(), tmp_path / "v.las", point_format=0, version="1.1")
    assert read_cloud(tmp_path / "v.las").meta["las"]["version"] == "1.1"


def test_rgb_cloud_written_as_point_format_1_drops_colour_with_a_warning(tmp_path, caplog):
    path = tmp_path / "pf1.las"
    write_cloud(_cloud(), path, point_format=1)
    assert "rgb" in caplog.text and "not written" in caplog.text
    back = read_cloud(path)
    assert back.meta["las"]["point_format"] == 1 and "rgb" not in back.attrs
    np.testing.assert_array_equal(back.attrs["gps_time"], _cloud().attrs["gps_time"])


def test_ascii_ply_labelled_binary_names_the_format(tmp_path, originals):
    path = tmp_path / "x.ply"
    path.write_bytes(originals["ply_ascii"].replace(b"format ascii", b"format binary_little_endian", 1))
    with pytest.raises(InvalidInputError, match="body is ascii text") as info:
        read_cloud(path)
    assert info.value.field == "format"


def test_huge_pcd_count_is_refused_without_allocating(tmp_path, originals):
    path = tmp_path / "x.pcd"
    path.write_bytes(_set_count("pcd_bin", originals["pcd_bin"], 4 * 10**12))
    with pytest.raises(InvalidInputError, match="POINTS says 4000000000000"):
        read_cloud(path)


@pytest.mark.parametrize("reader, text", [
    ("camera", b'{"model": "PINHOLE", "width": 640, "height": 480, "fx": 500, "fy": 500, "cx": 320, "cy": 240, "note": "\xe9"}'),
    ("gcp", b"name,X,Y,Z\nA\xff,1,2,3\n"),
])
def test_non_utf8_camera_and_gcp_files(tmp_path, reader, text):
    from workstation.io.camera import read_camera
    from workstation.io.gcp import read_gcp

    path = tmp_path / f"bad_{reader}.txt"
    path.write_bytes(text)
    with pytest.raises(InvalidInputError, match=r"bad_.*is not UTF-8 text.*line"):
        (read_camera if reader == "camera" else read_gcp)(path)


def test_camera_with_infinite_size_and_deep_json(tmp_path):
    from workstation.io.camera import read_camera

    path = tmp_path / "cam.json"
    path.write_text('{"model": "PINHOLE", "width": Infinity, "height": 4, "fx": 1, "fy": 1, "cx": 0, "cy": 0}')
    with pytest.raises(InvalidInputError, match="cam.json"):
        read_camera(path)
    path.write_text("[" * 100_000 + "]" * 100_000)
    with pytest.raises(InvalidInputError, match="cam.json"):
        read_camera(path)


def test_gcp_with_nan_coordinates(tmp_path):
    from workstation.io.gcp import read_gcp

    path = tmp_path / "gcp.csv"
    path.write_text("name,X,Y,Z\nA,nan,2,3\n")
    with pytest.raises(InvalidInputError, match="not finite"):
        read_gcp(path)


def test_geotiff_reader_ends_cleanly(tmp_path):
    from workstation.core.products import Raster
    from workstation.io.geotiff import read_raster, write_raster

    good = tmp_path / "dem.tif"
    write_raster(Raster(np.arange(400 * 300, dtype=np.float32).reshape(400, 300), (1, 0, 5e5, 0, -1, 4.1e6), "EPSG:32632",
                        -9999.0, {}), good)
    one = tmp_path / "one.tif"
    write_raster(Raster(np.ones((1, 1), np.float32), (1, 0, 5e5, 0, -1, 4.1e6), "EPSG:32632", None, {}), one)
    assert read_raster(one).array.shape == (1, 1)
    data = good.read_bytes()
    bad = tmp_path / "bad.tif"
    for content in (data[:8], data[:1000], data[: len(data) // 2], b"not a raster\n" * 20):
        bad.write_bytes(content)
        with pytest.raises(InvalidInputError, match="bad.tif"):
            read_raster(bad)
    for content, match in ((b"", "empty"), (None, "folder")):
        target = tmp_path / f"{match}.tif"
        target.mkdir() if content is None else target.write_bytes(content)
        with pytest.raises(InvalidInputError, match=match):
            read_raster(target)
    with pytest.raises(InvalidInputError, match="band 2 does not exist"):
        read_raster(good, band=2)


def test_mesh_reader_ends_cleanly(tmp_path):
    from workstation.core.products import Mesh
    from workstation.io.mesh import read_mesh, write_mesh

    rng = np.random.default_rng(0)
    mesh = Mesh(rng.uniform(0, 1, (20, 3)), rng.integers(0, 20, (30, 3)), {"rgb": rng.integers(0, 256, (20, 3)).astype(np.uint8)})
    for ext in (".ply", ".obj", ".glb"):
        good = tmp_path / f"m{ext}"
        write_mesh(mesh, good)
        data = good.read_bytes()
        bad = tmp_path / f"bad{ext}"
        for cut in (0, 10, len(data) // 2):
            bad.write_bytes(data[:cut])
            try:
                read_mesh(bad)
            except InvalidInputError as e:
                assert "bad" in str(e)
        for i in range(15):
            m = bytearray(data)
            m[rng.integers(0, len(m))] = rng.integers(0, 256)
            bad.write_bytes(bytes(m))
            try:
                read_mesh(bad)
            except InvalidInputError as e:
                assert "bad" in str(e)


def test_registry_wraps_unexpected_reader_errors(tmp_path, monkeypatch):
    from workstation.io import ply

    path = tmp_path / "x.ply"
    write_cloud(_cloud(), path)
    with pytest.raises(TypeError):
        read_cloud(path, no_such_option=1)  # a caller's mistake stays a TypeError

    def broken(p, **opts):
        raise KeyError("internal")

    monkeypatch.setattr(ply, "read", broken)
    with pytest.raises(InvalidInputError, match=r"x\.ply: cannot read as PLY: KeyError"):
        read_cloud(path)
