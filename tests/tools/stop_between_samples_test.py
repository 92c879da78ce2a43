"""A SIGINT while `emb run` is between two samples stops the run before IDA's next step, not
at the next sample (which may be far: a run whose steps have become tiny, or one long output
interval): the process ends by the signal within seconds, its results file says
"interrupted" at a time before the end, and the message says it stopped between samples.

    /usr/bin/python3 tests/tools/stop_between_samples_test.py EMB_EXECUTABLE SOURCE_DIR

The Jeffcott rotor (tools/scenes/jeffcott_disc.yaml) over 200 s with one output interval of
200 s: ~36 s of dynamic analysis (Release build) with no sample in between; its set-up takes
well under a second. The signal goes 3 s after the start (the run prints no progress line
before its first sample, so there is no phase to wait for). Before the change the run went
on to t = 200 s and then reported the signal after the finished run.
"""
import os
import signal
import subprocess
import sys
import tempfile
import threading
import time

import h5py

EMB, SOURCE = sys.argv[1], sys.argv[2]
# From the signal to the process's end: one IDA step and closing the file (a sanitizer build
# is 2-3x slower); far below the ~33 s the run would still take to its end.
STOP_SECONDS = 10.0


def main():
    work = tempfile.mkdtemp(prefix="emb_stop_")
    out = os.path.join(work, "out.h5")
    scene = os.path.join(SOURCE, "tools", "scenes", "jeffcott_disc.yaml")
    proc = subprocess.Popen([EMB, "run", scene, "-o", out, "--t-end", "200", "--dt", "200",
                             "--force"], cwd=work, stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE, text=True, start_new_session=True)
    lines = []

    def read():
        for line in proc.stderr:
            lines.append(line)

    reader = threading.Thread(target=read)
    reader.start()
    time.sleep(3.0)
    if proc.poll() is not None:
        reader.join()
        sys.exit(f"FAILED: emb run ended ({proc.returncode}) before the signal:\n" + "".join(lines))
    sent = time.monotonic()
    proc.send_signal(signal.SIGINT)
    try:
        rc = proc.wait(timeout=60.0)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        sys.exit("FAILED: no exit within 60 s of the SIGINT")
    took = time.monotonic() - sent
    reader.join()
    err = "".join(lines)
    problems = []
    if rc != -signal.SIGINT:
        problems.append(f"expected death by SIGINT, got {rc}")
    if took > STOP_SECONDS:
        problems.append(f"took {took:.1f} s after the signal (expected < {STOP_SECONDS} s)")
    if "between two samples" not in err:
        problems.append("the message does not say the run stopped between two samples")
    with h5py.File(out, "r") as f:
        status = f.attrs["status"]
        status = status.decode() if isinstance(status, bytes) else str(status)
        reached = float(f.attrs["t_reached"])
    if status != "interrupted":
        problems.append(f"status {status!r} (expected 'interrupted')")
    if not reached < 200.0:
        problems.append(f"t_reached {reached} (expected before the end, 200 s)")
    print(f"stopped {took:.2f} s after the SIGINT, status {status}, t_reached {reached}")
    for p in problems:
        print("FAILED:", p)
    if problems:
        print(err)
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
