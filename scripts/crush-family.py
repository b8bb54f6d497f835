#!/usr/bin/env python3
"""A family of thin-walled pipes crushed by a ball (issue 34, docs/hard-scenes.md), run with ccm.

Each member is a rubber pipe (R 20 mm, length 50 mm, E 5 MPa, nu 0.4) lying along x,
crushed across its axis by a ball (R 10 mm, E 200 MPa, 7800 kg/m^3, 4 mm tets) with self-contact
on. The family's axes:
  - the wall's thickness in mesh sizes: 0.5, 1 or 2 (a 2 mm mesh, walls of 1, 2 and 4 mm), and
    1/3 (the scene of issue 34: a 1 mm wall meshed at 3 mm, one flat tet through it);
  - support: its lowest 0.5 mm held fixed ("fixed"), or lying on a clamped anvil ("anvil");
  - the ball's speed: 2, 8 or 20 m/s;
  - friction: 0, 0.3 or 0.5.
The run lasts until the ball has crossed the pipe's diameter at its first speed, plus 2 ms.
A well-posed member must complete with its energy balance within 1 %, or end unstable for a
physical reason. Prints one line per member and writes a CSV table.

  scripts/crush-family.py [--all | --members K] [--structure] [--ccm build/ccm] [--out DIR]

--structure also runs each member without contact over a third of its time and prints the
contact run's ns per element-step as a multiple of that structure-alone cost (issue 34's floor
is 10x), both measured in the same sitting.

By default the scene of issue 34 (1/3, fixed, 8 m/s, friction 0.3) and 8 members spread over the
axes (each level of each axis at least once); --all runs all 72; --members K: the issue's scene
and K spread members.
"""
import argparse
import csv
import itertools
import os
import random
import re
import subprocess
import sys
import time

PIPE_R, LENGTH = 0.020, 0.050
MESH = 0.002  # the pipe's mesh size, but for the issue's scene (wall_tets 1/3: 1 mm at 3 mm)
BALL_R = 0.010
STRUCTURE_WINDOW = 1.0 / 3.0  # of a member's time, for its structure-alone cost (--structure)

AXES = {
    "wall_tets": [1.0 / 3.0, 0.5, 1.0, 2.0],  # wall / mesh size
    "support": ["fixed", "anvil"],
    "speed": [2.0, 8.0, 20.0],
    "friction": [0.0, 0.3, 0.5],
}


def scene(wall_tets, support, speed, friction, contact=True, window=1.0):
    """The member's scene; without contact (the structure alone) over `window` of its time."""
    h, wall = (0.003, 0.001) if wall_tets < 0.4 else (MESH, wall_tets * MESH)
    end = window * min(2.0 * PIPE_R / speed + 2e-3, 0.025)
    lift = 0.0055 if support == "anvil" else 0.0  # the pipe 0.5 mm above the anvil's top
    parts = [f'''title = "crush family: wall {wall_tets} tets, {support}, {speed} m/s, mu {friction}"
[time]
end = {end:.6g}
output_interval = {end / 60:.6g}
max_steps = 2000000

[[bodies]]
name = "pipe"
[bodies.material]
model = "neo_hookean"
E = 5.0e6
nu = 0.4
rho = 1100.0
[bodies.geometry]
shape = "pipe"
radius = {PIPE_R}
inner_radius = {PIPE_R - wall:.6g}
length = {LENGTH}
mesh_size = {h:.6g}
[bodies.placement]
rotate_axis = [0.0, 1.0, 0.0]
rotate_deg = 90.0
translate = [0.0, 0.0, {PIPE_R + lift:.6g}]

[[bodies]]
name = "ball"
initial_velocity = [0.0, 0.0, {-speed}]
[bodies.material]
model = "neo_hookean"
E = 2.0e8
nu = 0.3
rho = 7800.0
[bodies.geometry]
shape = "sphere"
radius = {BALL_R}
mesh_size = 0.004
[bodies.placement]
translate = [{LENGTH / 2}, 0.0, {2 * PIPE_R + lift + 0.0005 + BALL_R:.6g}]
''']
    surfaces = ['"pipe"', '"ball"']
    if support == "anvil":
        parts.append('''
[[bodies]]
name = "anvil"
[bodies.material]
model = "neo_hookean"
E = 1.0e8
nu = 0.3
rho = 2000.0
[bodies.geometry]
shape = "box"
size = [0.07, 0.06, 0.005]
mesh_size = 0.005
[bodies.placement]
translate = [-0.01, -0.03, 0.0]

[[fixed]]
node_set = "anvil"
''')
        surfaces.append('"anvil"')
    else:
        parts.append('''
[[fixed]]
body = "pipe"
box = { min = [-1.0, -1.0, -1.0], max = [1.0, 1.0, 0.0005] }
''')
    if not contact:
        return "".join(parts)
    parts.append(f'''
[contact]
model = "dcr"
surfaces = [{", ".join(surfaces)}]
self_contact = true
friction = {friction}
''')
    return "".join(parts)


