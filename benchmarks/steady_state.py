#!/usr/bin/python3
"""Cost to periodic steady state of engine scenes, by start route (issue 19).

    flock -x /tmp/emb-cpu.lock /usr/bin/python3 benchmarks/steady_state.py [--emb EMB]

Each route is a scene run with `analysis.steady_state` (whole 720-degree cycles until the
chosen channels repeat to TOLERANCE, relative RMS; libemb/results/steady_state.h) instead of
its fixed two cycles:
  engine_1cyl_cms.yaml  flexible single-throw crank (the scene's installed basis):
                        `elastic_start: as-given`
                        (undeformed) against `quasi-static` (needs out/crankshaft_1cyl.h5;
                        made here with `emb reduce meshes/crankshaft_1cyl.geo -n 30` if absent)
  engine_1cyl_rigid.yaml  the same engine, rigid crank
  inline4_rigid.yaml    the rigid inline-4, consistent start and crank + flywheel 5 % fast
Per route: the cycles run, the IDA steps, CPU and wall seconds of `emb run` (children's
rusage; run the script under the exclusive lock), the last change, and the start-up error
the steady-state run removes: the relative RMS difference of cycle 1 and of cycle 2 (what a
fixed two-cycle run reports) from the steady cycle, the largest over the channels; for that
channel the transient (cycle minus steady cycle): its mean decay per cycle and the dominant
frequency of its ringing (each cycle's mean removed).
Runs in out/bench_steady/; results through benchmarks/record.py merge into
benchmarks/results/steady_state.json; table `steady_state` in benchmarks/README.md.
"""
import argparse
import json
import os
import re
import resource
import subprocess
import sys
import time

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TOLERANCE = 1e-3
MAX_CYCLES = 30
PERIOD = 0.04  # [s]: one four-stroke cycle at 3000 rpm
ONE_CYL = ["main_bearing1.F.norm", "main_bearing2.F.norm", "flywheel_bolt.T.z", "nose_torsion.rz"]
INLINE4 = ["main_bearing_3.F.norm", "main_bearing_5.F.norm", "flywheel_bolts.T.z"]
# name, scene, channels, elastic start, factor on the crank's and flywheel's initial speed
ROUTES = [
    ("1cyl_cms_undeformed", "engine_1cyl_cms.yaml", ONE_CYL, "as-given", 1.0),
    ("1cyl_cms_quasi_static", "engine_1cyl_cms.yaml", ONE_CYL, "quasi-static", 1.0),
    ("1cyl_rigid", "engine_1cyl_rigid.yaml", ONE_CYL[:3], "as-given", 1.0),
    ("inline4_rigid", "inline4_rigid.yaml", INLINE4, "as-given", 1.0),
    ("inline4_rigid_speed_5pc", "inline4_rigid.yaml", INLINE4, "as-given", 1.05),
]


def variant(scene, channels, start, factor, path):
    """The scene with its analysis running to steady state from `start`, paths absolute."""
    with open(os.path.join(ROOT, "tools", "scenes", scene)) as f:
        text = f.read()
    text = text.replace("../../", ROOT + "/")
    head, sep, tail = text.partition("\nanalysis:\n")
    assert sep, scene
    lines = [l for l in tail.split("\n") if not re.match(r"\s+(t_end|steady_state|period|"
                                                           r"channels|tolerance|min_cycles|max_cycles|"
                                                           r"elastic_start):", l)]
    end = next((i for i, l in enumerate(lines) if i and l and not l.startswith((" ", "#"))),
               len(lines))  # the next section
    body = lines[:end] + [f"  elastic_start: {start}", "  steady_state:",
                          f"    period: {PERIOD}", f"    channels: [{', '.join(channels)}]",
                          f"    tolerance: {TOLERANCE}", f"    max_cycles: {MAX_CYCLES}"]
    # The output section goes: the runs write where -o says.
    skip = False
    for l in lines[end:]:
        if l and not l.startswith((" ", "#")):
            skip = l.startswith("output:")
        if not skip:
            body.append(l)
    text = head + sep + "\n".join(body) + "\n"
    if factor != 1.0:
        def faster(m):
            return m.group(1) + repr(float(m.group(2)) * factor)
        for name in ("crank", "flywheel"):
            text, n = re.subn(r"(- \{name: %s,[^}]*?angular_velocity: \[)([-0-9.e]+)" % name,
                              faster, text, count=1, flags=re.S)
            assert n == 1, (scene, name)
    with open(path, "w") as f:
        f.write(text)


def cycles_of(h5, channels):
    """Per channel the samples of every whole cycle [cycle][sample] (end sample excluded)."""
    from engine_plots import channel  # tools/plots/engine_plots.py: the same channel reader
    t = h5["time"][:]
    n = int(round(PERIOD / (t[1] - t[0])))
    k = (len(t) - 1) // n
    return {c: channel(h5, c)[:k * n].reshape(k, n) for c in channels}


