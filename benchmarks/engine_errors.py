"""Errors of engine runs against a reference run, cycle by cycle (benchmarks/record.py engine).

A run is DIR/NAME.json (`emb run --json`) and DIR/NAME.csv (the scene's CSV channels). When the
run searched for its periodic steady state (analysis.steady_state), its steady cycle is compared
with the reference's steady cycle, sample by sample at the same phase of the cycle (both are
time-locked to the engine's motion, and the output step divides the period); otherwise (a
transient such as the load step) the second half of each record is compared at the same times.

Channels: the nose torsion (sensor nose_torsion, rz), |F| of every main bearing
(main_bearingK.F.norm) and |F| of every big end (big_endK.F.{x,y,z}); each error is the RMS of
the difference over the compared window relative to the RMS of the reference there.
"""
import json
import os

import numpy as np


def _read(directory, name):
    with open(os.path.join(directory, name + ".json")) as f:
        summary = json.load(f)["summary"]
    with open(os.path.join(directory, name + ".csv")) as f:
        head = f.readline().strip().split(",")
    values = np.loadtxt(os.path.join(directory, name + ".csv"), delimiter=",", skiprows=1, ndmin=2)
    return summary, {h: values[:, i] for i, h in enumerate(head)}


def _signals(csv):
    out = {"nose_torsion": csv["nose_torsion.rz"]}
    for k in range(1, 6):
        name = "main_bearing%d.F.norm" % k
        if name in csv:
            out["main_bearing%d" % k] = csv[name]
    for k in range(1, 5):
        parts = ["big_end%d.F.%s" % (k, c) for c in "xyz"]
        if all(p in csv for p in parts):
            out["big_end%d" % k] = np.sqrt(sum(csv[p] ** 2 for p in parts))
    return out


def _window(summary, csv):
    """(first index, last index + 1) of the compared window of a run."""
    t = csv["t"]
    if "steady_state_cycle_start" in summary:
        a, b = summary["steady_state_cycle_start"], summary["steady_state_cycle_end"]
        idx = np.nonzero((t >= a - 1e-9) & (t <= b + 1e-9))[0]
        return int(idx[0]), int(idx[-1]) + 1
    return int(np.searchsorted(t, 0.5 * t[-1] - 1e-12)), len(t)


def compare(directory, reference, names, cycle_s):
    """Rows for `names` against `reference` (both in `directory`); cycle_s: one cycle [s]."""
    ref_summary, ref_csv = _read(directory, reference)
    ref = _signals(ref_csv)
    r0, r1 = _window(ref_summary, ref_csv)
    rows = []
    for name in names:
        summary, csv = _read(directory, name)
        run = _signals(csv)
        a, b = _window(summary, csv)
        n = min(r1 - r0, b - a)
        errors = {}
        for key, x in ref.items():
            if key in run:
                d = run[key][b - n:b] - x[r1 - n:r1]
                errors[key] = 100.0 * float(np.sqrt(np.mean(d ** 2)) / np.sqrt(np.mean(x[r1 - n:r1] ** 2)))
        cycles = csv["t"][-1] / cycle_s
        with open(os.path.join(directory, name + ".time")) as f:  # /usr/bin/time: user sys wall
            user, system, wall = (float(x) for x in f.read().split()[-3:])
        seconds = user + system
        family = lambda prefix: max((v for k, v in errors.items() if k.startswith(prefix)), default=None)
        rows.append({
            "name": name, "status": summary["status"],
            "modal_coordinates": summary["modal_coordinates"], "rtol": summary.get("rtol"),
            "steps": summary.get("steps"), "error_test_failures": summary.get("error_test_failures"),
            "cycles": round(cycles, 6), "cpu_seconds": seconds, "wall_seconds": wall,
            "seconds_run": summary["seconds_run"], "cpu_seconds_per_cycle": seconds / cycles,
            "steady_state": summary.get("steady_state"),
            "steady_state_change": summary.get("steady_state_change"),
            "errors_pct": errors, "max_error_pct": max(errors.values()) if name != reference else 0.0,
            "nose_torsion_error_pct": errors.get("nose_torsion"),
            "main_bearing_error_pct": family("main_bearing"),
            "big_end_error_pct": family("big_end"),
        })
    return rows