def spread_members(count):
    """`count` members, each level of each axis used at least once when count >= 3."""
    rng = random.Random(34)
    columns = {}
    for name, levels in AXES.items():
        column = [levels[k % len(levels)] for k in range(count)]
        rng.shuffle(column)
        columns[name] = column
    return [{name: columns[name][k] for name in AXES} for k in range(count)]


def summary_value(text, key):
    m = re.search(rf"^{key} = (.*?)\s*(#.*)?$", text, re.M)
    return m.group(1).strip('"') if m else ""


def solves_at_cap(warning):
    """The velocity solves the DCR stopped at their sweep cap, from the run's warning (0: none)."""
    m = re.search(r"(\d+) velocity solves", warning)
    return int(m.group(1)) if m else 0


def run_member(ccm, folder, index, member, structure=False):
    path = os.path.join(folder, f"member{index:02d}.toml")
    with open(path, "w") as f:
        f.write(scene(**member))
    out = os.path.join(folder, f"member{index:02d}")
    start = time.time()
    proc = subprocess.run([ccm, "run", path, "-o", out, "-q", "--threads", "1"],
                          capture_output=True, text=True)
    seconds = time.time() - start
    text = ""
    if os.path.exists(os.path.join(out, "summary.toml")):
        with open(os.path.join(out, "summary.toml")) as f:
            text = f.read()
    row = dict(member)
    row.update({
        "exit": proc.returncode,
        "verdict": summary_value(text, "verdict"),
        "energy_error_pct": 100.0 * float(summary_value(text, "energy_balance_error") or "nan"),
        "steps": summary_value(text, "steps"),
        "elements": summary_value(text, "elements"),
        "ns_per_element_step": float(summary_value(text, "ns_per_element_step") or "nan"),
        "reason": summary_value(text, "reason"),
        "warning": summary_value(text, "warning"),
        "solves_at_cap": solves_at_cap(summary_value(text, "warning")),
        "seconds": round(seconds, 1),
    })
    if proc.returncode not in (0, 3):
        row["reason"] = (proc.stderr.strip().splitlines() or ["?"])[-1]
    if structure:
        row["structure_ns_per_element_step"] = structure_cost(ccm, folder, index, member)
        row["ratio_to_structure"] = row["ns_per_element_step"] / row["structure_ns_per_element_step"]
    return row


def structure_cost(ccm, folder, index, member):
    """ns per element-step of the member's bodies stepped without contact, a third of its window
    (the same mesh and steps per second: the element kernel, output and energy sums)."""
    path = os.path.join(folder, f"member{index:02d}-structure.toml")
    with open(path, "w") as f:
        f.write(scene(**member, contact=False, window=STRUCTURE_WINDOW))
    out = os.path.join(folder, f"member{index:02d}-structure")
    subprocess.run([ccm, "run", path, "-o", out, "-q", "--threads", "1"], check=True,
                   capture_output=True, text=True)
    with open(os.path.join(out, "summary.toml")) as f:
        return float(summary_value(f.read(), "ns_per_element_step"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--all", action="store_true")
    parser.add_argument("--members", type=int, default=8)
    parser.add_argument("--ccm", default="build/ccm")
    parser.add_argument("--out", default="crush-family")
    parser.add_argument("--structure", action="store_true",
                        help="also time each member's bodies without contact, same sitting, and "
                        "print the contact run's cost as a multiple of that")
    args = parser.parse_args()
    if args.all:
        members = [dict(zip(AXES, values)) for values in itertools.product(*AXES.values())]
    else:
        issue_scene = {"wall_tets": 1.0 / 3.0, "support": "fixed", "speed": 8.0, "friction": 0.3}
        members = [issue_scene] + spread_members(args.members)
    os.makedirs(args.out, exist_ok=True)
    rows = []
    for k, member in enumerate(members):
        row = run_member(args.ccm, args.out, k, member, args.structure)
        rows.append(row)
        ok = row["verdict"] == "completed" and row["energy_error_pct"] <= 1.0
        print(f"{k:2d} wall {member['wall_tets']:5.3g} h {member['support']:5s} "
              f"{member['speed']:4g} m/s mu {member['friction']:3g}: {row['verdict']:9s} "
              f"energy {row['energy_error_pct']:7.3f} %  steps {row['steps']:>7s}  "
              f"at cap {row['solves_at_cap']:5d}  "
              f"{row['ns_per_element_step']:6.0f} ns/el-step  "
              + (f"({row['ratio_to_structure']:4.1f}x the structure's "
                 f"{row['structure_ns_per_element_step']:4.1f})  " if args.structure else "")
              + f"{row['seconds']:6.1f} s  "
              f"{'ok' if ok else 'FLOOR NOT MET'}  {row['reason']}", flush=True)
    with open(os.path.join(args.out, "crush-family.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    met = sum(r["verdict"] == "completed" and r["energy_error_pct"] <= 1.0 for r in rows)
    print(f"{met} of {len(rows)} members complete within 1 %; table: "
          f"{os.path.join(args.out, 'crush-family.csv')}")
    return 0 if met == len(rows) else 1


if __name__ == "__main__":
    sys.exit(main())
