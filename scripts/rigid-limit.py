#!/usr/bin/env python3
"""Toward the rigid limit: the rigid model's whole-impact errors against the CCM runs' own
mesh-convergence band (docs/recommendation.md, "Toward the rigid limit").

From the whole-impact grid (scenes/grids/whole-impacts.toml) it writes one grid over the levels
given, with a mesh_scale axis (a factor on every mesh size of both bodies; three meshes by
default), runs it (`ccm study run`) and prints one markdown table: per point and metric, the
rigid model's error against CCM on the same mesh (the largest over the meshes) and the CCM
runs' band (the largest change of CCM's own value between the meshes, relative to the finest
mesh's). Metrics: the designer's (peak force, deepest indentation, contact duration, rebound
speed; docs/metrics.md) and the thesis's final state (u_mean, u_max, kinetic energy; eqs.
2.37-2.39). An error inside the band is discretisation and the two contact laws, not the
impactor's stiffness.

    scripts/rigid-limit.py [--ccm build/ccm] [--er "1.0e4, 1.0e6"] [--rls "0.25, 0.5"]
        [--ke "10.0"] [--density "1.0"] [--scales "1.25, 1.0, 0.8"] [--work out/rigid-limit]
        [--jobs 2]

On a machine shared with other work, give each run one thread (CCM_THREADS=1 in the
environment): `--jobs 1` on 2 cores runs each with two, and two-thread runs on a machine whose
cores are taken read several times the CPU of one thread (docs/parallel.md).
"""
import argparse
import pathlib
import re
import sqlite3
import subprocess
import sys

from whole_impact_grid import with_levels

ROOT = pathlib.Path(__file__).resolve().parent.parent

# (name, the CCM value's column, the rigid value's column): the designer's metrics.
DESIGNER = (("peak force", "peak_force_ccm", "peak_force_rigid"),
            ("indentation", "indentation_ccm", "indentation_rigid"),
            ("duration", "contact_duration_ccm", "contact_duration_rigid"),
            ("rebound", "rebound_speed_ccm", "rebound_speed_rigid"))
# The thesis's final-state errors (the store keeps the errors, not both values).
FINAL = (("u_mean", "final_u_mean"), ("u_max", "final_u_max"), ("KE", "final_kinetic_energy"))


def grid_text(er, rls, ke, density, scales):
    text = with_levels("toward the rigid limit", er, rls, ke, density)
    return re.sub(r'(?m)^(density_ratio = \[.*)$', rf'\1\nmesh_scale = [{scales}]', text)


def other_axes(text):
    return dict((k, float(v)) for k, v in (kv.split("=") for kv in text.split(";") if kv))


def rows(store):
    con = sqlite3.connect(f"file:{store}?mode=ro", uri=True)
    con.row_factory = sqlite3.Row
    out = con.execute("""
        SELECT gp.modulus_ratio, gp.length_ratio, gp.kinetic_energy, gp.other_axes, m.*
        FROM metrics m JOIN grid_points gp ON gp.id = m.grid_point_id
        WHERE m.usable = 1""").fetchall()
    con.close()
    return out


def relative(a, b):
    return abs(a - b) / abs(b) if b else float("inf")


def point_table(points):
    """Per metric: the rigid error (largest over the meshes) and the CCM band."""
    by_scale = sorted(points, key=lambda r: other_axes(r["other_axes"])["mesh_scale"])
    finest = by_scale[0]
    cells = []
    for _, ccm, rigid in DESIGNER:
        error = max(relative(r[rigid], r[ccm]) for r in by_scale)
        band = max(relative(r[ccm], finest[ccm]) for r in by_scale)
        cells.append((error, band))
    for _, column in FINAL:  # final state: the rigid error; the band is not in the store
        cells.append((max(r[column] for r in by_scale), None))
    return cells


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--ccm", default=str(ROOT / "build/ccm"))
    p.add_argument("--er", default="1.0e4, 1.0e6")
    p.add_argument("--rls", default="0.25, 0.5")
    p.add_argument("--ke", default="10.0")
    p.add_argument("--density", default="1.0")
    p.add_argument("--scales", default="1.25, 1.0, 0.8")
    p.add_argument("--work", default="out/rigid-limit")
    p.add_argument("--jobs", type=int, default=2)
    a = p.parse_args()
    work = pathlib.Path(a.work)
    work.mkdir(parents=True, exist_ok=True)
    grid, store = work / "rigid-limit.toml", work / "rigid-limit.sqlite"
    grid.write_text(grid_text(a.er, a.rls, a.ke, a.density, a.scales))
    print(f"running {grid} ...", file=sys.stderr, flush=True)
    subprocess.run([a.ccm, "study", "run", str(grid), "--db", str(store), "--jobs", str(a.jobs),
                    "--quiet"], check=True)
    points = {}
    for r in rows(store):
        axes = other_axes(r["other_axes"])
        key = (r["modulus_ratio"], r["length_ratio"], r["kinetic_energy"], axes["density_ratio"])
        points.setdefault(key, []).append(r)
    names = [n for n, _, _ in DESIGNER] + [n for n, _ in FINAL]
    print("| ER | RLS | KE [J] | density ratio | meshes | "
          + " | ".join(f"{n}: rigid error, CCM band" if i < len(DESIGNER) else f"{n}: rigid error"
                       for i, n in enumerate(names)) + " |")
    print("|---" * (5 + len(names)) + "|")
    for key in sorted(points):
        cells = point_table(points[key])
        text = [f"{e:.4f}, {b:.4f}" + (" (inside)" if e <= b else "") if b is not None
                else f"{e:.4f}" for e, b in cells]
        print(f"| {key[0]:g} | {key[1]:g} | {key[2]:g} | {key[3]:g} | {len(points[key])} | "
              + " | ".join(text) + " |")


if __name__ == "__main__":
    main()
