"""Markdown table from `emb modes --json` outputs: cost per phase against frequency change.

Usage: python3 benchmarks/modes_table.py RUN.json [RUN.json ...]  (coarse to fine)
The finest run (most dofs) is the reference for the frequency change of the others.
"""
import json
import sys

runs = []
for path in sys.argv[1:]:
    with open(path) as f:
        runs.append(json.load(f))
runs.sort(key=lambda r: r["summary"]["dofs"])
ref = runs[-1]


def elastic(run):
    return [m["frequency_hz"] for m in run["modes"] if m["kind"] == "elastic"]


ref_f = elastic(ref)
print("| DOF | nnz(L) | mesh s | assembly s | factorisation s | eigen-solve s | checks s | "
      "total s | eigen/factor | solves | peak MB | f7 Hz | max |Δf|/f vs finest |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for r in runs:
    s = r["summary"]
    f = elastic(r)
    n = min(len(f), len(ref_f))
    change = max(abs(a - b) / b for a, b in zip(f[:n], ref_f[:n])) if r is not ref else 0.0
    print(f"| {s['dofs']} | {s['nnz_factor']/1e6:.1f}M | {s['seconds_mesh']:.1f} | "
          f"{s['seconds_assembly']:.2f} | {s['seconds_factorisation']:.2f} | "
          f"{s['seconds_eigen-solve']:.2f} | {s['seconds_checks']:.2f} | {s['seconds_total']:.1f} | "
          f"{s['seconds_eigen-solve']/s['seconds_factorisation']:.2f} | {s['solves']} | "
          f"{s['peak_memory_mb']:.0f} | {f[0]:.2f} | {change:.2e} |")
