#!/usr/bin/python3
"""Plots of an engine run: time traces of results channels and the engine-order spectrum.

    /usr/bin/python3 tools/plots/engine_plots.py RESULTS.h5 \
        --traces crank.omega.x,dyno_speed.T.z --spectrum dyno_speed.T.z --angle crank \
        [--rpm N] [--orders 12] [--all-cycles] [--out DIR] [--emb build/tools/emb/emb]

Writes DIR/<results stem>_traces.png (one panel per channel against the crank angle, or the
time with --time) and DIR/<results stem>_spectrum_<channel>.png (amplitude vs engine order,
computed by `emb spectrum --json`, so the numbers are the CLI's). Channel names as in
`emb spectrum --help`: <body>.p|v|omega.{x,y,z}, <element>.F|T.{x,y,z} (reactions and force
elements' loads), <sensor>.dx|dy|dz|rx|ry|rz, <joint>.angle|angle_rate|travel|travel_rate,
<probe>.<channel> (output points, chord sensors), energy.<column>. The crank angle: --angle
BODY (its rotation about --axis), --angle JOINT (a revolute joint's angle) or --rpm N
(constant speed).
A run that searched for its periodic steady state (analysis.steady_state) marks its steady
cycle in the file (root attributes steady_state_*): the traces show that cycle by default
(the crank angle then starts at 0 at the cycle's start) and the spectrum is `emb spectrum`'s
default, the same cycle; --all-cycles plots every sample (the steady cycle shaded). A run
that did not converge is plotted whole, with a warning.
"""
import argparse
import json
import os
import subprocess
import sys

import h5py
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy.spatial.transform import Rotation  # noqa: E402
from results_status import warn_if_unfinished  # noqa: E402  (tools/plots/results_status.py)

ENERGY = ["kinetic", "gravity", "elastic", "total", "dissipated"]


def names(f, path):
    return [s.decode() if isinstance(s, bytes) else s for s in f[path][:]]


def column(f, dataset, b, offset_attr, default_offset):
    """First column of body b's block in /state/q or /state/v, from the file's layout record
    (version 3; version 2 files have the same layout without the record: 7 and 6 per body)."""
    attrs = f[dataset].attrs
    stride = int(attrs.get("values_per_body", 7 if dataset == "state/q" else 6))
    return stride * b + int(attrs.get(offset_attr, default_offset))


def rotations(f, b):
    k = column(f, "state/q", b, "quaternion_column", 3)
    e = f["state/q"][:, k:k + 4]  # w, x, y, z
    return Rotation.from_quat(np.c_[e[:, 1:], e[:, :1]])


