"""Registration of partly overlapping scans of a built-up block (issue 24): the figures of
"Registration" in docs/benchmarks.md for `tests/registration/test_reg_block_overlap.py`'s scene.

Two samplings of the block mesh of the registration tests (`regutil.block_mesh`), the target
the part with x < 40 + overlap/2, the source the part of another sampling with
x >= 40 - overlap/2 moved by a station pose of `tests/pipeline/test_photos_scans.py`; then
`register()` with defaults. One line per case: rotation and translation error, fitness, the
"ambiguous" flag, wall and CPU seconds.

    PYTHONPATH=. .venv/bin/python scripts/bench_register_block.py
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

TESTS = Path(__file__).resolve().parents[1] / "tests"
sys.path[:0] = [str(TESTS / "pipeline"), str(TESTS / "registration")]

from test_photos_scans import STATIONS, block_points, pose_error  # noqa: E402

from workstation.core.cloud import Cloud  # noqa: E402
from workstation.core.errors import StageError  # noqa: E402
from workstation.registration.register import register  # noqa: E402


def case(tag: str, src, tgt, T) -> None:
    t0, c0 = time.perf_counter(), time.process_time()
    try:
        r = register(Cloud(src @ T[:3, :3].T + T[:3, 3]), Cloud(tgt))
    except StageError as ex:
        print(f"{tag}: refused ({ex})", flush=True)
        return
    rot, shift = pose_error(r.transform, T)
    print(f"{tag}: {rot:.3f} deg {shift:.3f} m, fitness {r.fitness:.2f}, ambiguous {bool(r.meta.get('ambiguous'))}, "
          f"{time.perf_counter() - t0:.1f} s wall {time.process_time() - c0:.1f} s CPU", flush=True)


def main() -> None:
    for n, seed in [(15000, 1), (8000, 0)]:
        pts, other = block_points(n, seed), block_points(n, seed + 10)
        for name in ("st2", "st3"):
            T = STATIONS[name][1]
            for ov in (40, 30, 20):
                case(f"{n} points, seed {seed}, {name}, overlap {ov} m", other[other[:, 0] >= 40 - ov / 2],
                     pts[pts[:, 0] < 40 + ov / 2], T)


if __name__ == "__main__":
    main()
