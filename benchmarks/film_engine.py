#!/usr/bin/python3
"""Cost and accuracy of a finite-width film big end in an engine run (issue 30).

    flock -x /tmp/emb-cpu.lock /usr/bin/python3 benchmarks/film_engine.py [--emb EMB] [--routes A,B]

The scene is tools/scenes/engine_1cyl_reynolds.yaml (the seed's Fig. 1.1 (c): the big end
moves in its clearance, held by a mass-conserving Reynolds film fed by a crankpin drilling),
run as shipped: its first four-stroke cycle from the quasi-static film (the scene says why
not to a steady state). Routes:
  reynolds_NxM   the scene on an N x M film grid (its own grid and the others: the grid's
                 convergence; the finest grid that ran its cycle is the reference)
  ocvirk         the same engine with the big end on the short-bearing (Ocvirk,
                 half-Sommerfeld) element at the same R, L, c and viscosity (the Walther law's
                 value at the scene's temperature)
Per route: status, IDA steps, CPU seconds of `emb run` (children's rusage; run the script
under the exclusive lock) and per cycle; over the cycle the peak big-end load, the smallest
film (h_min) and its crank angle, the peak film pressure, the mean friction power, the mean
cavitated fraction and supply flow; and their differences from the reference grid. Runs in out/bench_film_engine/; results through benchmarks/record.py merge
into benchmarks/results/film_engine.json; table `film_engine` in benchmarks/README.md.
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys

import h5py

from steady_state import cycles_of, timed_run  # benchmarks/steady_state.py

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = "engine_1cyl_reynolds.yaml"
PERIOD = 0.04  # [s]: one four-stroke cycle at 3000 rpm (steady_state.PERIOD for cycles_of)
GRIDS = [(24, 4), (32, 6), (48, 8), (64, 12)]


def walther_viscosity(nu_40, nu_100, density, temperature):
    """mu [Pa s] by ASTM D341 through nu(40 C) and nu(100 C) [m^2/s] (lubricant.h)."""
    t1, t2 = 313.15, 373.15
    y1 = math.log10(math.log10(nu_40 * 1e6 + 0.7))
    y2 = math.log10(math.log10(nu_100 * 1e6 + 0.7))
    b = (y1 - y2) / (math.log10(t2) - math.log10(t1))
    a = y1 + b * math.log10(t1)
    nu = 10.0 ** (10.0 ** (a - b * math.log10(temperature))) - 0.7
    return density * nu * 1e-6


def number(text, key):
    m = re.search(r"\b%s: ([-0-9.e]+)" % key, text)
    assert m, key
    return float(m.group(1))


def variant(route, path):
    """The shipped scene for `route`, paths absolute, its output section dropped (-o)."""
    with open(os.path.join(ROOT, "tools", "scenes", SCENE)) as f:
        text = f.read()
    text = text.replace("../../", ROOT + "/")
    text = text.split("\noutput:\n")[0] + "\n"
    if route.startswith("reynolds_"):
        n, m = route.split("_")[1].split("x")
        text, k = re.subn(r"grid_circumferential: \d+, grid_axial: \d+",
                          f"grid_circumferential: {n}, grid_axial: {m}", text)
        assert k == 1, route
    else:
        start = text.index("  - {name: big_end1, type: film-bearing")
        end = text.index("\n  - name: gas1")
        block = text[start:end]
        mu = walther_viscosity(number(block, "nu_40"), number(block, "nu_100"),
                               number(block, "density"), number(block, "temperature"))
        text = (text[:start] +
                "  - {name: big_end1, type: journal-bearing, i: crank_pin1, j: rod1_big, "
                f"radius: {number(block, 'radius')}, length: {number(block, 'length')}, "
                f"clearance: {number(block, 'clearance')}, viscosity: {mu!r}}}" + text[end:])
    with open(path, "w") as f:
        f.write(text)


def last_cycle(h5, name):
    """The last whole cycle's samples of channel `name` (forces' outputs or loads)."""
    return cycles_of(h5, [name])[name][-1]


def run_route(emb, work, route):
    yaml = os.path.join(work, route + ".yaml")
    variant(route, yaml)
    h5 = os.path.join(work, route + ".h5")
    summary, cpu, wall = timed_run(emb, yaml, h5, route, "film_engine.py")
    out = {"scene": SCENE, "route": route, "status": summary["status"],
           "message": summary.get("message", ""), "steps": summary["steps"], "cpu_s": cpu,
           "wall_s": wall, "time_reached_s": summary.get("t_reached"),
           "step_limiters": summary.get("step_limiters", "")}
    with h5py.File(h5, "r") as f:
        out["cycles"] = int((len(f["time"]) - 1) * (f["time"][1] - f["time"][0]) / PERIOD + 1e-9)
        if out["cycles"] >= 1:
            F = last_cycle(f, "big_end1.F.norm")
            h = last_cycle(f, "big_end1.h_min")
            power = last_cycle(f, "big_end1.friction_power")
            out.update({"peak_load_n": float(F.max()), "min_film_m": float(h.min()),
                        "min_film_crank_deg": float(h.argmin() * 720.0 / len(h)),
                        "mean_friction_power_w": float(power.mean())})
            if route.startswith("reynolds_"):
                out.update({
                    "peak_pressure_pa": float(last_cycle(f, "big_end1.p_max").max()),
                    "mean_cavitated_fraction":
                        float(last_cycle(f, "big_end1.cavitated_fraction").mean()),
                    "mean_supply_flow_m3s": float(last_cycle(f, "big_end1.supply_flow").mean())})
    # Per cycle of simulated time; a run that failed within its first cycle has no such figure.
    out["cpu_s_per_cycle"] = (out["cpu_s"] / ((out["time_reached_s"] or 0.0) / PERIOD)
                              if out["cycles"] >= 1 else None)
    path = os.path.join(work, route + ".json")
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
    print(f"{route}: {out['status']}, {out['cycles']} cycle(s), {out['steps']} steps, "
          f"{out['cpu_s']:.1f} s CPU", flush=True)
    return path


def add_errors(paths):
    """Differences of each route's figures from those of the finest grid that ran its cycle
    (recorded as `reference` in every route)."""
    runs = {r: json.load(open(p)) for r, p in paths.items()}
    finished = [r for r in (f"reynolds_{n}x{m}" for n, m in reversed(GRIDS))
                if r in runs and "peak_load_n" in runs[r] and runs[r]["status"] == "success"]
    if not finished:
        return
    ref = runs[finished[0]]
    for route, run in runs.items():
        run["reference"] = finished[0]
        if "peak_load_n" not in run:
            continue
        for key in ("peak_load_n", "min_film_m", "mean_friction_power_w", "peak_pressure_pa"):
            if key in run and key in ref:
                run[key.rsplit("_", 1)[0] + "_vs_reference"] = run[key] / ref[key] - 1.0
    for route, run in runs.items():
        with open(paths[route], "w") as f:
            json.dump(run, f, indent=1)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--emb", default=os.path.join(ROOT, "build", "tools", "emb", "emb"))
    ap.add_argument("--routes", default="", help="comma-separated route names (default: all)")
    ap.add_argument("--reuse", action="store_true",
                    help="take the routes' results from an earlier run of this script in "
                         "out/bench_film_engine/ instead of running them (re-renders only)")
    a = ap.parse_args()
    sys.path.insert(0, os.path.join(ROOT, "tools", "plots"))
    work = os.path.join(ROOT, "out", "bench_film_engine")
    os.makedirs(work, exist_ok=True)
    routes = [f"reynolds_{n}x{m}" for n, m in GRIDS] + ["ocvirk"]
    wanted = [r for r in a.routes.split(",") if r]
    paths = {r: (os.path.join(work, r + ".json") if a.reuse else run_route(a.emb, work, r))
             for r in routes if not wanted or r in wanted}
    add_errors(paths)
    subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "benchmarks", "record.py"), "merge",
                    "film_engine", *[f"{r}={p}" for r, p in paths.items()], "--command",
                    "flock -x /tmp/emb-cpu.lock /usr/bin/python3 benchmarks/film_engine.py"],
                   check=True)
    subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "benchmarks", "render_tables.py"),
                    "--print", "film_engine"], check=True)


if __name__ == "__main__":
    main()
