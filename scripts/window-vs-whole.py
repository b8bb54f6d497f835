#!/usr/bin/env python3
"""The thesis's window against whole impacts (docs/recommendation.md, "Whole impacts").

From the whole-impact grid (scenes/grids/whole-impacts.toml) it writes two grids on the levels
given, that differ only in when a run ends: at the thesis's t_f = 0.15 s (0.05 s after first
touch), or one hold after the bodies separate (the grid's guard as the bound). It runs both
(`ccm study run`) and prints one markdown table: per point, the rigid model's largest final-state
error (eqs. 2.37-2.39) and the rule's answer in each window, the whole impact's designer errors
(peak force, indentation, contact duration, rebound; docs/metrics.md) and both cost ratios.

    scripts/window-vs-whole.py [--ccm build/ccm] [--er "1.0, 1.0e2, 1.0e4"] [--rls "1.0"]
        [--ke "1.0, 10.0, 100.0"] [--density "1.0"] [--work out/window-vs-whole] [--jobs 2]
        [--whole-store data/reference/whole-impacts.sqlite]

With --whole-store the whole impacts are read from that store (the reference store holds every
point of the whole-impact grid) and only the thesis-window runs are made.
"""
import argparse
import pathlib
import re
import sqlite3
import subprocess
import sys

from whole_impact_grid import with_levels

ROOT = pathlib.Path(__file__).resolve().parent.parent


def grid_text(title, er, rls, ke, density, whole):
    text = with_levels(title, er, rls, ke, density)
    if not whole:  # the thesis's window: t_f = 0.15 s, no separation criterion
        text = re.sub(r'(?m)^end = .*$', "end = 0.15", text)
        text = re.sub(r'(?m)^end_after_separation = .*\n', "", text)
    return text


def metrics(store):
    con = sqlite3.connect(f"file:{store}?mode=ro", uri=True)
    rows = con.execute("""
        SELECT gp.modulus_ratio, gp.length_ratio, gp.kinetic_energy, gp.other_axes, m.usable,
               max(m.final_u_mean, m.final_u_max, m.final_kinetic_energy), m.rtr, m.t_final,
               m.error_peak_force, m.error_indentation, m.error_contact_duration,
               m.error_rebound_speed, m.excluded_reason
        FROM metrics m JOIN grid_points gp ON gp.id = m.grid_point_id
        ORDER BY gp.point_index""").fetchall()
    con.close()
    return {(r[0], r[1], r[2], r[3]): r[4:] for r in rows}


def answer(error, rtr, max_error):
    return "rigid" if error <= max_error and rtr > 1.0 else "ccm"


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--ccm", default=str(ROOT / "build/ccm"))
    p.add_argument("--er", default="1.0, 1.0e2, 1.0e4")
    p.add_argument("--rls", default="1.0")
    p.add_argument("--ke", default="1.0, 10.0, 100.0")
    p.add_argument("--density", default="1.0")
    p.add_argument("--max-error", type=float, default=0.1)
    p.add_argument("--work", default="out/window-vs-whole")
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--whole-store", default="")
    a = p.parse_args()
    work = pathlib.Path(a.work)
    work.mkdir(parents=True, exist_ok=True)
    stores = {}
    for name, whole in (("window", False), ("whole", True)):
        if whole and a.whole_store:
            stores[name] = pathlib.Path(a.whole_store)
            continue
        grid = work / f"{name}.toml"
        grid.write_text(grid_text(f"{name}", a.er, a.rls, a.ke, a.density, whole))
        stores[name] = work / f"{name}.sqlite"
        print(f"running {grid} ...", file=sys.stderr, flush=True)
        subprocess.run([a.ccm, "study", "run", str(grid), "--db", str(stores[name]), "--jobs",
                        str(a.jobs), "--quiet"], check=True)
    window, whole = metrics(stores["window"]), metrics(stores["whole"])
    print(f"| ER | RLS | KE [J] | other axes | thesis window: largest final-state error, answer "
          f"| whole impact: ends at [s], largest final-state error, answer | whole impact: "
          f"peak force, indentation, duration, rebound errors | RTR window, whole |")
    print("|---|---|---|---|---|---|---|---|")
    for key in sorted(window):
        w, h = window[key], whole.get(key)
        if h is None or not w[0] or not h[0]:
            reason = (w[8] if not w[0] else (h[8] if h else "not run"))
            print(f"| {key[0]:g} | {key[1]:g} | {key[2]:g} | {key[3]} | left out: {reason} | | | |")
            continue
        designer = ", ".join("-" if v is None else f"{v:.3f}" for v in h[4:8])
        print(f"| {key[0]:g} | {key[1]:g} | {key[2]:g} | {key[3]} "
              f"| {w[1]:.3f}, {answer(w[1], w[2], a.max_error)} "
              f"| {h[3]:.3f}, {h[1]:.3f}, {answer(h[1], h[2], a.max_error)} "
              f"| {designer} | {w[2]:.2f}, {h[2]:.2f} |")


if __name__ == "__main__":
    main()
