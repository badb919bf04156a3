"""The fault corpus: bad inputs, bad options and bad output paths for every command.

A :class:`Case` is a command line run in a fresh copy of the good inputs
(:mod:`tests.faults.fixtures`), after ``damage`` spoils the copy. :func:`check` runs it and
lists what went wrong by the rules of the reliability issue: no traceback, no crash, no hang,
no success where an error is due, no file left behind, no input modified, and a message that
names the file or the option. :func:`cases` is the whole corpus (run in-process by the test
suite, and as separate processes with a 60 s limit by ``scripts/bench_faults.py``).
"""

from __future__ import annotations

import contextlib
import hashlib
import io
import os
import shutil
import struct
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

CLOUDS = ("cloud.laz", "cloud.las", "cloud.ply", "cloud.pcd", "cloud.xyz")


@dataclass(frozen=True)
class Case:
    """One command line against a damaged copy of the good inputs.

    ``expect`` is ``"error"`` (exit 1 or 2) or ``"ok"`` (exit 0). For an error, the message
    must hold one of ``names`` (the damaged file or the bad option). ``outputs`` are the files
    an ``ok`` case may create or replace.
    """

    id: str
    argv: tuple
    damage: Callable[[Path], None] | None = None
    expect: str = "error"
    names: tuple = ()
    outputs: tuple = ()
    timeout: float = 60.0
    then: tuple = ()  # a command line that must succeed on what an ``ok`` result wrote


@dataclass
class Outcome:
    case: Case
    rc: int | None
    stderr: str
    problems: list = field(default_factory=list)


# --- damage ----------------------------------------------------------------------------------

def truncate(name: str, frac: float):
    def f(d: Path):
        p = d / name
        p.write_bytes(p.read_bytes()[: int(p.stat().st_size * frac)])
    return f


def poke(name: str, offset: int, fmt: str, value):
    """Overwrite the binary field at ``offset`` (struct format ``fmt``, little endian)."""
    def f(d: Path):
        b = bytearray((d / name).read_bytes())
        b[offset: offset + struct.calcsize("<" + fmt)] = struct.pack("<" + fmt, value)
        (d / name).write_bytes(bytes(b))
    return f


def flip(name: str, offset: int, n: int = 8):
    def f(d: Path):
        b = bytearray((d / name).read_bytes())
        for i in range(offset, min(offset + n, len(b))):
            b[i] ^= 0xFF
        (d / name).write_bytes(bytes(b))
    return f


def replace_text(name: str, old: bytes, new: bytes):
    def f(d: Path):
        b = (d / name).read_bytes()
        assert old in b, (name, old)
        (d / name).write_bytes(b.replace(old, new, 1))
    return f


def write(name: str, data: bytes):
    def f(d: Path):
        (d / name).write_bytes(data)
    return f


def make_dir(name: str):
    def f(d: Path):
        p = d / name
        p.unlink() if p.is_file() else None
        p.mkdir(exist_ok=True)
    return f


def both(*fs):
    def f(d: Path):
        for g in fs:
            g(d)
    return f


NOT_UTF8 = b"500000.0 4000000.0 100.0\n\xff\xfe\xfa 1 2\n"
RANDOM = bytes(range(256)) * 64


# --- running ---------------------------------------------------------------------------------

def snapshot(folder: Path) -> dict:
    """sha256 of every file under ``folder`` (hidden ones included), by relative path."""
    out = {}
    for p in folder.rglob("*"):
        if p.is_file() and not p.is_symlink():
            out[p.relative_to(folder).as_posix()] = hashlib.sha256(p.read_bytes()).hexdigest()
    return out


def run_inprocess(argv, cwd: Path, timeout: float) -> tuple[int | None, str]:
    """``ws ARGV`` in this process (the test suite: imports are paid once)."""
    from workstation.cli.main import main

    err, out = io.StringIO(), io.StringIO()
    old = os.getcwd()
    os.chdir(cwd)
    try:
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(out):
            rc = main(list(argv))
    except SystemExit as e:  # a command must not exit by itself
        rc = -999 if not isinstance(e.code, int) else e.code
        err.write(f"SystemExit({e.code}) escaped main()\n")
    finally:
        os.chdir(old)
    return rc, err.getvalue()


def run_subprocess(argv, cwd: Path, timeout: float) -> tuple[int | None, str]:
    """``ws ARGV`` as its own process: a crash or a hang is seen as such."""
    try:
        r = subprocess.run([sys.executable, "-m", "workstation.cli.main", *argv], cwd=cwd, capture_output=True,
                           text=True, timeout=timeout, errors="replace")
    except subprocess.TimeoutExpired:
        return None, ""
    return r.returncode, r.stderr


def check(case: Case, good: Path, work: Path, runner=run_inprocess) -> Outcome:
    """Run ``case`` in ``work`` (a fresh copy of ``good``) and list its problems."""
    if work.exists():
        shutil.rmtree(work)
    shutil.copytree(good, work, symlinks=True)
    if case.damage is not None:
        case.damage(work)
    before = snapshot(work)
    rc, stderr = runner(case.argv, work, case.timeout)
    after = snapshot(work)
    o = Outcome(case, rc, stderr)
    if rc is None:
        o.problems.append(f"hang (> {case.timeout:.0f} s)")
    elif rc < 0 or rc > 128 or rc == -999:
        o.problems.append(f"crash (exit {rc})")
    if "Traceback" in stderr:
        o.problems.append("traceback")
    if "weights_only" in stderr:  # a library's advice to load untrusted code must not reach the user
        o.problems.append("message advises weights_only=False")
    if "internal error" in stderr:
        o.problems.append("bug reported by the error boundary")
    if case.expect == "error" and rc == 0:
        o.problems.append("wrong success")
    if case.expect == "ok" and rc not in (0, None):
        o.problems.append(f"failed (exit {rc}) where a result is due")
    allowed = set(case.outputs) if rc == 0 and case.expect in ("ok", "any") else set()
    left = sorted(k for k in set(after) - set(before) - allowed
                  if not any(a.endswith("/") and k.startswith(a) for a in allowed))  # "dir/": anything in it
    if left:
        o.problems.append(f"files left: {left[:4]}")
    changed = sorted(k for k in before if k in after and before[k] != after[k] and k not in allowed)
    gone = sorted(k for k in before if k not in after and k not in allowed)
    if changed or gone:
        o.problems.append(f"inputs modified: {(changed + gone)[:4]}")
    if rc == 0 and case.then:
        rc2, err2 = runner(case.then, work, case.timeout)
        if rc2 != 0:
            o.problems.append(f"wrong success: its output fails `ws {' '.join(case.then)}`: {err2.strip()[-200:]}")
    if rc in (1, 2) and case.expect != "ok" and case.names and not any(n in stderr for n in case.names):
        o.problems.append(f"message names none of {list(case.names)}")
    return o
