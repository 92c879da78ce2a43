#!/usr/bin/python3
"""Records the numbers of a benchmark as JSON: benchmarks/results/NAME.json.

Every results file holds
    {"benchmark": NAME, "commit": SHA, "dirty": BOOL, "date": ISO-8601 UTC,
     "machine": {"cpu": MODEL, "cores": N, "memory_gb": X, "os": ...},
     "command": the command line that ran the benchmark, "note": $EMB_BENCH_NOTE,
     "data": {...the numbers...}}
"dirty" says whether the library, the tools, the meshes, the build files or the benchmarks
differed from the commit (documents, plots, results and the table renderer excluded). benchmarks/render_tables.py renders the documentation's tables from them.

The benchmark scripts call one subcommand each, which turns raw outputs into "data":
  run NAME -- PROGRAM ARGS...        PROGRAM prints one JSON document (C++ benchmarks)
  merge NAME LABEL=RUN.json ...      one JSON document per LABEL (e.g. block_solve per mesh)
  modes NAME H=RUN.json ...          `emb modes --json` per mesh size H [m]
  reduce-sizes NAME H=RUN.json ...   `emb reduce --json` per mesh size H [m]
  reduce-modes NAME RUN.json ...     `emb reduce --json` per mode count (+ PNG plot)
  stiffening NAME LABEL=RUN.json ... `emb reduce --json` with/without geometric stiffness
  compare NAME LABEL=RUN.json ...    `emb compare --json` per part/support
  web-width NAME B=RUN.json ...      `emb compare --json` per web width B [m]
  inline4 NAME DIR RUN ...           `emb run` outputs DIR/RUN.{json,csv} against DIR/ref
  engine NAME DIR CYCLE_S REF RUN ...  engine runs' steady cycles (or second halves) against
                                     REF's, per channel family (benchmarks/engine_errors.py)
  inline4-beam NAME DIR REF RUN ...  inline4_beam.sh: `emb run` outputs DIR/RUN.{json,csv}
                                     against DIR/REF over its span (nose torsion, the five
                                     main bearings, big end 1)
  profile NAME DIR                   perf reports and run summary of inline4_profile.sh
  clonk NAME DIR RUN ...             driveline_clonk.sh: `emb run` and clonk_plots.py outputs
                                     DIR/RUN.{json,csv}, DIR/RUN_metrics.json against the first
  slepc-reduce NAME LABEL=RUN.json,RUN.time,BODY.h5 ...  `emb reduce --json` (default or
                                     --backend slepc on N ranks), its wall time and peak
                                     memory (/usr/bin/time -f "%e %M"), its body file;
                                     compared with the run labelled cholmod
  slepc NAME LABEL=RUN.json,RUN.time ...  `emb modes --json` (default or --backend slepc
                                     on N ranks) and its wall time (/usr/bin/time -f %e);
                                     frequencies against the run labelled cholmod
  ccx NAME H=EMB.json,EMB.time,CCX.json ...  `emb modes --json` and CalculiX per mesh size H
                                     (benchmarks/ccx_vs_emb.sh), with a fitted t ∝ DOF^p
All take --command "...". Run with /usr/bin/python3 (inline4 needs numpy, reduce-modes
matplotlib for its plot).
"""
import argparse
import datetime
import json
import math
import os
import platform
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RESULTS = os.path.join(ROOT, "benchmarks", "results")


# --------------------------------------------------------------------------- metadata
def machine():
    cpu, memory_kb = "unknown", 0
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
        with open("/proc/meminfo") as f:
            for line in f:
                if line.startswith("MemTotal:"):
                    memory_kb = int(line.split()[1])
    except OSError:
        pass
    return {"cpu": cpu, "cores": os.cpu_count(), "memory_gb": round(memory_kb / 1048576, 1),
            "os": f"{platform.system()} {platform.release()}"}


def git(*args):
    return subprocess.run(["git", "-C", ROOT, *args], capture_output=True, text=True,
                          check=True).stdout.strip()


# What the benchmarks' programs and scripts are made of (a change elsewhere, e.g. in tests,
# examples or documents, does not make a run "dirty").
BUILT_FROM = ("libemb/", "tools/", "meshes/", "cmake/", "CMakeLists.txt", "benchmarks/")
NOT_BUILT = (".md", ".png", "render_tables.py")
RESULTS_DIR = "benchmarks/results/"  # the benchmarks write there themselves


