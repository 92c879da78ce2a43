#!/usr/bin/python3
"""Campbell diagram plot of `emb campbell -o DIAGRAM.json` (issue 17).

    /usr/bin/python3 tools/plots/campbell_plot.py DIAGRAM.json [--out campbell.png]
        [--orders 1,2,4,6] [--fmax 2500] [--title TEXT]

Draws every tracked mode's installed frequency [Hz] against the speed [rpm] (colour and
line style by class: torsion solid, bending dashed, axial dotted; forward/backward whirl in
the legend), the engine-order lines f = k n / 60 for the orders of the diagram (or --orders),
and marks the critical speeds (the diagram's `crossings`: order k meets mode f at
n = 60 f / k) with circles, labelled with their order. Modes are drawn as tracked by MAC, so a
line keeps its mode through crossings. Exits 1 naming the problem for a file that is not a
Campbell diagram.
"""
import argparse
import json
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

STYLE = {"torsion": ("tab:red", "-"), "bending": ("tab:blue", "--"), "axial": ("tab:green", ":")}


def fail(message):
    print("campbell_plot.py: error: " + message, file=sys.stderr)
    sys.exit(1)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("diagram", help="JSON written by emb campbell -o")
    p.add_argument("--out", default="campbell.png", help="PNG to write")
    p.add_argument("--orders", help="orders to draw, e.g. 1,2,4,6 (default: the diagram's)")
    p.add_argument("--fmax", type=float, help="upper frequency limit of the plot [Hz]")
    p.add_argument("--title", help="plot title (default: the scene)")
    a = p.parse_args()
    try:
        with open(a.diagram) as f:
            d = json.load(f)
    except (OSError, ValueError) as e:
        fail("cannot read %s: %s" % (a.diagram, e))
    for key in ("rpm", "modes", "crossings", "orders"):
        if key not in d:
            fail("%s: expected a Campbell diagram (emb campbell -o), missing '%s'" % (a.diagram, key))
    rpm = np.asarray(d["rpm"], dtype=float)
    orders = [float(x) for x in a.orders.split(",")] if a.orders else d["orders"]
    fmax = a.fmax or d.get("fmax_hz") or max(
        (max(v for v in m["hz"] if v is not None) for m in d["modes"]), default=100.0)
    fig, ax = plt.subplots(figsize=(9, 6))
    seen = set()
    for m in d["modes"]:
        hz = np.array([np.nan if v is None else v for v in m["hz"]], dtype=float)
        colour, style = STYLE.get(m["class"], ("k", "-"))
        label = m["class"] + ("" if m["whirl"] in ("-", "planar") else " (" + m["whirl"] + ")")
        ax.plot(rpm, hz, style, color=colour, lw=1.4, label=None if label in seen else label)
        seen.add(label)
    for k in orders:
        ax.plot(rpm, k * rpm / 60.0, color="0.6", lw=0.7)
        n_end = min(rpm[-1], 60.0 * fmax / k)
        ax.annotate("%g" % k, (n_end, k * n_end / 60.0), fontsize=7, color="0.4")
    shown = [c for c in d["crossings"] if c["order"] in orders and c["mode_hz"] <= fmax]
    if shown:
        ax.plot([c["rpm"] for c in shown], [c["mode_hz"] for c in shown], "o", mfc="none",
                color="k", ms=6, label="critical speed")
    ax.set_xlim(rpm[0], rpm[-1])
    ax.set_ylim(0, fmax)
    ax.set_xlabel("speed [rpm]")
    ax.set_ylabel("installed natural frequency [Hz]")
    ax.set_title(a.title or "Campbell diagram: " + str(d.get("scene", "")))
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    fig.savefig(a.out, dpi=120)
    print(a.out)


if __name__ == "__main__":
    main()
