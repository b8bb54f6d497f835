#!/usr/bin/env python3
"""`ccm study refine` against the same study on a finer grid (docs/refine.md, "Measured").

From a thesis grid file (default scenes/grids/default.toml) it writes two grids that differ only
in their ER levels: a coarse one (every COARSE decades) and a fine one (every FINE decades), on
the RLS and KE levels given (without the convergence runs). It runs both (`ccm study run`), refines the
coarse one to the fine spacing (`ccm study refine --tolerance FINE`), asks the fine one for its
boundaries (a refine with a tolerance above its spacing runs nothing) and prints the runs each
used and one markdown table: per line of the grid (RLS, KE) the boundaries' brackets in ER.

    scripts/refine-vs-fine.py [--ccm build/ccm] [--grid scenes/grids/default.toml]
        [--er-decades 0 4] [--coarse 2] [--fine 0.25] [--rls "0.5, 1.0"] [--ke "10.0, 50.0"]
        [--work out/refine-vs-fine] [--jobs 2]
"""
import argparse
import math
import pathlib
import re
import sqlite3
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent


def levels(first, last, step):
    n = round((last - first) / step)
    return [10.0 ** (first + k * step) for k in range(n + 1)]


def grid_text(base, title, ers, rls, ke):
    text = base.split("# Mesh convergence")[0].split("[convergence]")[0]
    text = re.sub(r'(?m)^title = .*$', f'title = "{title}"', text)
    text = re.sub(r'(?m)^ER = \[.*$', "ER = [" + ", ".join(f"{v:.17g}" for v in ers) + "]", text)
    text = re.sub(r'(?m)^RLS = \[.*$', f"RLS = [{rls}]", text)
    text = re.sub(r'(?m)^KE = \[.*$', f"KE = [{ke}]", text)
    return text


def run(args, *words):
    done = subprocess.run([args.ccm, *words], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"{' '.join(words)}: exit {done.returncode}\n{done.stderr}")
    return done.stdout


def runs_stored(db):
    with sqlite3.connect(db) as c:
        return c.execute("SELECT COUNT(*) FROM runs WHERE status = 'completed'").fetchone()[0]


def boundaries(refine_output):
    """{line: [(answer, ER, answer, ER, width)]} of a refine's printed boundaries."""
    out = {}
    for line, a, x, b, y, w, cause in re.findall(
            r"(?m)^  (.*): (\w+) at ER ([0-9.e+-]+), (\w+) at ER ([0-9.e+-]+) \(([0-9.]+) decades"
            r".*; the (errors and the cost|errors|cost) chang", refine_output):
        out.setdefault(line, []).append((a, float(x), b, float(y), cause))
    return out


def bracket_text(found):
    return "; ".join(f"{a} {x:.4g} / {b} {y:.4g} ({c})" for a, x, b, y, c in found) or "none"


def shift(refined, fine):
    """Decades between the two boundaries' middles, when each line has one."""
    if len(refined) != 1 or len(fine) != 1:
        return "-"
    (_, x1, _, y1, _), (_, x2, _, y2, _) = refined[0], fine[0]
    return f"{abs(math.log10(math.sqrt(x1 * y1) / math.sqrt(x2 * y2))):.2f}"


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--ccm", default=str(ROOT / "build" / "ccm"))
    p.add_argument("--grid", default=str(ROOT / "scenes" / "grids" / "default.toml"))
    p.add_argument("--er-decades", nargs=2, type=float, default=[0.0, 4.0])
    p.add_argument("--coarse", type=float, default=2.0)
    p.add_argument("--fine", type=float, default=0.25)
    p.add_argument("--rls", default="1.0")
    p.add_argument("--ke", default="50.0")
    p.add_argument("--work", default=str(ROOT / "out" / "refine-vs-fine"))
    p.add_argument("--jobs", default="2")
    args = p.parse_args()
    work = pathlib.Path(args.work)
    work.mkdir(parents=True, exist_ok=True)
    base = pathlib.Path(args.grid).read_text()
    first, last = args.er_decades
    out = {}
    for name, step in (("coarse", args.coarse), ("fine", args.fine)):
        grid = work / f"{name}.toml"
        grid.write_text(grid_text(base, f"ER every {step} decades", levels(first, last, step),
                                  args.rls, args.ke))
        db = work / f"{name}.sqlite"
        db.unlink(missing_ok=True)
        run(args, "study", "run", str(grid), "--db", str(db), "--jobs", args.jobs, "--quiet")
        out[name] = db
    refined = run(args, "study", "refine", "--db", str(out["coarse"]), "--tolerance",
                  str(args.fine), "--jobs", args.jobs, "--quiet")
    fine = run(args, "study", "refine", "--db", str(out["fine"]), "--tolerance", "100",
               "--quiet")
    r, f = boundaries(refined), boundaries(fine)
    print(f"runs: coarse grid refined {runs_stored(out['coarse'])}, fine grid "
          f"{runs_stored(out['fine'])}; tolerance {args.fine} decades\n")
    print("| line | refined coarse grid: answer at ER / answer at ER | fine grid | "
          "middles apart [decades] |")
    print("|---|---|---|---|")
    for line in sorted(set(r) | set(f)):
        print(f"| {line} | {bracket_text(r.get(line, []))} | {bracket_text(f.get(line, []))} | "
              f"{shift(r.get(line, []), f.get(line, []))} |")


if __name__ == "__main__":
    main()
