#!/usr/bin/env python3
"""The grid's meshed rigid impactor against the analytic sphere (docs/rigid-bodies.md).

For each named point of a grid, writes the rigid model's scene twice (`[contact] rigid_impactor`
"analytic" and "meshed"), runs both with `ccm run --threads 1`, alternating, ROUNDS times, and
prints the meshed run's final-state differences (the artifact's kinetic energy, mean and largest
displacement, relative to the analytic run's), the step counts, and the process CPU ratio
(median, min-max over the rounds).

With --schedules (dt_safety values), each point also runs both impactors once per schedule and
prints, per metric, the meshed run's difference from the analytic run averaged over the
schedules, and the analytic run's own spread over them ((max - min) / mean): a final state that
the step schedule alone moves by more than the difference does not resolve it.

    scripts/meshed-impactor.py [--ccm build/ccm] [--grid scenes/grids/default.toml]
                               [--points 0,2,6,8] [--rounds 3] [--crease-angle DEG]
                               [--schedules 0.9,0.8,0.7,0.6] [--keep DIR]
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


def with_impactor(grid_text, impactor, crease_angle=None):
    """The grid text with [contact] rigid_impactor set (replaced or added), and for the meshed
    impactor its crease_angle when given (replaced or added)."""
    text = re.sub(r'(?m)^(rigid_impactor|crease_angle)\s*=.*\n', "", grid_text)
    keys = 'rigid_impactor = "%s"\n' % impactor
    if impactor == "meshed" and crease_angle is not None:
        keys += "crease_angle = %g\n" % crease_angle
    if re.search(r'(?m)^\[contact\]\s*$', text):
        return re.sub(r'(?m)^\[contact\]\s*\n', '[contact]\n' + keys, text, count=1)
    return text + "\n[contact]\n" + keys


def write_scene(ccm, grid, point, out, dt_safety=None):
    scene = subprocess.run([ccm, "study", "scene", grid, "--point", str(point), "--model", "rigid"],
                           check=True, capture_output=True, text=True).stdout
    if dt_safety is not None:
        scene = re.sub(r'(?m)^dt_safety = .*$', "dt_safety = %g" % dt_safety, scene)
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


def relative(m, a, key):
    return (float(m[key]) - float(a[key])) / abs(float(a[key]))


def schedule_table(ccm, work, grids, points, schedules):
    """Per point and metric: the mean meshed-vs-analytic difference over the schedules, and the
    analytic run's own spread over them."""
    print("\nOver dt_safety %s: the meshed run's difference averaged over the schedules "
          "(the analytic run's own spread over them)" % ",".join("%g" % d for d in schedules))
    print("| point | kinetic energy | mean displacement | largest displacement |")
    print("|---|---|---|---|")
    for p in points:
        finals = {}
        for d in schedules:
            for impactor in ("analytic", "meshed"):
                scene = os.path.join(work, "point%d-%s-dt%g.toml" % (p, impactor, d))
                write_scene(ccm, grids[impactor], p, scene, d)
                out = os.path.join(work, "run-point%d-%s-dt%g" % (p, impactor, d))
                finals[(impactor, d)] = run(ccm, scene, out)[0]
        cells = []
        for k in METRICS:
            diffs = [relative(finals[("meshed", d)], finals[("analytic", d)], k)
                     for d in schedules]
            own = [float(finals[("analytic", d)][k]) for d in schedules]
            spread = (max(own) - min(own)) / abs(statistics.mean(own))
            cells.append("%+.2f %% (%.2f %%)" % (100 * statistics.mean(diffs), 100 * spread))
        print("| %d | %s |" % (p, " | ".join(cells)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ccm", default="build/ccm")
    ap.add_argument("--grid", default="scenes/grids/default.toml")
    ap.add_argument("--points", default="0,2,6,8")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--crease-angle", type=float,
                    help="the meshed impactor's crease angle (default: the grid's)")
    ap.add_argument("--schedules", help="dt_safety values to run each point at once more")
    ap.add_argument("--keep", help="folder for the scenes and runs (default: a temporary one)")
    args = ap.parse_args()
    ccm = os.path.abspath(args.ccm)
    work = args.keep or tempfile.mkdtemp(prefix="meshed-impactor.")
    os.makedirs(work, exist_ok=True)
    with open(args.grid) as f:
        grid_text = f.read()
    points = [int(p) for p in args.points.split(",")]
    scenes, grids = {}, {}
    for impactor in ("analytic", "meshed"):
        grids[impactor] = os.path.join(work, "grid-%s.toml" % impactor)
        with open(grids[impactor], "w") as f:
            f.write(with_impactor(grid_text, impactor, args.crease_angle))
        for p in points:
            scenes[(p, impactor)] = os.path.join(work, "point%d-%s.toml" % (p, impactor))
            write_scene(ccm, grids[impactor], p, scenes[(p, impactor)])
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
        errors = ["%.2f %%" % (100 * abs(relative(m, a, k))) for k in METRICS]
        ratios = [mc / ac for mc, ac in zip(cpu[(p, "meshed")], cpu[(p, "analytic")])]
        print("| %d | %s | %d -> %d | %.2f (%.2f-%.2f) |" %
              (p, " | ".join(errors), steps[(p, "analytic")], steps[(p, "meshed")],
               statistics.median(ratios), min(ratios), max(ratios)))
    if args.schedules:
        schedule_table(ccm, work, grids, points, [float(d) for d in args.schedules.split(",")])
    if not args.keep:
        shutil.rmtree(work)


if __name__ == "__main__":
    main()
