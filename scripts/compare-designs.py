#!/usr/bin/env python3
"""`ccm compare` on the repository's design scenes at several settings (docs/compare.md).

Each case is a scene of scenes/examples or scenes/designs, the body to make rigid, and the edits
that make the setting (exact lines of the scene replaced: a stiffness, a speed). For every case
the variant scene is written to a work folder, `ccm compare --json` runs it (each run is kept
under its content hash in the work folder, so a second call reuses them), and one markdown table
row is printed: the measured worst final-state error and cost ratio, the measured answer, the
study store's prediction at the scene's own groups, whether it held, and the groups outside the
study's grid.

    scripts/compare-designs.py [--ccm build/ccm] [--db results/default-study.sqlite]
                               [--work out/compare-designs] [--whole GUARD]

With --whole GUARD each scene runs its whole impact instead: `end` becomes the guard (seconds)
and `end_after_separation` ends a run a quarter of the scene's own `end` after the bodies
separate (a contact that closes again within it goes on), as a store of whole impacts compares
them (the reference store ccm ships: --db data/reference/whole-impacts.sqlite, or a copy of it,
since compare records into its --db).
"""
import argparse
import json
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent

# (name, scene, rigid body, {old line: new line})
CASES = [
    ("pad on limb, pad 5 MPa, 1 m/s", "scenes/examples/pad_on_limb_dcr.toml", "pad", {}),
    ("pad on limb, pad 0.5 MPa", "scenes/examples/pad_on_limb_dcr.toml", "pad",
     {"E = 5.0e6": "E = 5.0e5"}),
    ("pad on limb, 3 m/s", "scenes/examples/pad_on_limb_dcr.toml", "pad",
     {"initial_velocity = [0.0, 0.0, -1.0]   # m/s": "initial_velocity = [0.0, 0.0, -3.0]"}),
    ("shell on torso, shell 1 GPa", "scenes/designs/shell_on_torso.toml", "shell", {}),
    ("shell on torso, shell 3 MPa", "scenes/designs/shell_on_torso.toml", "shell",
     {"E = 1.0e9": "E = 3.0e6"}),
    ("ring on limb, ring 2 GPa, 1 m/s", "scenes/designs/ring_on_limb.toml", "ring", {}),
    ("ring on limb, 3 m/s", "scenes/designs/ring_on_limb.toml", "ring",
     {"initial_velocity = [0.0, 0.0, -1.0]   # m/s": "initial_velocity = [0.0, 0.0, -3.0]"}),
]


def variant(scene: pathlib.Path, edits: dict, out: pathlib.Path, guard: float) -> pathlib.Path:
    text = scene.read_text()
    for old, new in edits.items():
        if text.count(old) != 1:
            sys.exit(f"{scene}: the line '{old}' is not there exactly once")
        text = text.replace(old, new)
    if guard > 0:  # the whole impact: the guard as end, ended a quarter of the old end after
        end = float(re.search(r"(?m)^end = ([0-9.eE+-]+)", text).group(1))  # the separation
        text = re.sub(r"(?m)^end = [0-9.eE+-]+(.*)$",
                      f"end = {guard}\nend_after_separation = {end / 4:g}", text, count=1)
    out.write_text(text)
    return out


def row(name: str, j: dict) -> str:
    worst = max((e["final_state"] for e in j["errors"]), default=float("nan"))
    measured = j.get("decision", {}).get("model", "none (" + j.get("unusable", "?") + ")")
    p = j["study_prediction"]
    g = p.get("groups", {})
    groups = (f"{g['er']:.3g} / {g['rls']:.3g} / {g['ke_star']:.2g}" if g else "–")
    if "model" in p:
        predicted = p["model"] + ("" if p["reliable"] else " (unreliable)")
        held = "yes" if p.get("agrees_with_measured") else "**no**"
        outside = "; ".join(p["outside_grid"]) or "inside"
    else:
        predicted, held, outside = "–", "–", p.get("note", "")
    return (f"| {name} | {groups} | {worst:.3g} | {j['cost_ratio']:.2f} | {measured} | "
            f"{predicted} | {held} | {outside} |")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ccm", default=str(ROOT / "build" / "ccm"))
    ap.add_argument("--db", default=str(ROOT / "results" / "default-study.sqlite"))
    ap.add_argument("--work", default=str(ROOT / "out" / "compare-designs"))
    ap.add_argument("--whole", type=float, default=0.0, metavar="GUARD")
    args = ap.parse_args()
    work = pathlib.Path(args.work)
    work.mkdir(parents=True, exist_ok=True)
    print("| case | ER / RLS / KE* | worst final-state error | cost ratio | measured answer | "
          "the store predicts | held | groups outside the store's grid |")
    print("|---|---|---|---|---|---|---|---|")
    for k, (name, scene, rigid, edits) in enumerate(CASES):
        path = variant(ROOT / scene, edits, work / f"case{k}.toml", args.whole)
        r = subprocess.run([args.ccm, "compare", str(path), "--rigid", rigid, "--db", args.db,
                            "--out", str(work / f"case{k}"), "--json", "--quiet",
                            "--threads", "1"], capture_output=True, text=True)
        if r.returncode not in (0, 3):
            sys.exit(f"{name}: ccm compare failed ({r.returncode}): {r.stderr}")
        print(row(name, json.loads(r.stdout)), flush=True)


if __name__ == "__main__":
    main()
