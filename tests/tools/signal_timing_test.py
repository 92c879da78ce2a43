#!/usr/bin/python3
"""Signal-timing stress test: every long emb command stopped by SIGINT or SIGTERM at many
moments spread over the phases it prints, each outcome checked.

    /usr/bin/python3 tests/tools/signal_timing_test.py --emb build/tools/emb/emb --src . \
        --work build/signal_work --command modes [--trials 24] [--budget 240] [--mpirun PATH]

For one command (see COMMANDS): a calibration run without a signal records when each phase
starts (the "[  t s] phase" lines of the progress display) and how long the whole takes;
then `--trials` runs, each in a fresh directory holding a "previous" version of every output
file, get SIGINT or SIGTERM (alternating) at moments placed phase by phase over that time
(every phase gets some; the rest spread evenly), sent to the emb process only (as a batch
scheduler's `kill` does), never to its process group. Each run must end:
  - by the signal (or with exit code 0 if it finished before the signal took effect);
  - without a crash (no other signal, no sanitizer report, no raw C++ failure text);
  - with every output either untouched (the previous version) or complete (a signal that
    comes after an output took its name finds it finished; `emb run`'s results file then says
    "interrupted", or "success" with every sample if the signal came after the last one),
    and every output new if it exited 0;
  - with no temporary, probe or lock file left in its directory;
  - with no process of its session left (the workers of `emb sweep -j`, MPI ranks).
The moments are spread, not random: the same machine gives the same schedule. Where a
signal landed is read from the progress lines the run printed before it ended, and the
phases hit are reported. --budget bounds the time: trials stop when it is spent (at least
--min-trials must run, else the test fails as too slow to say anything).
"""

import argparse
import fnmatch
import io
import os
import re
import shutil
import signal
import subprocess
import sys
import threading
import time

import h5py

TEMPORARIES = [".*.tmp.*", ".emb-probe-*", ".*.lock", ".*.tmp"]
FORBIDDEN = ["Sanitizer", "Segmentation", "runtime error:", "core dumped", "Aborted",
             "terminate called", "std::", "HDF5-DIAG"]
PREVIOUS = b"previous output, must survive an interrupted run\n"
NUMBER = re.compile(rb"[-+]?[0-9][0-9.eE+-]*")
PHASE_LINE = re.compile(r"^\[\s*([0-9.]+) s\] (.+?)\s*$")

TUBE = ["{src}/meshes/tube.geo", "--size", "0.05", "--set", "n_circ=16"]
SWEEP_SCENE = "{src}/tests/sweep/data/one_cylinder_direct.yaml"
DISC = "{src}/tools/scenes/jeffcott_disc.yaml"

# name -> (command after `emb`, outputs (relative to the run directory), options)
COMMANDS = {
    "mesh": (["mesh", *TUBE, "--save-mesh", "out.msh"], ["out.msh"], {}),
    "modes": (["modes", *TUBE, "--modes", "12", "-o", "out.h5"], ["out.h5", "out.xdmf"], {}),
    "reduce": (["reduce", *TUBE, "-n", "10", "-o", "out.h5"], ["out.h5", "out.xdmf"], {}),
    "run": (["run", DISC, "-o", "out.h5", "--t-end", "2", "--dt", "1e-3", "--force"],
            ["out.h5"], {"results": "out.h5"}),
    "sweep": (["sweep", SWEEP_SCENE, "--rpm", "2000,2500,3000,3500,4000", "-o", "out.h5"],
              ["out.h5"], {}),
    "sweep_j2": (["sweep", SWEEP_SCENE, "--rpm", "2000,2500,3000,3500,4000", "-j", "2", "-o",
                  "out.h5"], ["out.h5"], {}),
    "campbell": (["campbell", DISC, "--rpm", "500:6000:50", "--body", "disc", "-o", "out.csv"],
                 ["out.csv"], {}),
    "compare": (["compare", *TUBE, "--cms", "5", "--webs", "rigid", "-n", "6", "--report-dir",
                 "rep"], ["rep/tube_free-free_compare.md", "rep/tube_free-free_compare.csv"],
                {"dirs": ["rep"]}),
    "modes_slepc": (["modes", *TUBE, "--modes", "12", "--backend", "slepc", "-o", "out.h5"],
                    ["out.h5", "out.xdmf"], {"mpi_ranks": 2}),
}


