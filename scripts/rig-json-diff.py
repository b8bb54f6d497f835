#!/usr/bin/env python3
"""Two `ccm rig run ... --json` documents value by value (bench/results/rig-scene-path-*.md,
rig-bench-path-*.md): every number and string of the run, the model and the comparison, leaving
out what differs between any two runs (timestamps, wall and CPU times, store paths and ids).
Prints how many values were compared, how many differ, the largest relative difference and
where; exit 1 when any differs by more than --tolerance (default 0: bit for bit).

Usage: scripts/rig-json-diff.py BEFORE.json AFTER.json [--only comparison] [--tolerance 1e-9]
"""
import argparse
import json
import sys

SKIP = ("started_at", "ended_at", "wall", ".db", "rig_runs_id", "files", "seconds", "cpu")


def flat(x, path=""):
    if isinstance(x, dict):
        for k, v in x.items():
            yield from flat(v, f"{path}.{k}")
    elif isinstance(x, list):
        for i, v in enumerate(x):
            yield from flat(v, f"{path}[{i}]")
    else:
        yield path, x


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("before")
    ap.add_argument("after")
    ap.add_argument("--only", help="compare this top-level key alone (e.g. comparison)")
    ap.add_argument("--tolerance", type=float, default=0.0, help="relative")
    a = ap.parse_args()
    docs = [json.load(open(f)) for f in (a.before, a.after)]
    if a.only:
        docs = [d[a.only] for d in docs]
    before, after = (dict(flat(d)) for d in docs)
    keys = sorted(k for k in set(before) | set(after) if not any(s in k for s in SKIP))
    worst, where, differ = 0.0, None, []
    for k in keys:
        x, y = before.get(k), after.get(k)
        if isinstance(x, (int, float)) and isinstance(y, (int, float)) and not isinstance(x, bool):
            rel = abs(x - y) / abs(x) if x != 0 else abs(y)
            if rel > worst:
                worst, where = rel, k
            if rel > a.tolerance:
                differ.append(k)
        elif x != y:
            differ.append(k)
    print(f"{len(keys)} values compared, {len(differ)} differ"
          f" (tolerance {a.tolerance:g}); largest relative difference {worst:.3g}"
          + (f" at {where}" if where else ""))
    for k in differ[:10]:
        print(f"  {k}: {before.get(k)!r} -> {after.get(k)!r}")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