def commit():
    sha = git("rev-parse", "HEAD")
    changed = [line[3:] for line in git("status", "--porcelain", "--untracked-files=no").splitlines()]
    dirty = [p for p in changed if p.startswith(BUILT_FROM) and not p.endswith(NOT_BUILT)
             and not p.startswith(RESULTS_DIR)]
    return sha, bool(dirty)


def relative_paths(x):
    """`x` with the checkout's absolute path left out of every string (results name files
    relative to the repository, never this machine's paths)."""
    if isinstance(x, str):
        return x.replace(ROOT + os.sep, "")
    if isinstance(x, dict):
        return {k: relative_paths(v) for k, v in x.items()}
    if isinstance(x, list):
        return [relative_paths(v) for v in x]
    return x


def write_result(name, command, data):
    """benchmarks/results/NAME.json with the metadata around `data` (atomically; paths inside
    the checkout made relative to it)."""
    data = relative_paths(data)
    sha, dirty = commit()
    doc = {"benchmark": name, "commit": sha, "dirty": dirty,
           "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ"),
           "machine": machine(), "command": command, "note": os.environ.get("EMB_BENCH_NOTE", ""),
           "data": data}
    os.makedirs(RESULTS, exist_ok=True)
    path = os.path.join(RESULTS, name + ".json")
    with open(path + ".tmp", "w") as f:
        json.dump(doc, f, indent=1, allow_nan=False, default=str)
        f.write("\n")
    os.replace(path + ".tmp", path)
    print(f"wrote {os.path.relpath(path, ROOT)}")


def load(path):
    with open(path) as f:
        return json.load(f)


def labelled(items):
    """["0.02=a.json", ...] -> [("0.02", "a.json"), ...]"""
    out = []
    for item in items:
        label, sep, path = item.partition("=")
        if not sep:
            sys.exit(f"record.py: expected LABEL=FILE, got '{item}'")
        out.append((label, path))
    return out


def finite(x):
    """NaN (from JSON null or a non-number) -> None, so that the JSON stays strict."""
    return x if isinstance(x, (int, float)) and math.isfinite(x) else None


# --------------------------------------------------------------------------- collectors
def phases(summary):
    return {k[len("seconds_"):]: v for k, v in summary.items() if k.startswith("seconds_")}


def collect_modes(items):
    runs = []
    for h, path in labelled(items):
        r = load(path)
        s = r["summary"]
        runs.append({"h_m": float(h), "dofs": s["dofs"], "nnz_factor": s["nnz_factor"],
                     "seconds": phases(s), "solves": s["solves"],
                     "ordering_s": s.get("ordering_seconds"),
                     "peak_memory_mb": s["peak_memory_mb"], "status": s["status"],
                     "rigid_modes": s["rigid_modes"],
                     "max_backward_error": s["max_backward_error"],
                     "elastic_hz": [m["frequency_hz"] for m in r["modes"] if m["kind"] == "elastic"]})
    runs.sort(key=lambda r: r["dofs"])
    ref = runs[-1]["elastic_hz"]
    for r in runs:
        n = min(len(r["elastic_hz"]), len(ref))
        r["max_change_vs_finest"] = max(abs(a - b) / b for a, b in zip(r["elastic_hz"][:n], ref[:n]))
    return {"runs": runs}


def paired_errors(run, fmax=None):
    return [abs(x["error_percent"]) for x in run["comparison"]
            if isinstance(x["error_percent"], float) and (fmax is None or x["full_hz"] <= fmax)]


def certificate(run):
    c = run["certificate"]
    return {k: c.get(k) for k in ("passed", "mass_error", "com_error", "inertia_error",
                                   "static_error", "num_near_zero", "min_mac", "unrepresented",
                                   "max_frequency_error")}


def collect_reduce_sizes(items):
    runs = []
    for h, path in labelled(items):
        r = load(path)
        s = r["summary"]
        err = paired_errors(r)
        runs.append({"h_m": float(h), "dofs": s["dofs"],
                     "fixed_interface_modes": s["fixed_interface_modes"],
                     "elastic_modes": s["elastic_modes"], "seconds": phases(s),
                     "peak_memory_mb": s["peak_memory_mb"],
                     "max_error_pct": max(err) if err else None, "certificate": certificate(r)})
    runs.sort(key=lambda r: r["dofs"])
    return {"runs": runs}


