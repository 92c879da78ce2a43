#!/usr/bin/python3
"""Plots of a speed sweep (emb sweep) or a run-up (emb runup): a waterfall and order cuts.

    /usr/bin/python3 tools/plots/sweep_plots.py SWEEP.h5 [--channel nose_torsion.rz]
        [--orders 0.5,1,2,4] [--critical campbell.json [--critical-class torsion]
        [--critical-min-torsion 0.25]]
        [--scale 57.29578 --unit deg]
        [--out DIR]

Writes DIR/<sweep stem>_waterfall_<channel>.png (engine order against speed, each point's
order amplitudes as vertical lines along the order axis, the classic waterfall of an order
analysis) and DIR/<sweep stem>_order_cuts_<channel>.png (amplitude against speed, one curve
per chosen order, default the six largest; failed points are left out, points that did not
reach their steady state are drawn hollow).

--critical FILE marks resonance speeds: a JSON list of {"order": o, "rpm": n, "mode_hz": f}
(mode_hz optional, "label" optional), or any JSON document holding such a list (e.g.
`emb campbell --json` output: the first list of objects with "order" and "rpm" keys found, depth
first). Each critical speed of an order that is cut is a dashed vertical line in that order's
colour, and on the waterfall a cross at (rpm, order). `emb campbell --json` (or its -o file)
holds them as "crossings" with a "class" per mode (torsion, bending, axial): --critical-class
keeps the ones of that class (e.g. torsion for the nose torsion); --critical-min-torsion S
keeps the crossings of modes with a torsion share >= S (the crossing's "torsion"), which a
torsion channel sees even when their class is bending (coupled modes).
--channel defaults to the first channel whose name starts with "nose_torsion", else the first.
--scale multiplies the amplitudes (e.g. 57.29578 for rad -> deg) and --unit labels them.
"""
import argparse
import json
import os
import sys

import h5py
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def strings(ds):
    return [s.decode() if isinstance(s, bytes) else s for s in ds[:]]


def read_sweep(path):
    with h5py.File(path, "r") as f:
        if f.attrs.get("format", b"") not in ("emb-sweep", b"emb-sweep"):
            sys.exit("sweep_plots.py: error: '%s' is not a sweep file (format emb-sweep, from "
                     "emb sweep or emb runup)" % path)
        return {"rpm": f["rpm"][:], "status": strings(f["status"]),
                "channels": strings(f["channels"]), "orders": f["orders"][:],
                "amplitude": f["amplitude"][:]}


def find_critical(doc):
    """The first list of objects with 'order' and 'rpm' in a JSON document (depth first)."""
    if isinstance(doc, list):
        if doc and all(isinstance(x, dict) and "order" in x and "rpm" in x for x in doc):
            return doc
        items = doc
    elif isinstance(doc, dict):
        items = doc.values()
    else:
        return None
    for x in items:
        found = find_critical(x)
        if found is not None:
            return found
    return None


