#!/usr/bin/env python3
"""The grid's meshed rigid impactor against the analytic sphere (docs/rigid-bodies.md).

For each named point of a grid, writes the rigid model's scene twice (`[contact] rigid_impactor`
"analytic" and "meshed"), runs both with `ccm run --threads 1`, alternating, ROUNDS times, and
prints the meshed run's final-state differences (the artifact's kinetic energy, mean and largest
displacement, relative to the analytic run's), the step counts, and the process CPU ratio
(median, min-max over the rounds).

    scripts/meshed-impactor.py [--ccm build/ccm] [--grid scenes/grids/default.toml]
                               [--points 0,2,6,8] [--rounds 3] [--crease-angle DEG]
                               [--keep DIR]
"""
import argparse
import csv
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

METRICS = ("artifact.kinetic_energy", "artifact.u_mean", "artifact.u_max")


def with_impactor(grid_text, impactor):
    """The grid text with [contact] rigid_impactor set (replaced or added)."""
    text = re.sub(r'(?m)^rigid_impactor\s*=.*\n', "", grid_text)
    return re.sub(r'(?m)^\[contact\]\s*\n', '[contact]\nrigid_impactor = "%s"\n' % impactor,
                  text, count=1)


def write_scene(ccm, grid, point, out, crease_angle=None):
    scene = subprocess.run([ccm, "study", "scene", grid, "--point", str(point), "--model", "rigid"],
                           check=True, capture_output=True, text=True).stdout
    if crease_angle is not None:  # the meshed rigid body's contact only
        scene = re.sub(r'(?m)^(rigid = "impactor"\n)', r'\1crease_angle = %g\n' % crease_angle,
                       scene)
    with open(out, "w") as f:
        f.write(scene)


def run(ccm, scene, out):
    """Runs the scene; returns (final history row as a dict, steps, process CPU seconds)."""
    shutil.rmtree(out, ignore_errors=True)
    proc = subprocess.Popen([ccm, "run", scene, "--threads", "1", "--quiet", "-o", out])
    _, status, usage = os.wait4(proc.pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit("%s: ccm run failed" % scene)
    with open(os.path.join(out, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(out, "summary.toml")) as f:
        steps = int(re.search(r"(?m)^steps = (\d+)", f.read()).group(1))
    return rows[-1], steps, usage.ru_utime + usage.ru_stime


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ccm", default="build/ccm")
    ap.add_argument("--grid", default="scenes/grids/default.toml")
    ap.add_argument("--points", default="0,2,6,8")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--crease-angle", type=float,
                    help="the meshed impactor's [contact] crease_angle (default: the scene's)")
    ap.add_argument("--keep", help="folder for the scenes and runs (default: a temporary one)")
    args = ap.parse_args()
    ccm = os.path.abspath(args.ccm)
    work = args.keep or tempfile.mkdtemp(prefix="meshed-impactor.")
    os.makedirs(work, exist_ok=True)
    with open(args.grid) as f:
        grid_text = f.read()
    points = [int(p) for p in args.points.split(",")]
    scenes = {}
    for impactor in ("analytic", "meshed"):
        grid = os.path.join(work, "grid-%s.toml" % impactor)
        with open(grid, "w") as f:
            f.write(with_impactor(grid_text, impactor))
        for p in points:
            scenes[(p, impactor)] = os.path.join(work, "point%d-%s.toml" % (p, impactor))
            write_scene(ccm, grid, p, scenes[(p, impactor)], args.crease_angle)
    cpu = {key: [] for key in scenes}
    final, steps = {}, {}
    for _ in range(args.rounds):
        for p in points:
            for impactor in ("analytic", "meshed"):
                key = (p, impactor)
                out = os.path.join(work, "run-point%d-%s" % key)
                final[key], steps[key], seconds = run(ccm, scenes[key], out)
                cpu[key].append(seconds)
    print("| point | kinetic energy | mean displacement | largest displacement | steps, analytic"
          " -> meshed | CPU ratio, median (min-max) of %d |" % args.rounds)
    print("|---|---|---|---|---|---|")
    for p in points:
        a, m = final[(p, "analytic")], final[(p, "meshed")]
        errors = ["%.2f %%" % (100 * abs(float(m[k]) - float(a[k])) / abs(float(a[k])))
                  for k in METRICS]
        ratios = [mc / ac for mc, ac in zip(cpu[(p, "meshed")], cpu[(p, "analytic")])]
        print("| %d | %s | %d -> %d | %.2f (%.2f-%.2f) |" %
              (p, " | ".join(errors), steps[(p, "analytic")], steps[(p, "meshed")],
               statistics.median(ratios), min(ratios), max(ratios)))
    if not args.keep:
        shutil.rmtree(work)


if __name__ == "__main__":
    main()