def collect_reduce_modes(paths):
    runs = []
    for path in paths:
        r = load(path)
        s = r["summary"]
        seconds = phases(s)
        runs.append({"dofs": s["dofs"], "fixed_interface_modes": s["fixed_interface_modes"],
                     "elastic_modes": s["elastic_modes"], "seconds": seconds,
                     "seconds_reduction": seconds["total"] - seconds.get("certificate", 0.0),
                     "max_error_pct_6khz": max(paired_errors(r, 6000.0)),
                     "max_error_pct_3khz": max(paired_errors(r, 3000.0)),
                     "certificate": certificate(r)})
    runs.sort(key=lambda r: r["fixed_interface_modes"])
    plot_reduce_modes(runs)
    return {"runs": runs}


def plot_reduce_modes(runs):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("record.py: no matplotlib, plot not made", file=sys.stderr)
        return
    t = [r["seconds_reduction"] for r in runs]
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.loglog(t, [r["max_error_pct_6khz"] for r in runs], "o-", label="modes ≤ 6 kHz")
    ax.loglog(t, [r["max_error_pct_3khz"] for r in runs], "s-", label="modes ≤ 3 kHz")
    for r in runs:
        ax.annotate(str(r["fixed_interface_modes"]), (r["seconds_reduction"], r["max_error_pct_6khz"]),
                    textcoords="offset points", xytext=(4, 4))
    ax.set_xlabel("reduction wall time [s]")
    ax.set_ylabel("max frequency error vs full FE [%]")
    ax.set_title(f"Crankshaft CB ({runs[0]['dofs'] / 1000:.0f}k DOF): error against cost")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    out = os.path.join(ROOT, "benchmarks", "reduce_error_vs_time.png")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"wrote {os.path.relpath(out, ROOT)}")


def collect_stiffening(items):
    runs = []
    for label, path in labelled(items):
        r = load(path)
        s = r["summary"]
        out = s.get("output", "").split(" and ")[0]
        runs.append({"name": label, "dofs": s["dofs"],
                     "fixed_interface_modes": s["fixed_interface_modes"],
                     "elastic_modes": s["elastic_modes"], "seconds": phases(s),
                     "peak_memory_mb": s["peak_memory_mb"],
                     "file_mb": os.path.getsize(out) / 1e6 if out and os.path.exists(out) else None,
                     "certificate": certificate(r)})
    return {"runs": runs}


def collect_compare(items):
    cases = []
    for label, path in labelled(items):
        r = load(path)
        s = r["summary"]
        ref = r["modes"]
        routes = []
        for x in r["routes"]:
            errors = [finite(e) for e in x["relative_errors"]]
            judged = [100 * e for e, m in zip(errors, ref)
                      if e is not None and (x["method"] in ("cms", "fe") or m["beam_like"] == "yes")]
            routes.append({"route": x["route"], "method": x["method"], "unknowns": x["unknowns"],
                           "seconds": x["seconds"], "paired": x["paired"], "judged": x["judged"],
                           "max_abs_error_pct": finite(x["max_abs_error_pct"]),
                           "mean_abs_error_pct": finite(x["mean_abs_error_pct"]),
                           "min_error_pct": min(judged) if judged else None,
                           "max_error_pct": max(judged) if judged else None,
                           "min_mac": finite(x["min_mac"]), "relative_errors": errors})
        cases.append({"name": label, "part": s["part"], "support": s["support"],
                      "fe_dofs": s["fe_dofs"], "mesh": s["mesh"], "tmm_vs_lumped": s["tmm_vs_lumped"],
                      "reference_hz": [m["reference_hz"] for m in ref],
                      "beam_like": [m["beam_like"] == "yes" for m in ref],
                      "num_not_beam_like": len(r["not_beam_like"]), "routes": routes})
    return {"cases": cases}


def collect_web_width(items, route):
    runs = []
    reference = None
    for width, path in labelled(items):
        r = load(path)
        reference = [m["reference_hz"] for m in r["modes"]]
        x = next(x for x in r["routes"] if x["route"] == route)
        runs.append({"width_m": float(width), "route": route,
                     "errors_pct": [None if finite(e) is None else 100 * e for e in x["relative_errors"]],
                     "mac": [finite(m) for m in x["mac"]]})
    runs.sort(key=lambda r: r["width_m"])
    return {"reference_hz": reference, "runs": runs}


