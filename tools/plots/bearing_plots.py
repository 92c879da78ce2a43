#!/usr/bin/python3
"""Plots of a film bearing in a run: the journal's orbit and the film's figures over the cycle.

    /usr/bin/python3 tools/plots/bearing_plots.py RESULTS.h5 --bearing big_end1 \
        [--clearance C] [--rpm N] [--all-cycles] [--out DIR] [--json]

The bearing is a `film-bearing` force element of the run (its outputs are the channels
<bearing>.eccentricity_x, .eccentricity_y, .h_min, .p_max, .friction_power,
.cavitated_fraction, .F.norm; docs/reference/tribology.md). Writes
  DIR/<results stem>_<bearing>_orbit.png   the orbit in the shell's axes as the eccentricity
                                           ratio e/c (polar: the clearance circle is 1),
                                           coloured by crank angle (or time);
  DIR/<results stem>_<bearing>_film.png    load [kN], h_min [µm], p_max [MPa], friction
                                           power [W] and cavitated fraction [-] against the
                                           crank angle [deg] (--rpm N: constant speed from the
                                           first sample plotted) or the time [s].
The clearance c comes from the run's scene (the bearing's `clearance`), or --clearance.
A run that found its periodic steady state is plotted over that cycle (--all-cycles: every
sample). --json prints the orbit's figures (samples, largest e/c, smallest h_min).
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
import yaml  # noqa: E402
from engine_plots import channel, names, steady_cycle  # noqa: E402  (tools/plots/)
from results_status import warn_if_unfinished  # noqa: E402


def scene_clearance(f, bearing):
    """The bearing's clearance [m] from the run's scene file, None if it cannot be read."""
    scene = f.attrs.get("scene")
    scene = scene.decode() if isinstance(scene, bytes) else scene
    try:
        with open(scene) as s:
            doc = yaml.safe_load(s)
    except (OSError, TypeError, yaml.YAMLError):
        return None
    for force in doc.get("forces", []) or []:
        if isinstance(force, dict) and force.get("name") == bearing:
            return float(force["clearance"]) if "clearance" in force else None
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("results")
    ap.add_argument("--bearing", required=True, help="the film-bearing element's name")
    ap.add_argument("--clearance", type=float, default=None,
                    help="radial clearance c [m] (default: the scene's)")
    ap.add_argument("--rpm", type=float, default=None,
                    help="crank speed [rpm] for a crank-angle axis (default: time)")
    ap.add_argument("--all-cycles", action="store_true",
                    help="every sample, not only the steady cycle the run recorded")
    ap.add_argument("--out", default=".")
    ap.add_argument("--json", action="store_true", help="print the orbit's figures as JSON")
    a = ap.parse_args()
    stem = os.path.splitext(os.path.basename(a.results))[0]
    with h5py.File(a.results, "r") as f:
        warn_if_unfinished(f, a.results)
        outputs = names(f, "model/force_output_channels") if "model/force_output_channels" in f else []
        if f"{a.bearing}.eccentricity_x" not in outputs:
            films = sorted({o.rsplit(".", 1)[0] for o in outputs if o.endswith(".eccentricity_x")})
            sys.exit(f"bearing_plots: '{a.bearing}' is not a film bearing of {a.results} "
                     f"(expected one of: {', '.join(films) or 'none in this run'})")
        c = a.clearance if a.clearance is not None else scene_clearance(f, a.bearing)
        if not c or c <= 0:
            sys.exit(f"bearing_plots: no clearance for '{a.bearing}': the scene could not be "
                     "read; give --clearance C [m]")
        t = f["time"][:]
        cycle = None if a.all_cycles else steady_cycle(f, a.results)
        tol = 1e-9 * max(1.0, abs(t[-1]))
        keep = (np.ones_like(t, dtype=bool) if cycle is None
                else (t >= cycle[0] - tol) & (t <= cycle[1] + tol))
        get = {k: channel(f, f"{a.bearing}.{k}")[keep]
               for k in ("eccentricity_x", "eccentricity_y", "h_min", "p_max", "friction_power",
                         "cavitated_fraction")}
        load = channel(f, f"{a.bearing}.F.norm")[keep]
    t = t[keep]
    if a.rpm:
        x, xlabel = (t - t[0]) * a.rpm * 6.0, "crank angle [deg]"
    else:
        x, xlabel = t, "time [s]"
    ex, ey = get["eccentricity_x"], get["eccentricity_y"]
    ratio, angle = np.hypot(ex, ey) / c, np.arctan2(ey, ex)
    os.makedirs(a.out, exist_ok=True)
    orbit_png = os.path.join(a.out, f"{stem}_{a.bearing}_orbit.png")
    fig = plt.figure(figsize=(6, 6))
    ax = fig.add_subplot(projection="polar")
    points = ax.scatter(angle, ratio, c=x, s=4, cmap="viridis")
    ax.plot(angle, ratio, lw=0.4, color="0.5")
    ax.set_rmax(1.0)
    ax.set_rticks([0.25, 0.5, 0.75, 1.0])
    ax.set_title(f"'{a.bearing}': journal orbit, e/c in the shell's axes (c = {c * 1e6:g} µm)")
    fig.colorbar(points, ax=ax, shrink=0.7, label=xlabel)
    fig.savefig(orbit_png, dpi=110)
    plt.close(fig)
    film_png = os.path.join(a.out, f"{stem}_{a.bearing}_film.png")
    panels = [(load / 1e3, "load |F| [kN]"), (get["h_min"] * 1e6, "h_min [µm]"),
              (get["p_max"] / 1e6, "p_max [MPa]"), (get["friction_power"], "friction power [W]"),
              (get["cavitated_fraction"], "cavitated fraction [-]")]
    fig, axes = plt.subplots(len(panels), 1, sharex=True, figsize=(9, 2.2 * len(panels)))
    for ax, (y, label) in zip(axes, panels):
        ax.plot(x, y, lw=0.8)
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel(xlabel)
    axes[0].set_title(f"film bearing '{a.bearing}'")
    fig.tight_layout()
    fig.savefig(film_png, dpi=110)
    plt.close(fig)
    if a.json:
        print(json.dumps({"bearing": a.bearing, "clearance_m": c, "samples": int(len(t)),
                          "max_eccentricity_ratio": float(ratio.max()),
                          "min_h_min_m": float(get["h_min"].min()),
                          "written": [orbit_png, film_png]}, indent=1))
    else:
        print(f"wrote {orbit_png} and {film_png}")


if __name__ == "__main__":
    main()