def expand(args, src):
    return [a.replace("{src}", src) for a in args]


def command_line(name, args):
    cmd = [args.emb, *expand(COMMANDS[name][0], args.src)]
    ranks = COMMANDS[name][2].get("mpi_ranks")
    if ranks:
        cmd = [args.mpirun, "--allow-run-as-root", "-n", str(ranks), *cmd]
    return cmd


def mpi_env():
    return {"OMPI_MCA_plm": "isolated", "OMPI_MCA_btl_vader_single_copy_mechanism": "none",
            "OMPI_MCA_rmaps_base_oversubscribe": "1"}


def prepare(run_dir, name, previous):
    shutil.rmtree(run_dir, ignore_errors=True)
    os.makedirs(run_dir)
    for d in COMMANDS[name][2].get("dirs", []):
        os.makedirs(os.path.join(run_dir, d))
    if previous:
        for out in COMMANDS[name][1]:
            with open(os.path.join(run_dir, out), "wb") as f:
                f.write(PREVIOUS)


def progress_name(line):
    """The phase a progress line announces: "[  0.4 s] assembly" -> "assembly"; other
    progress lines ("emb sweep: [2/5] 2500 rpm: ...", "emb campbell: 550 rpm") as printed,
    up to a colon after the counter."""
    m = PHASE_LINE.match(line)
    if m:
        return m.group(2)
    return re.sub(r"^(emb \w+: [^:]+):.*$", r"\1", line)


def phases_of(lines):
    """[(seconds after the start, phase)] of the progress lines, first appearance of each."""
    found, seen = [], set()
    for t, line in lines:
        name = progress_name(line)
        if name and name not in seen and not name.startswith("emb: "):
            seen.add(name)
            found.append((t, name))
    return found


def leftovers(run_dir):
    bad = []
    for root, dirs, files in os.walk(run_dir):
        for n in files + dirs:
            if any(fnmatch.fnmatch(n, p) for p in TEMPORARIES):
                bad.append(os.path.relpath(os.path.join(root, n), run_dir))
    return bad


def session_alive(pgid):
    try:
        os.killpg(pgid, 0)
        return True
    except ProcessLookupError:
        return False
    except PermissionError:
        return True


def results_status(path):
    try:
        with h5py.File(path, "r") as f:
            s = f.attrs.get("status")
            return s.decode() if isinstance(s, bytes) else str(s)
    except OSError:
        return None


def samples(source):
    """The number of samples in a results file (a path, or the file's bytes), None if it has
    no time series."""
    if source is None:
        return None
    try:
        handle = io.BytesIO(source) if isinstance(source, bytes) else source
        with h5py.File(handle, "r") as f:
            return f["time"].shape[0] if "time" in f else None
    except OSError:
        return None


def run_once(cmd, run_dir, env, when, sig, timeout):
    """Starts cmd in its own session; sends `sig` to its pid at `when` seconds if it still
    runs. Returns (exit code or None on a hang, [(seconds, stderr line)], the time the
    signal was sent or None, seconds, pgid)."""
    start = time.monotonic()
    proc = subprocess.Popen(cmd, cwd=run_dir, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            stdin=subprocess.DEVNULL, env=env, start_new_session=True)
    pgid = proc.pid
    lines = []

    def read():  # every line (progress lines end in \r) with the time it arrived
        buf = b""
        while True:
            chunk = os.read(proc.stderr.fileno(), 4096)
            if not chunk:
                break
            buf += chunk
            parts = re.split(rb"[\r\n]", buf)
            buf = parts.pop()
            now = time.monotonic() - start
            lines.extend((now, p.decode(errors="replace").strip()) for p in parts if p.strip())
        if buf.strip():
            lines.append((time.monotonic() - start, buf.decode(errors="replace").strip()))

    reader = threading.Thread(target=read)
    reader.start()
    sent_at = None
    if when is not None:
        while time.monotonic() - start < when and proc.poll() is None:
            time.sleep(0.002)
        if proc.poll() is None:
            proc.send_signal(sig)
            sent_at = time.monotonic() - start
    try:
        proc.wait(timeout=timeout)
        rc = proc.returncode
    except subprocess.TimeoutExpired:
        os.killpg(pgid, signal.SIGKILL)
        proc.wait()
        rc = None
    reader.join()
    return rc, lines, sent_at, time.monotonic() - start, pgid


