"""Run the fault corpus (tests/faults) and count what the reliability issue counts.

Each case runs as its own ``ws`` process with a 60 s limit (so a crash or a hang is seen), in
a fresh copy of the good inputs. Prints one line per problem case and the totals; writes the
table as JSON with ``--json PATH``.

    python scripts/bench_faults.py                 # every case, as processes (~10 min)
    python scripts/bench_faults.py --in-process    # faster, as the test suite runs them
    python scripts/bench_faults.py -k ply          # only cases whose id holds "ply"
"""

from __future__ import annotations

import argparse
import collections
import json
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from tests.faults import fixtures  # noqa: E402
from tests.faults.cases import cases  # noqa: E402
from tests.faults.corpus import check, run_inprocess, run_subprocess  # noqa: E402

KINDS = ("traceback", "crash", "hang", "wrong success", "files left", "inputs modified", "message names none",
         "bug reported", "failed")


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--in-process", action="store_true")
    ap.add_argument("-k", default="", help="only cases whose id holds this")
    ap.add_argument("-x", "--exclude", default=None, help="skip cases whose id holds this")
    ap.add_argument("--json", default=None)
    args = ap.parse_args()
    runner = run_inprocess if args.in_process else run_subprocess
    with tempfile.TemporaryDirectory() as tmp:
        good = fixtures.build(Path(tmp) / "good")
        selected = [c for c in cases() if args.k in c.id and not (args.exclude and args.exclude in c.id)]
        totals = collections.Counter()
        slowest = (0.0, "")
        rows = []
        for c in selected:
            t0 = time.perf_counter()
            o = check(c, good, Path(tmp) / "work", runner)
            dt = time.perf_counter() - t0
            slowest = max(slowest, (dt, c.id))
            totals["cases"] += 1
            totals["clean error" if o.rc in (1, 2) else ("ok" if o.rc == 0 else "other")] += 1
            for p in o.problems:
                totals[next((k for k in KINDS if p.startswith(k)), p)] += 1
            if o.problems:
                last = o.stderr.strip().splitlines()[-1:] or [""]
                print(f"{c.id}: {'; '.join(o.problems)} | rc={o.rc} | {last[0][:160]}", flush=True)
            rows.append({"id": c.id, "rc": o.rc, "problems": o.problems, "seconds": round(dt, 2)})
    print("\n" + "  ".join(f"{k}: {v}" for k, v in totals.items()))
    print(f"slowest case: {slowest[1]} {slowest[0]:.1f} s")
    if args.json:
        Path(args.json).write_text(json.dumps({"totals": totals, "cases": rows}, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