def rel_rms(a, b):
    return float(np.sqrt(np.sum((a - b) ** 2) / np.sum(b ** 2)))


def timed_run(emb, yaml, h5, name, script):
    """`emb run YAML -o H5 --json`: its summary, CPU seconds (children's rusage) and wall
    seconds; exits naming `script` and the route if emb failed other than numerically."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    r = subprocess.run([emb, "run", yaml, "-q", "--json", "-o", h5], capture_output=True, text=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if r.returncode not in (0, 3):
        sys.exit(f"{script}: {name}: emb run failed ({r.returncode}):\n{r.stderr}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return json.loads(r.stdout)["summary"], cpu, wall


def run_route(emb, work, name, scene, channels, start, factor):
    yaml = os.path.join(work, name + ".yaml")
    variant(scene, channels, start, factor, yaml)
    h5 = os.path.join(work, name + ".h5")
    summary, cpu, wall = timed_run(emb, yaml, h5, name, "steady_state.py")
    with h5py.File(h5, "r") as f:
        per = cycles_of(f, channels)
        converged = bool(int(f.attrs["steady_state_converged"]))
        cycles = int(f.attrs["steady_state_cycles"])
    steady = {c: v[-1] for c, v in per.items()}
    err = [max(rel_rms(v[k], steady[c]) for c, v in per.items()) for k in (0, 1)]
    worst = [max(per, key=lambda c: rel_rms(per[c][k], steady[c])) for k in (0, 1)]
    # The start-up transient of the worst channel: cycle minus steady cycle, its mean decay
    # per cycle over the cycles before the last two and its dominant frequency.
    transient = per[worst[0]][:-1] - steady[worst[0]]
    size = np.sqrt(np.mean(transient ** 2, axis=1))
    m = max(1, min(len(size) - 1, 6))
    decay = float((size[m] / size[0]) ** (1.0 / m)) if len(size) > 1 and size[0] > 0 else None
    dt = PERIOD / transient.shape[1]
    # Each cycle's mean taken out: the frequency of the ringing, not of the steps between
    # cycles of a decaying mean.
    ringing = transient[:m + 1] - transient[:m + 1].mean(axis=1, keepdims=True)
    spectrum = np.abs(np.fft.rfft(ringing.ravel()))
    frequency = float(np.fft.rfftfreq(ringing.size, dt)[np.argmax(spectrum[1:]) + 1])
    out = {"scene": scene, "elastic_start": start, "speed_factor": factor,
           "channels": channels, "tolerance": TOLERANCE, "converged": converged,
           "cycles": cycles,
           "change": summary.get("steady_state_change"), "steps": summary["steps"],
           "cpu_s": cpu, "wall_s": wall, "seconds_run": summary["seconds_run"],
           "cycle1_error": err[0], "cycle1_worst_channel": worst[0],
           "cycle2_error": err[1], "cycle2_worst_channel": worst[1],
           "start_note": summary.get("elastic_start", ""),
           "transient_decay_per_cycle": decay, "transient_frequency_hz": frequency}
    out["cpu_s_per_cycle"] = out["cpu_s"] / out["cycles"]
    path = os.path.join(work, name + ".json")
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
    print(f"{name}: {out['cycles']} cycles, {out['steps']} steps, {out['cpu_s']:.2f} s CPU; "
          f"cycle 1 off by {err[0]:.3g} ({worst[0]}), cycle 2 by {err[1]:.3g}", flush=True)
    return path


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--emb", default=os.path.join(ROOT, "build", "tools", "emb", "emb"))
    ap.add_argument("--routes", default="", help="comma-separated route names (default: all)")
    a = ap.parse_args()
    sys.path.insert(0, os.path.join(ROOT, "tools", "plots"))
    work = os.path.join(ROOT, "out", "bench_steady")
    os.makedirs(work, exist_ok=True)
    body = os.path.join(ROOT, "out", "crankshaft_1cyl.h5")
    if not os.path.exists(body):
        subprocess.run([a.emb, "reduce", os.path.join(ROOT, "meshes", "crankshaft_1cyl.geo"),
                        "-n", "30", "-o", body, "-q"], check=True)
    wanted = [r for r in a.routes.split(",") if r]
    items = [f"{r[0]}={run_route(a.emb, work, *r)}" for r in ROUTES
             if not wanted or r[0] in wanted]
    subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "benchmarks", "record.py"), "merge",
                    "steady_state", *items, "--command",
                    "flock -x /tmp/emb-cpu.lock /usr/bin/python3 benchmarks/steady_state.py"],
                   check=True)
    subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "benchmarks", "render_tables.py"),
                    "--print", "steady_state"], check=True)


if __name__ == "__main__":
    main()