def collect_inline4(directory, names):
    import numpy as np

    def read(name):
        csv = np.genfromtxt(os.path.join(directory, name + ".csv"), delimiter=",", names=True)
        return csv, load(os.path.join(directory, name + ".json"))["summary"]

    ref, _ = read("ref")
    t = ref["t"]
    second = t >= 0.5 * t[-1] - 1e-12  # the second of two cycles
    cycles = t[-1] / 0.04  # 4-stroke cycles at 3000 rpm

    def rms(x):
        return float(np.sqrt(np.mean(x[second] ** 2)))

    nose_ref = ref["nose_torsionrz"]
    force_ref = np.hypot(ref["main_bearing3Fx"], ref["main_bearing3Fy"])
    rows = []
    for name in names:
        run, s = read(name)
        nose = run["nose_torsionrz"]
        force = np.hypot(run["main_bearing3Fx"], run["main_bearing3Fy"])
        rows.append({"name": name, "status": s["status"], "modal_coordinates": s["modal_coordinates"],
                     "rtol": s["rtol"], "steps": s["steps"], "residual_evals": s["residual_evals"],
                     "jacobian_evals": s["jacobian_evals"], "seconds_run": s["seconds_run"],
                     "seconds_per_cycle": s["seconds_run"] / cycles,
                     "nose_rms_error_pct": 100 * rms(nose - nose_ref) / rms(nose_ref),
                     "bearing3_rms_error_pct": 100 * rms(force - force_ref) / rms(force_ref),
                     "max_nose_torsion_mrad": 1e3 * float(np.max(np.abs(nose[second])))})
    return {"cycles": cycles, "reference": "ref", "runs": rows}


def collect_engine(inputs):
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import engine_errors
    directory, cycle_s, reference, names = inputs[0], float(inputs[1]), inputs[2], inputs[2:]
    return {"cycle_s": cycle_s, "reference": reference,
            "runs": engine_errors.compare(directory, reference, names, cycle_s)}
def collect_inline4_beam(directory, reference, names):
    """RMS errors of the nose torsion, of |F| of each main bearing and of big end 1 against
    the reference run, over the reference's span (a run may be longer: its first samples are
    compared); wall time per cycle (0.04 s at 3000 rpm) over each run's own span."""
    import numpy as np

    def read(name):
        csv = np.genfromtxt(os.path.join(directory, name + ".csv"), delimiter=",", names=True)
        return csv, load(os.path.join(directory, name + ".json"))["summary"]

    ref, _ = read(reference)
    n = len(ref["t"])
    cycle = 0.04

    def rms(x):
        return float(np.sqrt(np.mean(x ** 2)))

    def channels(run):
        run = run[:n]
        out = {"nose": run["nose_torsionrz"],
               "big_end1": np.hypot(run["big_end1Fx"], run["big_end1Fy"])}
        for k in range(1, 6):
            out[f"bearing{k}"] = np.hypot(run[f"main_bearing{k}Fx"], run[f"main_bearing{k}Fy"])
        return out

    r = channels(ref)
    rows = []
    for name in names:
        run, s = read(name)
        if len(run["t"]) < n or np.max(np.abs(run["t"][:n] - ref["t"])) > 1e-9:
            sys.exit(f"record.py inline4-beam: {name} is not sampled like {reference}")
        c = channels(run)
        err = {k: 100 * rms(c[k] - r[k]) / rms(r[k]) for k in r}
        cycles = float(run["t"][-1] - run["t"][0]) / cycle
        rows.append({"name": name, "status": s["status"], "bodies": s["bodies"],
                     "parts": s.get("parts", []), "rtol": s["rtol"], "steps": s["steps"],
                     "error_test_failures": s["error_test_failures"],
                     "residual_evals": s["residual_evals"], "jacobian_evals": s["jacobian_evals"],
                     "seconds_run": s["seconds_run"], "t_end": float(run["t"][-1]),
                     "cycles": cycles, "seconds_per_cycle": s["seconds_run"] / cycles,
                     "nose_rms_error_pct": err["nose"],
                     "bearing_rms_error_pct": [err[f"bearing{k}"] for k in range(1, 6)],
                     "bearing_max_rms_error_pct": max(err[f"bearing{k}"] for k in range(1, 6)),
                     "big_end1_rms_error_pct": err["big_end1"],
                     "max_nose_torsion_mrad": 1e3 * float(np.max(np.abs(c["nose"])))})
    return {"reference": reference, "window_s": [float(ref["t"][0]), float(ref["t"][-1])],
            "runs": rows}