def channel(f, name):
    """The values of a channel (same conventions as libemb/results/results_reader.h)."""
    owner, _, comp = name.rpartition(".")
    if name.startswith("energy."):
        return f["energy"][:, ENERGY.index(name[7:])]
    joints = names(f, "model/joints") if "model/joints" in f else []
    if owner in joints:  # <joint>.angle, .angle_rate, .travel, .travel_rate
        k = joints.index(owner)
        values = f["joints"][:, 4 * k + ["angle", "angle_rate", "travel", "travel_rate"].index(comp)]
        if np.isnan(values).any():
            raise SystemExit(f"engine_plots: channel '{name}': joint '{owner}' has no such "
                             "coordinate (angle: revolute and cylindrical joints; travel: "
                             "translational and cylindrical joints)")
        return values
    probes = names(f, "model/output_point_channels") if "model/output_point_channels" in f else []
    if name in probes:  # output points, chord sensors
        return f["output_points"][:, probes.index(name)]
    outputs = (names(f, "model/force_output_channels")
               if "model/force_output_channels" in f else [])
    if name in outputs:  # force elements' outputs: <element>.<output> (h_min, p_max, ...)
        return f["forces/outputs"][:, outputs.index(name)]
    sensors = names(f, "model/sensors") if "model/sensors" in f else []
    if owner in sensors:  # <sensor>.dx .. .rz
        k = sensors.index(owner)
        return f["sensors"][:, 6 * k + ["dx", "dy", "dz", "rx", "ry", "rz"].index(comp)]
    owner, _, quantity = owner.rpartition(".")
    ports = names(f, "model/reaction_ports")
    forces = names(f, "model/force_elements") if "model/force_elements" in f else []
    if quantity == "F" and comp == "norm" and owner in forces:  # |F| of a force element
        return np.linalg.norm(np.stack([channel(f, f"{owner}.F.{x}") for x in "xyz"]), axis=0)
    if comp not in ("x", "y", "z"):
        raise SystemExit(f"engine_plots: unknown channel '{name}'")
    c = "xyz".index(comp)
    if quantity in ("F", "T") and owner not in ports and owner in forces:  # /forces/load
        k = forces.index(owner)
        values = f["forces/load"][:, 6 * k + c + (3 if quantity == "T" else 0)]
        if np.isnan(values).any():
            raise SystemExit(f"engine_plots: channel '{name}': force element '{owner}' reports "
                             "no load (F/T channels exist for bushings and journal bearings)")
        return values
    if quantity in ("F", "T"):
        p = ports.index(owner)
        key = "reactions/force" if quantity == "F" else "reactions/torque"
        return f[key][:].reshape(len(f["time"]), -1)[:, 3 * p + c]
    b = names(f, "model/bodies").index(owner)
    if quantity == "p":
        return f["state/q"][:, column(f, "state/q", b, "position_column", 0) + c]
    if quantity == "v":
        return f["state/v"][:, column(f, "state/v", b, "velocity_column", 0) + c]
    if quantity == "omega":  # omega_B in the file, W in the channel
        k = column(f, "state/v", b, "angular_velocity_column", 3)
        return rotations(f, b).apply(f["state/v"][:, k:k + 3])[:, c]
    raise SystemExit(f"engine_plots: unknown channel '{name}'")


def crank_angle(f, body, axis, rpm=None):
    """Crank angle [deg], 0 at the first sample: the constant speed `rpm` if given, else the
    unwrapped angle of the revolute joint `body` if it names one, else the unwrapped rotation
    of the body `body` about a world axis."""
    t = f["time"][:]
    if rpm is not None:
        return 6.0 * rpm * (t - t[0])
    if "model/joints" in f and body in names(f, "model/joints"):
        ang = channel(f, body + ".angle")
        return np.degrees(ang - ang[0])
    a = "xyz".index(axis)
    u, ax = np.eye(3)[(a + 1) % 3], np.eye(3)[a]
    r = rotations(f, names(f, "model/bodies").index(body)).apply(u)
    ang = np.unwrap(np.arctan2(r @ np.cross(ax, u), r @ u))
    return np.degrees(ang - ang[0])


