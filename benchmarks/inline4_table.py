"""Table of the inline-4 flexible-crank benchmark (benchmarks/inline4_flex.sh): per run the
wall time per engine cycle, IDA steps, and the RMS error of the nose torsion and of main
bearing 3's force over the second cycle against the reference run `ref`, relative to the
reference's RMS. Run with /usr/bin/python3 (numpy)."""
import json
import os
import sys

import numpy as np


def load(d, name):
    csv = np.genfromtxt(os.path.join(d, name + ".csv"), delimiter=",", names=True)
    summary = json.load(open(os.path.join(d, name + ".json")))["summary"]
    return csv, summary


def main():
    d = sys.argv[1]
    ref, _ = load(d, "ref")
    t = ref["t"]
    second = t >= 0.5 * t[-1] - 1e-12  # the second of two cycles
    def rms(x):
        return float(np.sqrt(np.mean(x[second] ** 2)))
    nose_ref = ref["nose_torsionrz"]
    f_ref = np.hypot(ref["main_bearing3Fx"], ref["main_bearing3Fy"])
    rows = []
    names = sorted(n[:-5] for n in os.listdir(d) if n.endswith(".json") and n != "ref.json")
    for name in ["ref"] + names:
        run, s = load(d, name)
        cycles = t[-1] / 0.04
        nose = run["nose_torsionrz"]
        f = np.hypot(run["main_bearing3Fx"], run["main_bearing3Fy"])
        e_nose = rms(nose - nose_ref) / rms(nose_ref)
        e_force = rms(f - f_ref) / rms(f_ref)
        rows.append((name, s["modal_coordinates"], s["rtol"], s["steps"],
                     s["seconds_run"] / cycles, 100 * e_nose, 100 * e_force,
                     1e3 * np.max(np.abs(nose[second]))))
    print("| run | modal coordinates | rtol | IDA steps | wall s / cycle | nose torsion RMS error % | bearing 3 force RMS error % | max nose torsion mrad |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print("| %s | %d | %.0e | %d | %.2f | %.3g | %.3g | %.3g |" % r)


if __name__ == "__main__":
    main()