def collect_clonk(directory, names):
    """driveline_clonk.sh: `emb run --json` summaries, the CSV channels and clonk_plots.py's
    metrics of each run against the first (the reference)."""
    import numpy as np

    def read(name):
        csv = np.genfromtxt(os.path.join(directory, name + ".csv"), delimiter=",", names=True)
        return (csv, load(os.path.join(directory, name + ".json"))["summary"],
                load(os.path.join(directory, name + "_metrics.json")))

    ref, ref_summary, ref_metrics = read(names[0])

    def rms(x):
        return float(np.sqrt(np.mean(x ** 2)))

    rows = []
    for name in names:
        run, s, m = read(name)
        n = min(len(run), len(ref))
        t_end = float(s["t_reached"])
        row = {"name": name, "status": s["status"], "modal_coordinates": s["modal_coordinates"],
               "rtol": s["rtol"], "steps": s["steps"], "events": s.get("events", 0),
               "restarts": s.get("restarts", 0), "contacts": s.get("contacts", 0),
               "seconds_run": s["seconds_run"], "t_end": t_end,
               "seconds_per_simulated_second": s["seconds_run"] / t_end,
               "events_per_simulated_second": s.get("events", 0) / t_end}
        for channel, key in [("gearbox_lashTz", "gear_torque"), ("tube_midan", "tube_accel")]:
            x, r = run[channel][:n], ref[channel][:n]
            if key == "tube_accel":  # the vibration: mean (centripetal) part removed
                x, r = x - np.mean(x), r - np.mean(r)
            row[key + "_rms_error_pct"] = 100 * rms(x - r) / rms(r)
        windows = []
        for w, wr in zip(m["windows"], ref_metrics["windows"]):
            diff = [a - b for a, b in zip(w["band_levels_db"], wr["band_levels_db"])]
            windows.append({"start": w["start"], "peak_accel": w["peak_accel"],
                            "rms_accel": w["rms_accel"], "band_levels_db": w["band_levels_db"],
                            "band_error_db": diff,
                            "max_abs_band_error_db": max(abs(d) for d in diff),
                            "peak_sound_power_level_db": w.get("peak_sound_power_level_db")})
        row["windows"] = windows
        row["elements"] = m["elements"]
        rows.append(row)
    return {"reference": names[0], "band_centres_hz": ref_metrics["windows"][0]["band_centres_hz"]
            if ref_metrics["windows"] else [], "runs": rows}


def collect_profile(directory):
    def shares(path, key):
        out = []
        with open(path) as f:
            for line in f:
                parts = line.split()
                if parts and parts[0].endswith("%"):
                    out.append({key: " ".join(parts[1:]), "share_pct": float(parts[0][:-1])})
        return out

    run = load(os.path.join(directory, "run.json"))["summary"]
    return {"run": {k: run.get(k) for k in ("status", "steps", "residual_evals", "jacobian_evals",
                                            "modal_coordinates", "seconds_run", "t_reached")},
            "by_library": shares(os.path.join(directory, "by_library.txt"), "library"),
            "by_function": shares(os.path.join(directory, "by_function.txt"), "symbol")}


def peak_mb_from_time(path):
    """Peak resident set [MB] from `/usr/bin/time -v`'s report."""
    with open(path) as f:
        for line in f:
            if "Maximum resident set size" in line:
                return int(line.rsplit(":", 1)[1]) / 1000
    return None


def wall_from_time(path):
    with open(path) as f:
        for line in f:
            if "Elapsed (wall clock)" in line:
                t = line.rsplit(" ", 1)[1].strip().split(":")
                return sum(float(x) * 60 ** i for i, x in enumerate(reversed(t)))
    return None


def fit_power(dofs, seconds):
    """p of t = a·DOF^p by least squares in log-log."""
    x = [math.log(d) for d in dofs]
    y = [math.log(t) for t in seconds]
    mx, my = sum(x) / len(x), sum(y) / len(y)
    sxx = sum((a - mx) ** 2 for a in x)
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sxx if sxx > 0 else None