def steady_cycle(f, path):
    """The steady cycle (t_start, t_end) [s] a run recorded (results_writer.h), or None if it
    did not search for one or did not find it (then with a warning)."""
    if "steady_state_converged" not in f.attrs:
        return None
    if not int(f.attrs["steady_state_converged"]):
        print(f"warning: '{path}' did not reach its periodic steady state (last cycle-to-cycle "
              f"change {float(f.attrs['steady_state_change']):.3g}, tolerance "
              f"{float(f.attrs['steady_state_tolerance']):.3g}): plotting every sample",
              file=sys.stderr)
        return None
    return float(f.attrs["steady_state_cycle_start"]), float(f.attrs["steady_state_cycle_end"])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("results")
    ap.add_argument("--traces", default="", help="comma-separated channels to plot")
    ap.add_argument("--spectrum", default="", help="channel for the order spectrum")
    ap.add_argument("--angle", default="crank",
                    help="body whose rotation is the crank angle, or a revolute joint")
    ap.add_argument("--axis", default="x", help="world axis of the crank rotation")
    ap.add_argument("--rpm", type=float, default=None,
                    help="instead of --angle: a constant crank speed [rpm] from the first sample")
    ap.add_argument("--time", action="store_true", help="traces against time instead of angle")
    ap.add_argument("--orders", default="12")
    ap.add_argument("--all-cycles", action="store_true",
                    help="traces of every sample, not only the steady cycle the run recorded")
    ap.add_argument("--out", default=".")
    ap.add_argument("--emb", default=os.path.join("build", "tools", "emb", "emb"))
    args = ap.parse_args()
    stem = os.path.splitext(os.path.basename(args.results))[0]
    os.makedirs(args.out, exist_ok=True)
    written = []
    with h5py.File(args.results, "r") as f:
        warn_if_unfinished(f, args.results)
        traces = [c for c in args.traces.split(",") if c]
        cycle = steady_cycle(f, args.results)
        if traces:
            t = f["time"][:]
            x = t if args.time else crank_angle(f, args.angle, args.axis, args.rpm)
            # Samples of the steady cycle, its end sample included (results/steady_state.h).
            tol = 1e-9 * max(1.0, abs(t[-1]))
            in_cycle = (np.ones_like(t, dtype=bool) if cycle is None
                        else (t >= cycle[0] - tol) & (t <= cycle[1] + tol))
            keep = in_cycle if cycle is not None and not args.all_cycles else np.ones_like(in_cycle)
            if not args.time:
                x = x - x[np.argmax(keep)]  # 0 at the first sample plotted
            fig, axes = plt.subplots(len(traces), 1, sharex=True, figsize=(9, 2.4 * len(traces)),
                                     squeeze=False)
            for ax, name in zip(axes[:, 0], traces):
                ax.plot(x[keep], channel(f, name)[keep], lw=0.8)
                if cycle is not None and args.all_cycles:
                    ax.axvspan(x[in_cycle][0], x[in_cycle][-1], color="tab:green", alpha=0.12)
                ax.set_ylabel(name)
                ax.grid(alpha=0.3)
            if not args.time:
                for ax in axes[:, 0]:
                    ax.set_xticks(np.arange(np.floor(x[keep][0] / 180) * 180, x[keep][-1] + 1, 180))
            axes[-1, 0].set_xlabel("time [s]" if args.time else "crank angle [deg]")
            what = ("" if cycle is None else
                    f"steady cycle {cycle[0]:.4g}-{cycle[1]:.4g} s" +
                    (" shaded" if args.all_cycles else "") + ", ")
            scene = f.attrs.get("scene", b"")  # emb stores strings as fixed-length bytes
            scene = scene.decode() if isinstance(scene, bytes) else scene
            fig.suptitle(f"{stem}: {what}{scene}", fontsize=9)
            fig.tight_layout()
            print(f"traces: {int(keep.sum())} samples, t = {t[keep][0]:.6g} .. {t[keep][-1]:.6g} s"
                  + (" (the steady cycle)" if cycle is not None and not args.all_cycles else ""))
            path = os.path.join(args.out, f"{stem}_traces.png")
            fig.savefig(path, dpi=120)
            written.append(path)
    if args.spectrum:
        crank = (["--rpm", repr(args.rpm)] if args.rpm is not None
                 else ["--angle", args.angle, "--axis", args.axis])
        cmd = [args.emb, "spectrum", args.results, "--channel", args.spectrum, *crank,
               "--orders", args.orders, "--json"]
        run = subprocess.run(cmd, capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit(f"engine_plots: {' '.join(cmd)} failed:\n{run.stderr}")
        data = json.loads(run.stdout)
        orders = [r["order"] for r in data["orders"] if r["order"] > 0]
        amps = [r["amplitude"] for r in data["orders"] if r["order"] > 0]
        fig, ax = plt.subplots(figsize=(9, 3.5))
        ax.bar(orders, amps, width=0.3)
        ax.set_xlabel("engine order (per crank revolution)")
        ax.set_ylabel(f"amplitude of {args.spectrum}")
        ax.set_title(f"{stem}: {args.spectrum}, {data['summary']['cycles']} cycle(s), "
                     f"mean {data['summary']['mean']:.4g}", fontsize=9)
        ax.set_xticks(np.arange(0, float(args.orders) + 0.5, 1.0))
        ax.grid(alpha=0.3)
        fig.tight_layout()
        path = os.path.join(args.out, f"{stem}_spectrum_{args.spectrum.replace('.', '_')}.png")
        fig.savefig(path, dpi=120)
        written.append(path)
    for p in written:
        print("wrote", p)


if __name__ == "__main__":
    main()
