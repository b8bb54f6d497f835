#!/usr/bin/env python3
"""Where each thread of a ccm run spends its time, by phase (issue 35 item 3; docs/parallel.md).

    perf record -o run.data ./build/ccm run SCENE --out DIR --threads 2 --quiet
    scripts/perf-thread-shares.py run.data

Reads `perf report --sort pid,sym` (perf names threads by their id) and sums each thread's
samples into the engine's phases by symbol name. The thread with the lowest id is the main one,
which runs every serial phase; the others are OpenMP's. Shares are of all the run's samples, so
a thread's column adds up to about 1 / threads. Unresolved addresses are libgomp's (its spin and
barrier waits: Debian's libgomp has no symbols). Shares inside one profile do not drift with the
machine's speed as timings do; compare two builds by the ratio of a changed phase to an unchanged
one.
"""
import collections
import re
import subprocess
import sys

PHASES = [  # first match wins
    ("OpenMP runtime (spin, barriers)", lambda s: s.startswith("0x")),
    ("elements (kernel)", lambda s: "run_slab" in s or "log_skx" in s or "nodal_pressure" in s),
    ("node loops, integrator",
     lambda s: "for_each_index" in s or "CentralDifference" in s or "run_explicit" in s),
    ("contact: patch solve (Eigen LDLT)", lambda s: "Eigen::" in s or "PatchSolve" in s),
    ("contact: velocity sweeps", lambda s: "ContactImpulses" in s or "update_row" in s),
    ("contact: broad phase, boxes, reach",
     lambda s: any(k in s for k in ("BroadPhase", "SweptBox", "swept_box", "reach_per_body"))),
    ("contact: CCD, narrow phase",
     lambda s: any(k in s.lower() for k in ("ccd", "pairdistance", "test_candidates",
                                            "edges_stay", "triple", "orient"))),
    ("contact: position projection, its element update",
     lambda s: "Projection" in s or "first_piola" in s or "compute_inverse" in s),
    ("contact: other", lambda s: "dcr::" in s),
    ("allocation, copies", lambda s: any(k in s for k in ("malloc", "free", "memmove", "memcpy"))),
]


def phase_of(symbol):
    for name, test in PHASES:
        if test(symbol):
            return name
    return "other"


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    report = subprocess.run(["perf", "report", "-i", sys.argv[1], "--no-children", "--sort",
                             "pid,sym", "--stdio"], capture_output=True, text=True, check=True)
    rows = []
    for line in report.stdout.splitlines():
        m = re.match(r"\s+([0-9.]+)%\s+(\d+):\S+\s+\[.\]\s+(.*)", line)
        if m:
            rows.append((float(m.group(1)), int(m.group(2)), m.group(3).strip()))
    if not rows:
        sys.exit("perf-thread-shares: no samples in the report")
    threads = sorted({r[1] for r in rows})
    table = collections.defaultdict(lambda: collections.defaultdict(float))
    for share, tid, symbol in rows:
        table[phase_of(symbol)][tid] += share
    names = ["main"] + [f"thread {i}" for i in range(1, len(threads))]
    print("| phase | " + " | ".join(names) + " |")
    print("|---" * (len(threads) + 1) + "|")
    for phase, by in sorted(table.items(), key=lambda kv: -sum(kv[1].values())):
        print(f"| {phase} | " + " | ".join(f"{by[t]:.1f} %" for t in threads) + " |")
    totals = [sum(by[t] for by in table.values()) for t in threads]
    print("| all | " + " | ".join(f"{x:.1f} %" for x in totals) + " |")


if __name__ == "__main__":
    main()
