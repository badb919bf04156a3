"""What glibc's malloc settings cost the buildings stage in one process: CPU per building,
user and system time, and minor page faults of ``reconstruct_buildings`` on a district of N
buildings. Run it with and without Dask's worker default to see what a worker pays:

    PYTHONPATH=. python scripts/bench_malloc.py 150
    MALLOC_TRIM_THRESHOLD_=65536 PYTHONPATH=. python scripts/bench_malloc.py 150
"""
import json
import os
import resource
import sys

from workstation.buildings import synth
from workstation.buildings.pipeline import BuildingsParams, reconstruct_buildings


def main(n: int) -> None:
    xyz, cls, _ = synth.district(n, seed=0, density=8.0)
    reconstruct_buildings(*synth.district(4, seed=1, density=8.0)[:2], BuildingsParams(solar=None))  # warm-up
    r0 = resource.getrusage(resource.RUSAGE_SELF)
    r = reconstruct_buildings(xyz, cls, BuildingsParams(solar=None))
    r1 = resource.getrusage(resource.RUSAGE_SELF)
    print(json.dumps({"malloc_trim_threshold": os.environ.get("MALLOC_TRIM_THRESHOLD_"), "buildings": len(r.models),
                      "cpu_ms_per_building": round(1000 * r.timings["buildings_cpu_s"] / len(r.models), 1),
                      "user_s": round(r1.ru_utime - r0.ru_utime, 2), "sys_s": round(r1.ru_stime - r0.ru_stime, 2),
                      "minor_faults": r1.ru_minflt - r0.ru_minflt}))


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 150)