def collect_ccx(items):
    runs = []
    for h, paths in labelled(items):
        emb_json, emb_time, ccx_json = paths.split(",")
        r = load(emb_json)
        s = r["summary"]
        c = load(ccx_json)
        emb_hz = [m["frequency_hz"] for m in r["modes"]]
        ccx_hz = c["frequencies_hz"]
        elastic = [i for i, m in enumerate(r["modes"]) if m["kind"] == "elastic"]
        diff = max(abs(emb_hz[i] - ccx_hz[i]) / ccx_hz[i] for i in elastic if i < len(ccx_hz))
        wall = wall_from_time(emb_time)
        runs.append({"h_m": float(h), "dofs": s["dofs"], "nnz_factor": s["nnz_factor"],
                     "emb_seconds": phases(s), "emb_wall_s": wall,
                     "ordering_s": s.get("ordering_seconds"),
                     "emb_peak_mb": peak_mb_from_time(emb_time),
                     "ccx_wall_s": c["seconds"], "ccx_peak_mb": c["peak_memory_mb"],
                     "ratio": c["seconds"] / wall, "max_rel_freq_diff": diff,
                     "block_steps": s.get("block_steps"), "solves": s["solves"],
                     "status": s["status"], "max_backward_error": s["max_backward_error"],
                     "f7_hz": emb_hz[6] if len(emb_hz) > 6 else None})
    runs.sort(key=lambda r: r["dofs"])
    dofs = [r["dofs"] for r in runs]
    growth = {"emb": fit_power(dofs, [r["emb_wall_s"] for r in runs]),
              "ccx": fit_power(dofs, [r["ccx_wall_s"] for r in runs])} if len(runs) > 1 else {}
    return {"runs": runs, "growth_exponent": growth}


def collect_slepc(items):
    """slepc_modes.sh: per run the phases, MUMPS's factor counters and the frequencies'
    largest relative difference to the default (cholmod) run's."""
    runs = []
    for label, paths in labelled(items):
        json_path, time_path = paths.split(",")
        r = load(json_path)
        s = r["summary"]
        with open(time_path) as f:
            wall = float(f.read().split()[-1])
        runs.append({"name": label, "ranks": s.get("mpi_ranks", 1), "dofs": s["dofs"],
                     "method": s["method"], "seconds": phases(s), "wall_s": wall,
                     "nnz_factor": s["nnz_factor"], "factor_flops": s.get("factor_flops"),
                     "factor_peak_mb": s.get("factor_peak_mb"),
                     "factor_total_mb": s.get("factor_total_mb"),
                     "rank0_peak_memory_mb": s["peak_memory_mb"], "solves": s["solves"],
                     "status": s["status"], "rigid_modes": s["rigid_modes"],
                     "max_backward_error": s["max_backward_error"],
                     "elastic_hz": [m["frequency_hz"] for m in r["modes"] if m["kind"] == "elastic"]})
    ref = [r for r in runs if r["name"] == "cholmod"]
    if not ref:
        sys.exit("record.py slepc: expected a run labelled cholmod")
    for r in runs:
        pairs = list(zip(r["elastic_hz"], ref[0]["elastic_hz"]))
        r["max_rel_diff_vs_cholmod"] = max(abs(a - b) / b for a, b in pairs) if pairs else None
    return {"runs": runs}


def time_and_peak(path):
    """Wall time [s] and peak resident set [MB] from `/usr/bin/time -f "%e %M"` (under mpirun
    the largest process of the job: getrusage of the waited-for children)."""
    with open(path) as f:
        wall, kb = f.read().split()[-2:]
    return float(wall), int(kb) / 1000


