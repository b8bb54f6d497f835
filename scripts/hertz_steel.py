#!/usr/bin/env python3
"""Errors of a two-sphere Hertz run against the closed form (docs/contact-persistent.md,
"Steel spheres at +-5 m/s"): contact duration, peak force and maximum approach of the centres.

    scripts/hertz_steel.py RESULTS_DIR [RESULTS_DIR ...]

Reads RESULTS_DIR/scene.toml (material, radius, speeds) and RESULTS_DIR/history.csv (the force
output contact.<a>.<b>.force_axis, the tracked centres). The closed form (Johnson 1985, 11.4)
for identical spheres: E* = E / (2 (1 - nu^2)), R* = R / 2, m* = m / 2, with m the mesh's mass
(2 KE_0 / v^2 of one sphere, from the first history row):
    delta_max = (15 m* v^2 / (16 E* sqrt(R*)))^(2/5),   F_max = 4/3 E* sqrt(R*) delta_max^(3/2),
    t_c = 2.9432 delta_max / v                                  (v the closing speed).
"""
import csv
import math
import sys
import tomllib


def closed_form(E, nu, R, m, v):
    Es = E / (2.0 * (1.0 - nu * nu))
    Rs, ms = R / 2.0, m / 2.0
    delta = (15.0 * ms * v * v / (16.0 * Es * math.sqrt(Rs))) ** 0.4
    return {"duration": 2.9432 * delta / v, "force": 4.0 / 3.0 * Es * math.sqrt(Rs) * delta**1.5,
            "approach": delta, "a": math.sqrt(Rs * delta)}


def measured(rows, names):
    low, up = names
    force_col = next(k for k in rows[0] if k.endswith(".force_axis"))
    t = [float(r["time"]) for r in rows]
    F = [float(r[force_col]) for r in rows]
    # Each row's force is the mean over the interval ending at it: the contact lasts over the
    # intervals with a non-zero impulse.
    active = [i for i in range(1, len(rows)) if abs(F[i]) > 1e-9 * max(abs(x) for x in F)]
    duration = sum(t[i] - t[i - 1] for i in active)
    # Approach of the centres: u_z(low) - u_z(up), less what closed the initial gap before the
    # first interval with contact.
    closing = [float(r[f"{low}_centre.uz"]) - float(r[f"{up}_centre.uz"]) for r in rows]
    first = active[0] if active else 1
    approach = max(closing) - closing[first - 1]
    return {"duration": duration, "force": max(abs(x) for x in F), "approach": approach}


def main(dirs):
    for d in dirs:
        scene = tomllib.load(open(f"{d}/scene.toml", "rb"))
        b = scene["bodies"]
        mat, geo = b[0]["material"], b[0]["geometry"]
        v1 = b[0]["initial_velocity"][2]
        v2 = b[1]["initial_velocity"][2]
        rows = list(csv.DictReader(open(f"{d}/history.csv")))
        ke = float(rows[0][f"{b[0]['name']}.kinetic_energy"])
        m = 2.0 * ke / (v1 * v1)
        h = closed_form(mat["E"], mat["nu"], geo["radius"], m, abs(v1 - v2))
        got = measured(rows, (b[0]["name"], b[1]["name"]))
        err = {k: 100.0 * (got[k] / h[k] - 1.0) for k in got}
        print(f"{d}: m = {1e3 * m:.2f} g, a = {1e3 * h['a']:.3f} mm | "
              f"duration {1e6 * got['duration']:.2f} us ({err['duration']:+.2f} %), "
              f"peak force {1e-3 * got['force']:.2f} kN ({err['force']:+.2f} %), "
              f"max approach {1e6 * got['approach']:.1f} um ({err['approach']:+.2f} %)")


if __name__ == "__main__":
    main(sys.argv[1:])
