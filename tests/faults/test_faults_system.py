"""Faults from the system around a command: a full disk, a read-only folder, a signal during
the write, two processes writing the same output. Each runs ``ws`` as its own process."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

WS = [sys.executable, "-m", "workstation.cli.main"]


def _ws(*args, cwd=None, **kw):
    return subprocess.run([*WS, *map(str, args)], capture_output=True, text=True, cwd=cwd, timeout=120, **kw)


@pytest.fixture(scope="module")
def big_cloud(tmp_path_factory) -> Path:
    """A 3 M-point LAS: long enough to write that a signal or a second writer lands mid-write."""
    from workstation.core.cloud import Cloud
    from workstation.io import write_cloud

    rng = np.random.default_rng(0)
    n = 3_000_000
    xyz = np.round(np.column_stack([rng.uniform(0, 500, n), rng.uniform(0, 500, n), rng.uniform(0, 30, n)]), 3)
    p = tmp_path_factory.mktemp("big") / "big.las"
    write_cloud(Cloud(xyz, {"intensity": rng.integers(0, 999, n).astype(np.uint16)}, crs="EPSG:32632"), p)
    return p


def _mount_tmpfs(path: Path, opts: str) -> None:
    path.mkdir()
    if os.geteuid() != 0:
        pytest.skip("mounting a small file system needs root")
    r = subprocess.run(["mount", "-t", "tmpfs", "-o", opts, "tmpfs", str(path)], capture_output=True)
    if r.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs here: {r.stderr.decode().strip()}")


def _mounted(folder: Path, opts: str):
    _mount_tmpfs(folder, opts)
    yield folder
    subprocess.run(["umount", str(folder)])


@pytest.fixture
def small_disk(tmp_path):
    yield from _mounted(tmp_path / "small", "size=256k")


@pytest.fixture
def read_only(tmp_path):
    yield from _mounted(tmp_path / "ro", "ro,size=64k")


def test_disk_full_is_a_clean_error_and_leaves_nothing(big_cloud, small_disk):
    r = _ws("convert", big_cloud, small_disk / "out.laz")
    assert r.returncode == 1, r.stderr
    assert "Traceback" not in r.stderr
    assert "no space left" in r.stderr and "out.laz" in r.stderr
    assert list(small_disk.iterdir()) == []


def test_read_only_folder_is_a_clean_error(big_cloud, read_only):
    r = _ws("convert", big_cloud, read_only / "out.laz")
    assert r.returncode == 1, r.stderr
    assert "Traceback" not in r.stderr
    assert "read-only" in r.stderr and "out.laz" in r.stderr


def _signal_mid_write(big_cloud, out: Path, sig: int):
    """Start ``ws convert``; send ``sig`` once its temporary output exists; return the result."""
    proc = subprocess.Popen([*WS, "convert", str(big_cloud), str(out)], stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and proc.poll() is None:
        if any(p.name.startswith(f".{out.stem}.") for p in out.parent.iterdir()):
            break
        time.sleep(0.01)
    if proc.poll() is not None:
        pytest.skip("the write finished before the signal could be sent")
    proc.send_signal(sig)
    _, err = proc.communicate(timeout=60)
    return proc.returncode, err


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGHUP, signal.SIGINT])
def test_signal_during_write_removes_the_temporary_file(big_cloud, tmp_path, sig):
    out = tmp_path / "out" / "o.laz"
    out.parent.mkdir()
    rc, err = _signal_mid_write(big_cloud, out, sig)
    assert rc == 128 + sig, err
    assert "Traceback" not in err
    assert list(out.parent.iterdir()) == []


def test_two_writers_of_one_new_output_exactly_one_wins(big_cloud, tmp_path):
    out = tmp_path / "same.las"
    procs = [subprocess.Popen([*WS, "convert", str(big_cloud), str(out)], stderr=subprocess.PIPE, text=True)
             for _ in range(2)]
    results = [(p.wait(timeout=120), p.stderr.read()) for p in procs]
    codes = sorted(rc for rc, _ in results)
    assert codes == [0, 1], results
    loser = next(err for rc, err in results if rc == 1)
    assert "exists" in loser and "Traceback" not in loser
    assert [p.name for p in tmp_path.iterdir()] == ["same.las"]
    r = _ws("info", out)
    assert r.returncode == 0, r.stderr