def collect_slepc_reduce(items):
    """slepc_reduce.sh: per run (`emb reduce --json`, its /usr/bin/time wall time and peak
    memory, its body file) the phases, MUMPS's counters, and the body's largest relative
    differences to the default (cholmod) run's: fixed-interface frequencies, K^ and M^ (max
    entry difference over the largest entry), elastic frequencies, certificate verdict."""
    import h5py
    import numpy as np
    runs, bodies = [], {}
    for label, paths in labelled(items):
        json_path, time_path, h5_path = paths.split(",")
        r = load(json_path)
        s = r["summary"]
        wall, peak = time_and_peak(time_path)
        with h5py.File(h5_path, "r") as f:
            bodies[label] = {k: np.array(f[k]) for k in
                             ("/reduced/K", "/reduced/M", "/fixed_interface/frequencies_hz")}
        runs.append({"name": label, "ranks": s.get("mpi_ranks", 1), "dofs": s["dofs"],
                     "seconds": phases(s), "wall_s": wall, "peak_mb": peak,
                     "rank0_peak_memory_mb": s["peak_memory_mb"],
                     "static_factor_flops": s.get("static_factor_flops"),
                     "static_factor_peak_mb": s.get("static_factor_peak_mb"),
                     "eigen_factor_flops": s.get("eigen_factor_flops"),
                     "eigen_factor_peak_mb": s.get("eigen_factor_peak_mb"),
                     "static_blocked_solves": s.get("static_blocked_solves"),
                     "fixed_interface_modes": s["fixed_interface_modes"],
                     "certificate_passed": r["certificate"]["passed"],
                     "elastic_hz": [m["frequency_hz"] for m in r["modes"]]})
    if "cholmod" not in bodies:
        sys.exit("record.py slepc-reduce: expected a run labelled cholmod")
    ref = bodies["cholmod"]
    ref_hz = [r for r in runs if r["name"] == "cholmod"][0]["elastic_hz"]

    def rel(a, b):
        if a.shape != b.shape:
            return None
        return float(np.max(np.abs(a - b)) / np.max(np.abs(b)))

    def rel_each(a, b):
        if len(a) != len(b):
            return None
        return max((abs(x - y) / y for x, y in zip(a, b)), default=0.0)

    for r in runs:
        b = bodies[r["name"]]
        r["max_rel_diff_vs_cholmod"] = {
            "fixed_interface_hz": rel_each(b["/fixed_interface/frequencies_hz"],
                                           ref["/fixed_interface/frequencies_hz"]),
            "K": rel(b["/reduced/K"], ref["/reduced/K"]),
            "M": rel(b["/reduced/M"], ref["/reduced/M"]),
            "elastic_hz": rel_each(r["elastic_hz"], ref_hz)}
        del r["elastic_hz"]
    return {"runs": runs}


def collect_merge(items):
    return {"runs": [dict(name=label, **load(path)) for label, path in labelled(items)]}


def collect_run(program):
    out = subprocess.run(program, capture_output=True, text=True)
    if out.returncode != 0:
        sys.stderr.write(out.stderr)
        sys.exit(f"record.py: {' '.join(program)} failed with exit code {out.returncode}")
    return json.loads(out.stdout)


# --------------------------------------------------------------------------- main
def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("kind", choices=["run", "merge", "modes", "reduce-sizes", "reduce-modes", "stiffening",
                                    "compare", "web-width", "inline4", "inline4-beam", "profile", "clonk",
                                    "ccx", "engine", "slepc", "slepc-reduce"])
    p.add_argument("name", help="results file name: benchmarks/results/NAME.json")
    p.add_argument("inputs", nargs="*")
    p.add_argument("--command", help="the command line that ran the benchmark (default: PROGRAM)")
    p.add_argument("--route", default="beam consistent, elastic webs", help="web-width: the route")
    argv = sys.argv[1:]
    program = []
    if "--" in argv:
        i = argv.index("--")
        argv, program = argv[:i], argv[i + 1:]
    a = p.parse_intermixed_args(argv)
    if a.kind == "run":
        if not program:
            sys.exit("record.py run: expected -- PROGRAM ARGS...")
        data = collect_run(program)
        command = a.command or " ".join(os.path.relpath(x, ROOT) if os.path.isabs(x) else x
                                        for x in program)
    else:
        if not a.command:
            sys.exit(f"record.py {a.kind}: expected --command")
        command = a.command
        collectors = {
            "merge": lambda: collect_merge(a.inputs),
            "modes": lambda: collect_modes(a.inputs),
            "reduce-sizes": lambda: collect_reduce_sizes(a.inputs),
            "reduce-modes": lambda: collect_reduce_modes(a.inputs),
            "stiffening": lambda: collect_stiffening(a.inputs),
            "compare": lambda: collect_compare(a.inputs),
            "web-width": lambda: collect_web_width(a.inputs, a.route),
            "inline4": lambda: collect_inline4(a.inputs[0], a.inputs[1:]),
            "inline4-beam": lambda: collect_inline4_beam(a.inputs[0], a.inputs[1], a.inputs[2:]),
            "profile": lambda: collect_profile(a.inputs[0]),
            "clonk": lambda: collect_clonk(a.inputs[0], a.inputs[1:]),
            "ccx": lambda: collect_ccx(a.inputs),
            "engine": lambda: collect_engine(a.inputs),
            "slepc": lambda: collect_slepc(a.inputs),
            "slepc-reduce": lambda: collect_slepc_reduce(a.inputs),
        }
        data = collectors[a.kind]()
    write_result(a.name, command, data)


if __name__ == "__main__":
    main()