def read_critical(path, kind=None, min_torsion=None):
    try:
        with open(path) as f:
            doc = json.load(f)
    except (OSError, ValueError) as e:
        sys.exit("sweep_plots.py: error: --critical '%s': %s" % (path, e))
    found = find_critical(doc)
    if found is None:
        if isinstance(doc, list) and not doc:
            return []
        sys.exit("sweep_plots.py: error: --critical '%s': expected a list of {\"order\", \"rpm\"[, "
                 "\"mode_hz\"]} objects" % path)
    out = []
    for c in found:
        if kind is not None and c.get("class") != kind:
            continue
        if min_torsion is not None:
            if "torsion" not in c:
                sys.exit("sweep_plots.py: error: --critical-min-torsion: '%s' has crossings "
                         "without a \"torsion\" share (emb campbell writes them)" % path)
            if float(c["torsion"]) < min_torsion:
                continue
        try:
            out.append((float(c["order"]), float(c["rpm"]), c.get("mode_hz"), c.get("label")))
        except (TypeError, ValueError):
            sys.exit("sweep_plots.py: error: --critical '%s': order and rpm must be numbers, got "
                     "%r" % (path, c))
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("sweep")
    p.add_argument("--channel")
    p.add_argument("--orders", help="orders to cut, comma-separated (default: the 6 largest)")
    p.add_argument("--critical", help="JSON of critical speeds (see the file's doc)")
    p.add_argument("--critical-class", help="keep only critical speeds of this mode class")
    p.add_argument("--critical-min-torsion", type=float,
                   help="keep only critical speeds of modes with at least this torsion share")
    p.add_argument("--scale", type=float, default=1.0)
    p.add_argument("--unit", default="")
    p.add_argument("--out", default=".")
    a = p.parse_args()
    s = read_sweep(a.sweep)
    channels = s["channels"]
    ch = a.channel or next((c for c in channels if c.startswith("nose_torsion")), channels[0])
    if ch not in channels:
        sys.exit("sweep_plots.py: error: channel '%s' is not in %s; expected one of %s"
                 % (ch, a.sweep, ", ".join(channels)))
    c = channels.index(ch)
    orders = s["orders"]
    amp = s["amplitude"][:, c, :] * a.scale
    ok = np.array([st != "failed" for st in s["status"]])
    settled = np.array([st in ("converged", "run-up") for st in s["status"]])
    if not ok.any():
        sys.exit("sweep_plots.py: error: every point of %s failed; nothing to plot" % a.sweep)
    rpm = s["rpm"]
    critical = (read_critical(a.critical, a.critical_class, a.critical_min_torsion)
                if a.critical else [])
    if a.orders:
        try:
            cut = [float(x) for x in a.orders.split(",")]
        except ValueError:
            sys.exit("sweep_plots.py: error: --orders: expected numbers, got '%s'" % a.orders)
        missing = [o for o in cut if not np.any(np.isclose(orders, o))]
        if missing:
            sys.exit("sweep_plots.py: error: --orders %s not in the sweep (it has %s)"
                     % (missing, list(orders)))
    else:
        peak = np.nanmax(np.where(ok[:, None], amp, np.nan), axis=0)
        cut = sorted(orders[np.argsort(-np.nan_to_num(peak))[:6]])
    os.makedirs(a.out, exist_ok=True)
    stem = os.path.splitext(os.path.basename(a.sweep))[0]
    tag = ch.replace(".", "_")
    unit = " [%s]" % a.unit if a.unit else ""

    # Waterfall: order on the vertical axis, speed across; each order's amplitude as a bar
    # whose height is proportional to it (scaled so the largest spans 2 orders), colour too.
    fig, ax = plt.subplots(figsize=(9, 6))
    top = np.nanmax(amp[ok]) if np.isfinite(np.nanmax(amp[ok])) else 1.0
    norm = plt.Normalize(0.0, top)
    cmap = plt.get_cmap("viridis")
    for i in np.where(ok)[0]:
        for k, o in enumerate(orders):
            h = 2.0 * amp[i, k] / top if top > 0 else 0.0
            ax.plot([rpm[i], rpm[i]], [o, o + h], color=cmap(norm(amp[i, k])), lw=2.5,
                    alpha=1.0 if settled[i] else 0.4)
    for o, n, _, _ in critical:
        ax.plot(n, o, "rx", ms=9, mew=2)
    sm = plt.cm.ScalarMappable(norm=norm, cmap=cmap)
    fig.colorbar(sm, ax=ax, label="amplitude of %s%s" % (ch, unit))
    ax.set_xlabel("engine speed [rpm]")
    ax.set_ylabel("engine order (per revolution)")
    ax.set_title("Waterfall of %s (%s)" % (ch, stem) +
                 ("; x: critical speeds" if critical else ""))
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "%s_waterfall_%s.png" % (stem, tag)), dpi=110)
    plt.close(fig)

    # Order cuts.
    fig, ax = plt.subplots(figsize=(9, 6))
    for o in cut:
        k = int(np.argmin(np.abs(orders - o)))
        line, = ax.plot(rpm[ok], amp[ok, k], "-", label="order %g" % o)
        ax.plot(rpm[ok & settled], amp[ok & settled, k], "o", color=line.get_color(), ms=4)
        ax.plot(rpm[ok & ~settled], amp[ok & ~settled, k], "o", mfc="none",
                color=line.get_color(), ms=6)
        for oc, n, hz, label in critical:
            if abs(oc - o) < 1e-9:
                ax.axvline(n, color=line.get_color(), ls="--", lw=1)
                text = label or ("%g Hz" % hz if hz is not None else "critical")
                ax.annotate(text, (n, ax.get_ylim()[1]), rotation=90, va="top", ha="right",
                            fontsize=8, color=line.get_color())
    ax.set_xlabel("engine speed [rpm]")
    ax.set_ylabel("amplitude of %s%s" % (ch, unit))
    ax.set_title("Order cuts of %s (%s)" % (ch, stem) +
                 ("; dashed: critical speeds" if critical else ""))
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "%s_order_cuts_%s.png" % (stem, tag)), dpi=110)
    plt.close(fig)
    print("wrote %s_waterfall_%s.png and %s_order_cuts_%s.png in %s" % (stem, tag, stem, tag, a.out))


if __name__ == "__main__":
    main()