def schedule(phases, total, trials):
    """Signal moments: one at the start; half of the trials inside the phases (evenly within
    each, every phase if there are at most that many, else evenly chosen ones); the rest
    evenly over the whole time."""
    bounds = [t for t, _ in phases] + [total]
    times = [0.01]
    inside = trials // 2
    if phases and inside:
        step = max(1.0, len(phases) / inside)
        chosen = sorted({int(j * step) for j in range(len(phases)) if j * step < len(phases)})
        per = max(1, inside // len(chosen))
        for k in chosen:
            a, b = bounds[k], bounds[k + 1]
            times += [a + (b - a) * (j + 0.5) / per for j in range(per)]
    rest = max(0, trials - len(times))
    times += [total * (j + 0.5) / rest for j in range(rest)]
    return sorted(times)[:trials]


def complete(path, reference):
    """True if `path` holds a whole output: an HDF5 file that opens (emb renames a finished
    temporary into place, so a file under the name is never half written), or a text file
    with the calibration run's lines, each of the same shape (numbers aside: a report holds
    its run's timings, which differ from run to run)."""
    if path.endswith(".h5"):
        try:
            with h5py.File(path, "r"):
                return True
        except OSError:
            return False
    shape = lambda b: [NUMBER.sub(b"#", line) for line in b.rstrip().split(b"\n")]
    with open(path, "rb") as f:
        return reference is not None and shape(f.read()) == shape(reference)


def check_trial(name, run_dir, rc, err, sent, sig, pgid, reference):
    """The problems of one trial (empty: it ended as it must). `reference`: the calibration
    run's outputs (bytes by name)."""
    problems = []
    outputs = COMMANDS[name][1]
    results = COMMANDS[name][2].get("results")
    if rc is None:
        return ["HANG: no exit within the time limit"]
    # Under mpirun the launcher's code: Open MPI's forwards the signal to the ranks, waits for
    # them and exits with 1.
    died = rc == -sig or (COMMANDS[name][2].get("mpi_ranks") is not None and rc in (1, 128 + sig))
    if sent and not died and rc != 0:
        problems.append(f"expected death by {signal.Signals(sig).name} (or exit 0 if it had "
                        f"finished), got {'signal ' + str(-rc) if rc < 0 else 'exit ' + str(rc)}")
    if not sent and rc != 0:
        problems.append(f"ended before the signal with exit {rc}")
    for bad in FORBIDDEN:
        if bad in err:
            problems.append(f"'{bad}' on stderr")
    # Each output is the previous file or a complete new one (a signal after an output took
    # its name finds it finished); after exit 0, a new one.
    for out in outputs:
        path = os.path.join(run_dir, out)
        if not os.path.exists(path):
            problems.append(f"'{out}' was removed")
            continue
        with open(path, "rb") as f:
            previous = f.read() == PREVIOUS
        if previous and rc == 0:
            problems.append(f"exit 0 but '{out}' was not written")
        elif not previous and not complete(path, reference.get(out)):
            problems.append(f"'{out}' holds an incomplete new file")
        elif not previous and out == results and died:
            # A signal before the last sample stops the run ("interrupted"); one that lands
            # after the file was committed ends the process with the results whole
            # ("success", every sample of the calibration run's).
            status = results_status(path)
            whole = status == "success" and samples(path) == samples(reference.get(out))
            if status != "interrupted" and not whole:
                problems.append(f"'{out}' ends with status {status!r} and "
                                f"{samples(path)} of {samples(reference.get(out))} samples "
                                "after the signal (expected 'interrupted', or 'success' "
                                "with every sample)")
    for left in leftovers(run_dir):
        problems.append(f"'{left}' left behind")
    deadline = time.monotonic() + 5.0  # MPI launchers reap their ranks after the fact
    while session_alive(pgid) and time.monotonic() < deadline:
        time.sleep(0.05)
    if session_alive(pgid):
        problems.append("processes of the run still alive after it ended")
        os.killpg(pgid, signal.SIGKILL)
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--emb", required=True)
    ap.add_argument("--src", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--command", required=True, choices=sorted(COMMANDS))
    ap.add_argument("--trials", type=int, default=24)
    ap.add_argument("--min-trials", type=int, default=12)
    ap.add_argument("--budget", type=float, default=240.0, help="seconds for the trials")
    ap.add_argument("--mpirun", default="mpirun")
    args = ap.parse_args()
    args.emb = os.path.abspath(args.emb)
    args.src = os.path.abspath(args.src)
    name = args.command
    env = dict(os.environ)
    if COMMANDS[name][2].get("mpi_ranks"):
        env.update(mpi_env())
    work = os.path.join(os.path.abspath(args.work), name)
    cmd = command_line(name, args)

    # Calibration: the phases and the whole time, without a signal.
    cal_dir = os.path.join(work, "calibration")
    prepare(cal_dir, name, previous=False)
    rc, lines, _, total, pgid = run_once(cmd, cal_dir, env, None, None, timeout=600)
    if rc != 0:
        sys.exit(f"{name}: the calibration run failed ({rc}): " +
                 "\n".join(l for _, l in lines[-20:]))
    phases = phases_of(lines)
    reference = {}
    for out in COMMANDS[name][1]:
        with open(os.path.join(cal_dir, out), "rb") as f:
            reference[out] = f.read()
    print(f"{name}: {' '.join(cmd[1:])}")
    print(f"  calibration: {total:.2f} s, phases: " +
          ", ".join(f"{p} at {t:.2f} s" for t, p in phases))

    failures, hit, ran = [], {}, 0
    started = time.monotonic()
    for k, when in enumerate(schedule(phases, total, args.trials)):
        if time.monotonic() - started > args.budget:
            break
        sig = signal.SIGTERM if k % 2 == 0 else signal.SIGINT
        run_dir = os.path.join(work, f"trial_{k:02d}")
        prepare(run_dir, name, previous=True)
        rc, lines, sent_at, seconds, pgid = run_once(cmd, run_dir, env, when, sig,
                                                     timeout=3 * total + 60)
        ran += 1
        sent = sent_at is not None
        err = "\n".join(l for _, l in lines)
        before = [p for t, p in phases_of(lines) if t <= sent_at] if sent else []
        landed = before[-1] if before else ("start" if sent else "after the end")
        hit[landed] = hit.get(landed, 0) + 1
        problems = check_trial(name, run_dir, rc, err, sent, sig, pgid, reference)
        outcome = "finished" if rc == 0 else (f"signal {-rc}" if rc and rc < 0 else f"exit {rc}")
        print(f"  {signal.Signals(sig).name:7s} at {when:6.3f} s ({landed}): {outcome}"
              + ("" if not problems else "  FAILED: " + "; ".join(problems)))
        if problems:
            failures.append((when, sig, problems, err[-1500:]))
        else:
            shutil.rmtree(run_dir, ignore_errors=True)
    print(f"  phases hit: " + ", ".join(f"{p} x{n}" for p, n in hit.items()))
    missed = [p for _, p in phases if p not in hit]
    if missed and len(phases) <= args.trials // 2:
        print(f"  note: no signal landed in {', '.join(missed)} on this machine's timing")
    elif missed:
        print(f"  {len(phases) - len(missed)} of {len(phases)} progress steps hit")
    if ran < args.min_trials:
        failures.append((0, 0, [f"only {ran} trials within the budget of {args.budget} s "
                                f"(at least {args.min_trials} expected)"], ""))
    for when, sig, problems, err in failures:
        print(f"FAILED at {when:.3f} s: " + "; ".join(problems))
        if err:
            print("  its stderr ends with:\n    " + err.strip().replace("\n", "\n    "))
    print(f"{name}: {ran} trials, {len(failures)} failed")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
