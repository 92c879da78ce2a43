#!/usr/bin/python3
"""Clonk metrics and pictures of a driveline run with lash elements and tube output points.

    /usr/bin/python3 tools/plots/clonk_plots.py out/driveline_clonk.h5 --out out/clonk \
        [--accel tube_mid.a.n] [--power tube_noise.power] [--window 0.1] [--json]

Reads the results file of `emb run` (libemb/results/results_writer.h): the contacts of the
lash elements (/events/contacts), their contact torques (/forces/load, T.z) and the output
points (/output_points). Writes to DIR:
  <stem>_impacts.png      contact torque of every lash element against time, with the
                          located contact onsets marked
  <stem>_surface.png      the tube surface's acceleration (--accel, e.g. the mid-span radial
                          acceleration) against time
  <stem>_spectrogram.png  its spectrogram (Hann, 512-sample segments), 0-5 kHz
  <stem>_bands.png        its 1/3-octave band levels 0.5-5 kHz [dB re 1e-6 m/s^2] in every
                          clonk window (the --window seconds after the first contact of a
                          burst of closings faster than a tenth of the fastest)
  <stem>_noise.png        the radiated-noise proxy P = integral of v_n^2 over the outer
                          surface (--power) and the sound power level it gives with
                          radiation efficiency 1, L_W = 10 log10(rho c P / 1e-12 W)
and prints the metrics (--json: one JSON document): per lash element its contacts, largest
closing speed and peak torque; per window the peak and RMS acceleration, the band levels and
the peak noise proxy.

The band level of band k is 10 log10(sum of |X(f)|^2 over the band / 1e-12) with X the
one-sided amplitude spectrum of the Hann-windowed record (the RMS in the band, Parseval).
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
from scipy import signal  # noqa: E402
from results_status import warn_if_unfinished  # noqa: E402  (tools/plots/results_status.py)

RHO_C = 415.0  # characteristic impedance of air at 20 C [kg/(m^2 s)]
BAND_CENTRES = [500, 630, 800, 1000, 1250, 1600, 2000, 2500, 3150, 4000, 5000]  # [Hz]
ACCEL_REF = 1e-6  # [m/s^2], ISO 1683
POWER_REF = 1e-12  # [W]


def names(f, path):
    return [s.decode() if isinstance(s, bytes) else s for s in f[path][:]]


def output_point(f, name):
    channels = names(f, "model/output_point_channels")
    if name not in channels:
        sys.exit("clonk_plots: no output point channel '%s' in the results (there are: %s)"
                 % (name, ", ".join(channels)))
    return f["output_points"][:, channels.index(name)]


def lash_torques(f, contacts):
    """{element: contact force/torque on its coordinate} for the elements with contacts."""
    forces = names(f, "model/force_elements")
    out = {}
    for k in sorted({int(c[0]) for c in contacts}):
        load = f["forces/load"][:, 6 * k:6 * k + 6]
        # A lash reports the signed force on its coordinate in T.z (angle) or F.z (slide).
        out[forces[k]] = load[:, 5] if np.any(load[:, 5] != 0) else load[:, 2]
    return out


def clonk_windows(contacts, length):
    """Start times of the bursts of fast closings (faster than a tenth of the fastest)."""
    if len(contacts) == 0:
        return []
    fast = contacts[contacts[:, 3] > 0.1 * contacts[:, 3].max()]
    starts = []
    for t in np.sort(fast[:, 2]):
        if not starts or t > starts[-1] + length:
            starts.append(float(t))
    return starts


def band_levels(x, dt):
    """1/3-octave band levels [dB re ACCEL_REF] of the record x (uniform step dt)."""
    n = len(x)
    w = np.hanning(n)
    X = np.fft.rfft((x - np.mean(x)) * w) / (np.sum(w) / 2.0)  # one-sided amplitude
    f = np.fft.rfftfreq(n, dt)
    levels = []
    for fc in BAND_CENTRES:
        lo, hi = fc / 2 ** (1 / 6), fc * 2 ** (1 / 6)
        band = (f >= lo) & (f < hi)
        ms = 0.5 * np.sum(np.abs(X[band]) ** 2)  # mean square of the band's sinusoids
        levels.append(10 * np.log10(max(ms, 1e-300) / ACCEL_REF ** 2))
    return levels


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("results")
    p.add_argument("--out", default=".")
    p.add_argument("--accel", default="tube_mid.a.n")
    p.add_argument("--power", default="tube_noise.power")
    p.add_argument("--window", type=float, default=0.1, help="clonk window length [s]")
    p.add_argument("--json", action="store_true")
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    stem = os.path.splitext(os.path.basename(a.results))[0]
    with h5py.File(a.results, "r") as f:
        warn_if_unfinished(f, a.results)
        t = f["time"][:]
        contacts = f["events/contacts"][:] if "events/contacts" in f else np.zeros((0, 7))
        torques = lash_torques(f, contacts) if len(contacts) else {}
        forces = names(f, "model/force_elements")
        accel = output_point(f, a.accel)
        power = output_point(f, a.power) if a.power else None
    dt = float(np.median(np.diff(t)))
    metrics = {"results": a.results, "elements": {}, "windows": []}
    for name in torques:
        k = forces.index(name)
        mine = contacts[contacts[:, 0] == k]
        metrics["elements"][name] = {
            "contacts": int(len(mine)),
            "max_closing_speed": float(mine[:, 3].max()),
            "max_peak_force": float(mine[:, 4].max())}

    fig, ax = plt.subplots(figsize=(10, 4))
    for name, y in torques.items():
        ax.plot(t, y, lw=0.8, label=name)
        k = forces.index(name)
        onsets = contacts[contacts[:, 0] == k, 2]
        ax.plot(onsets, np.interp(onsets, t, y), "k|", ms=8)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("contact force on the lash coordinate [N m]")
    ax.set_title("impacts (| = located contact onsets)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, stem + "_impacts.png"), dpi=120)

    fig, ax = plt.subplots(figsize=(10, 4))
    ax.plot(t, accel, lw=0.5)
    ax.set_xlabel("t [s]")
    ax.set_ylabel(a.accel + " [m/s^2]")
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, stem + "_surface.png"), dpi=120)

    fs = 1.0 / dt
    nper = min(512, len(accel))
    fq, ts, S = signal.spectrogram(accel - np.mean(accel), fs=fs, window="hann", nperseg=nper,
                                   noverlap=nper * 7 // 8, scaling="spectrum")
    fig, ax = plt.subplots(figsize=(10, 4))
    keep = fq <= 5000
    ax.pcolormesh(ts + t[0], fq[keep], 10 * np.log10(S[keep] / ACCEL_REF ** 2 + 1e-30),
                  shading="auto", cmap="viridis")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("f [Hz]")
    ax.set_title("spectrogram of %s [dB re 1e-6 m/s^2]" % a.accel)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, stem + "_spectrogram.png"), dpi=120)

    fig, ax = plt.subplots(figsize=(8, 4))
    for start in clonk_windows(contacts, a.window):
        sel = (t >= start) & (t < start + a.window)
        levels = band_levels(accel[sel], dt)
        w = {"start": start, "length": a.window,
             "peak_accel": float(np.max(np.abs(accel[sel] - np.mean(accel[sel])))),
             "rms_accel": float(np.std(accel[sel])),
             "band_centres_hz": BAND_CENTRES, "band_levels_db": levels}
        if power is not None:
            w["peak_power_proxy"] = float(np.max(power[sel]))
            w["peak_sound_power_level_db"] = float(
                10 * np.log10(RHO_C * max(w["peak_power_proxy"], 1e-300) / POWER_REF))
        metrics["windows"].append(w)
        ax.plot(BAND_CENTRES, levels, "o-", label="from t = %.3f s" % start)
    ax.set_xscale("log")
    ax.set_xticks(BAND_CENTRES)
    ax.set_xticklabels([str(c) for c in BAND_CENTRES], rotation=45)
    ax.set_xlabel("1/3-octave band centre [Hz]")
    ax.set_ylabel("level [dB re 1e-6 m/s^2]")
    ax.set_title(a.accel)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, stem + "_bands.png"), dpi=120)

    if power is not None:
        fig, ax = plt.subplots(2, 1, figsize=(10, 5), sharex=True)
        ax[0].plot(t, power, lw=0.5)
        ax[0].set_ylabel("P = int v_n^2 dA [m^4/s^2]")
        ax[1].plot(t, 10 * np.log10(RHO_C * np.maximum(power, 1e-300) / POWER_REF), lw=0.5)
        ax[1].set_ylabel("L_W (sigma = 1) [dB]")
        ax[1].set_xlabel("t [s]")
        fig.tight_layout()
        fig.savefig(os.path.join(a.out, stem + "_noise.png"), dpi=120)

    if a.json:
        print(json.dumps(metrics, indent=1))
    else:
        for name, e in metrics["elements"].items():
            print("%-20s %4d contacts, closing speed up to %.3g, peak force %.4g"
                  % (name, e["contacts"], e["max_closing_speed"], e["max_peak_force"]))
        for w in metrics["windows"]:
            print("window from %.4f s: peak %.4g m/s^2, rms %.4g m/s^2; bands [dB]: %s"
                  % (w["start"], w["peak_accel"], w["rms_accel"],
                     " ".join("%.1f" % x for x in w["band_levels_db"])))
        print("written: %s_{impacts,surface,spectrogram,bands,noise}.png in %s" % (stem, a.out))


if __name__ == "__main__":
    main()
