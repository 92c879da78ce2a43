"""PNG plots of an `emb compare --report-dir DIR` CSV (the speed-against-error picture).

Usage: /usr/bin/python3 benchmarks/compare_plots.py DIR/PART_SUPPORT_compare.csv ...
For each CSV X.csv writes X_error_vs_mode.png (|frequency error| per mode, one line per route;
shell modes, which no beam represents, marked) and X_error_vs_time.png (max |error| over the
modes each route is judged on against its wall time, log-log).
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {"cms": ("tab:blue", "o"), "beam": ("tab:orange", "s"), "tmm": ("tab:green", "^"),
         "fe": ("black", "*")}


def read(path):
    routes = {}
    for row in csv.DictReader(open(path)):
        r = routes.setdefault(row["route"], {"method": row["method"], "seconds": float(row["seconds"]),
                                            "modes": []})
        err = float(row["error_pct"]) if row["error_pct"] else math.nan
        r["modes"].append((int(row["mode"]), float(row["reference_hz"]), row["beam_like"] == "1", err))
        title = f"{row['part']}, {row['support']}"
    return title, routes


def judged(route, mode):
    return route["method"] in ("cms", "fe") or mode[2]


def route_color(name, r, routes):
    """CMS routes in shades of blue by mode count; the others by method."""
    if r["method"] != "cms":
        return STYLE[r["method"]][0] if "consistent" not in name else "tab:red"
    cms = [n for n, x in routes.items() if x["method"] == "cms"]
    return plt.cm.Blues(0.4 + 0.6 * cms.index(name) / max(1, len(cms) - 1))


def plot(path):
    title, routes = read(path)
    base = os.path.splitext(path)[0]
    fig, ax = plt.subplots(figsize=(8, 5))
    shells = None
    for name, r in routes.items():
        if r["method"] == "fe":
            shells = [m for m in r["modes"] if not m[2]]
            continue
        color, marker = STYLE[r["method"]]
        pts = [(m[0], abs(m[3])) for m in r["modes"] if judged(r, m) and not math.isnan(m[3])]
        if not pts:
            continue
        dashed = "--" if "elastic" in name else "-"
        ax.semilogy([p[0] for p in pts], [max(p[1], 1e-6) for p in pts], dashed, marker=marker,
                    color=route_color(name, r, routes), label=name, alpha=0.8)
    for m in shells or []:
        ax.axvline(m[0], color="grey", lw=0.5, ls=":")
    ax.set_xlabel("3-D mode number (dotted: shell modes no beam represents)")
    ax.set_ylabel("|frequency error| [%]")
    ax.set_title(f"Frequency error vs mode: {title}")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(base + "_error_vs_mode.png", dpi=110)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(7, 5))
    for name, r in routes.items():
        if r["method"] == "fe":
            ax.axvline(r["seconds"], color="black", ls="--", lw=1)
            ax.text(r["seconds"], 0.02, " 3-D FE (reference)", rotation=90, va="bottom",
                    fontsize=8, transform=ax.get_xaxis_transform())
            continue
        errs = [abs(m[3]) for m in r["modes"] if judged(r, m) and not math.isnan(m[3])]
        if not errs:
            continue
        color, marker = STYLE[r["method"]]
        face = "none" if "consistent" in name else color
        ax.loglog(r["seconds"], max(max(errs), 1e-6), marker, color=route_color(name, r, routes),
                  ms=8, mfc=face if r["method"] != "cms" else route_color(name, r, routes),
                  label=name, alpha=0.8)
    ax.set_xlabel("wall time of the route [s]")
    ax.set_ylabel("max |frequency error| over the modes compared [%]")
    ax.set_title(f"Error vs wall time: {title}")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(base + "_error_vs_time.png", dpi=110)
    plt.close(fig)
    print(f"wrote {base}_error_vs_mode.png and {base}_error_vs_time.png")


for p in sys.argv[1:]:
    plot(p)
