"""Markdown tables (and a PNG) from `emb reduce --json` outputs.

Usage: python3 benchmarks/reduce_table.py sizes RUN.json ...   time per phase, memory
       python3 benchmarks/reduce_table.py modes RUN.json ...   error vs modes vs wall time
"""
import json
import os
import sys

kind, paths = sys.argv[1], sys.argv[2:]
runs = [json.load(open(p)) for p in paths]

PHASES = ["mesh", "assembly", "factorisation", "eigen-solve", "constraint modes",
          "reduced matrices", "orthonormalisation", "invariants", "certificate", "write"]


def paired_errors(run):
    return [abs(r["error_percent"]) for r in run["comparison"] if isinstance(r["error_percent"], float)]


if kind == "sizes":
    print("| FE DOF | kept modes | " + " | ".join(p + " s" for p in PHASES) +
          " | total s | peak MB | max error % (≤ band) |")
    print("|---" * (len(PHASES) + 5) + "|")
    for r in runs:
        s = r["summary"]
        cells = [f"{s.get('seconds_' + p, 0.0):.1f}" for p in PHASES]
        err = paired_errors(r)
        print(f"| {s['dofs']} | {s['fixed_interface_modes']} | " + " | ".join(cells) +
              f" | {s['seconds_total'] + s.get('seconds_write', 0.0):.1f} | {s['peak_memory_mb']:.0f} | "
              f"{max(err) if err else float('nan'):.3f} |")
else:
    print("| fixed-interface modes | elastic coords | reduction s (without certificate) | "
          "max error % ≤ 6 kHz | max error % ≤ 3 kHz | not represented | min MAC |")
    print("|---|---|---|---|---|---|---|")
    points = []
    for r in runs:
        s, c = r["summary"], r["certificate"]
        t = s["seconds_total"] - s.get("seconds_certificate", 0.0)
        rows = [x for x in r["comparison"] if isinstance(x["error_percent"], float)]
        e6 = max(abs(x["error_percent"]) for x in rows)
        e3 = max(abs(x["error_percent"]) for x in rows if x["full_hz"] <= 3000)
        print(f"| {s['fixed_interface_modes']} | {s['elastic_modes']} | {t:.1f} | {e6:.3f} | {e3:.3f} | "
              f"{c.get('unrepresented', 0)} | {c.get('min_mac', float('nan')):.4f} |")
        points.append((t, e6, e3, s["fixed_interface_modes"]))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 4))
        ax.loglog([p[0] for p in points], [p[1] for p in points], "o-", label="modes ≤ 6 kHz")
        ax.loglog([p[0] for p in points], [p[2] for p in points], "s-", label="modes ≤ 3 kHz")
        for t, e6, _, n in points:
            ax.annotate(str(n), (t, e6), textcoords="offset points", xytext=(4, 4))
        ax.set_xlabel("reduction wall time [s]")
        ax.set_ylabel("max frequency error vs full FE [%]")
        ax.set_title("Crankshaft CB (93k DOF): error against cost")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
        out = os.path.join(os.path.dirname(os.path.abspath(paths[0])), "reduce_error_vs_time.png")
        fig.savefig(out, dpi=120, bbox_inches="tight")
        print(f"\n(plot: {out})")
    except ImportError:
        pass
