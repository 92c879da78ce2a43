#!/usr/bin/python3
"""Replays emb's corpus of bad inputs and faults (issue 14) and fails on any crash, hang,
silent acceptance or lost file.

    /usr/bin/python3 tests/corpus/run_corpus.py --emb build/tools/emb/emb --src . \
        --work build/corpus_work [-j 2] [--only NAME_PREFIX] [--list]

Each case of make_manifest.py (imported; one entry per case: category, setup steps,
command, expected exit code and stderr fragments, files that must not exist or must not
change afterwards, optionally a second command) runs in a fresh directory
WORK/cases/<name>. Every
case is also held to rules no case may break:
  - no crash: no death by a signal the case did not send, no exit code 4 (internal error);
  - no hang: the command ends within the case's timeout (default 60 s);
  - no raw C++ failure text on stderr ("std::", "stod", "_M_range_check", "bad_alloc", ...);
  - the exact exit code expected (a bad input that exits 0 is a silent acceptance);
  - no hidden temporaries (".*.tmp.*", ".emb-probe-*") left by anything but SIGKILL, and no
    lock file (".*.lock", which emb no longer makes) at all.
Fixtures (a small part, its mesh, a body file, results files) are made once per run with
the emb under test, into WORK/fix. Full-disk cases mount a small tmpfs when they can (root)
and otherwise limit the file size with RLIMIT_FSIZE; read-only directories are a read-only
tmpfs mount (root) or mode 0555 (others); the case says which it got.
"""

import argparse
import base64
import concurrent.futures
import fnmatch
import hashlib
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import time

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
FORBIDDEN = ["std::", "stod", "stoi", "_M_range_check", "basic_string", "bad_alloc",
             "vector::", "terminate called", "what():", "Segmentation", "Sanitizer",
             "runtime error:", "core dumped", "Aborted", "HDF5-DIAG"]
TEMPORARIES = [".*.tmp.*", ".emb-probe-*", ".*.lock"]
SIGNALS = {"INT": signal.SIGINT, "TERM": signal.SIGTERM, "KILL": signal.SIGKILL}


class Context:
    def __init__(self, args):
        self.emb = os.path.abspath(args.emb)
        self.src = os.path.abspath(args.src)
        self.work = os.path.abspath(args.work)
        self.fix = os.path.join(self.work, "fix")
        self.can_mount = os.geteuid() == 0 and self._try_mount()

    def _try_mount(self):
        probe = os.path.join(self.work, "mount_probe")
        os.makedirs(probe, exist_ok=True)
        ok = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", probe],
                            capture_output=True).returncode == 0
        if ok:
            subprocess.run(["umount", probe], capture_output=True)
        return ok

    def expand(self, s, case_dir):
        return (s.replace("{emb}", self.emb).replace("{src}", self.src)
                .replace("{fix}", self.fix).replace("{work}", case_dir))


# --- fixtures --------------------------------------------------------------------------

def make_fixtures(ctx, fixtures):
    """Writes the fixture files of the manifest and runs its commands in WORK/fix."""
    shutil.rmtree(ctx.fix, ignore_errors=True)
    os.makedirs(ctx.fix)
    for name, text in fixtures["files"].items():
        with open(os.path.join(ctx.fix, name), "w") as f:
            f.write(text)
    for args in fixtures["commands"]:
        r = subprocess.run([ctx.emb, *args, "-q"], cwd=ctx.fix, capture_output=True, text=True,
                           timeout=300)
        if r.returncode != 0:
            sys.exit(f"fixture: emb {' '.join(args)} failed ({r.returncode}): {r.stderr}")


# --- setup steps -----------------------------------------------------------------------

class Mounts:
    def __init__(self):
        self.points = []

    def mount(self, path, options):
        r = subprocess.run(["mount", "-t", "tmpfs", "-o", options, "tmpfs", path],
                           capture_output=True, text=True)
        if r.returncode != 0:
            raise RuntimeError(f"mount {path}: {r.stderr}")
        self.points.append(path)

    def release(self):
        for p in reversed(self.points):
            subprocess.run(["umount", "-l", p], capture_output=True)
        self.points = []


def h5_mutate(path, op, args, ctx, case_dir):
    """Changes an HDF5 file as a crafted or damaged one would be."""
    with h5py.File(path, "r+") as f:
        if op == "delete":
            del f[args[0]]
        elif op == "del_attr":
            del f[args[0]].attrs[args[1]]
        elif op == "set_attr":
            obj, name, value, kind = args
            if kind == "float":
                f[obj].attrs[name] = np.float64(float(value))
            elif kind == "int":
                f[obj].attrs[name] = np.int64(int(value))
            elif kind == "str":  # fixed-length, as emb writes strings
                f[obj].attrs[name] = np.bytes_(str(value).encode())
            elif kind == "vlen_str":  # h5py's default for str: refused by emb
                f[obj].attrs[name] = str(value)
            elif kind == "array":
                f[obj].attrs[name] = np.full(int(value), 1.0)
        elif op == "ext_link":
            target = ctx.expand(args[1], case_dir)
            f[args[0]] = h5py.ExternalLink(target, args[2])
        elif op == "soft_link":
            f[args[0]] = h5py.SoftLink(args[1])
        elif op == "ext_dataset":
            f.create_dataset(args[0], shape=(4,), dtype="f8",
                             external=[(ctx.expand(args[1], case_dir), 0, 32)])
        elif op == "vds":
            target = ctx.expand(args[1], case_dir)
            layout = h5py.VirtualLayout(shape=(4,), dtype="f8")
            layout[:] = h5py.VirtualSource(target, args[2], shape=(4,))
            f.create_virtual_dataset(args[0], layout)
        elif op == "replace":  # a dataset replaced by one of another shape or type
            name, shape, dtype = args
            data = f[name][()] if name in f else None
            del f[name]
            if dtype == "str":
                f.create_dataset(name, data=np.array([b"x"] * int(np.prod(shape)), dtype="S1"))
            elif dtype == "vlen_str":
                f.create_dataset(name, data=["x"] * int(np.prod(shape)),
                                 dtype=h5py.string_dtype())
            else:
                f.create_dataset(name, data=np.zeros(shape, dtype=dtype))
        elif op == "huge":  # claims far more values than the file holds
            name = args[0]
            if name in f:
                del f[name]
            f.create_dataset(name, shape=(1 << 20, 1 << 20), dtype="f8", chunks=(64, 64),
                             compression="gzip")
        elif op == "scale":  # one entry changed, as a disk error or an editor would
            name, index, value = args
            a = f[name][()]
            a.flat[int(index)] = float(value)
            f[name][...] = a
        elif op == "fill":  # a whole dataset set to one value, shape kept
            name, value = args
            a = f[name][()]
            a[...] = float(value)
            f[name][...] = a
        else:
            raise ValueError(op)


def run_setup(step, ctx, case_dir, mounts, env):
    kind, *a = step
    p = lambda x: os.path.join(case_dir, ctx.expand(x, case_dir))  # noqa: E731
    if kind == "write":
        os.makedirs(os.path.dirname(p(a[0])) or ".", exist_ok=True)
        with open(p(a[0]), "w") as f:
            f.write(ctx.expand(a[1], case_dir))
    elif kind == "writeb":
        with open(p(a[0]), "wb") as f:
            f.write(base64.b64decode(a[1]))
    elif kind == "copy":
        shutil.copy(ctx.expand(a[0], case_dir), p(a[1]))
    elif kind == "truncate":
        src = ctx.expand(a[0], case_dir)
        data = open(src, "rb").read()
        with open(p(a[1]), "wb") as f:
            f.write(data[:int(len(data) * float(a[2]))])
    elif kind == "mkdir":
        os.makedirs(p(a[0]), exist_ok=True)
    elif kind == "symlink":
        os.symlink(ctx.expand(a[0], case_dir), p(a[1]))
    elif kind == "fifo":
        os.mkfifo(p(a[0]))
    elif kind == "chmod":
        os.chmod(p(a[0]), int(a[1], 8))
    elif kind == "h5":
        shutil.copy(ctx.expand(a[0], case_dir), p(a[1]))
        h5_mutate(p(a[1]), a[2], a[3:], ctx, case_dir)
    elif kind == "readonly_dir":
        os.makedirs(p(a[0]), exist_ok=True)
        if ctx.can_mount:
            mounts.mount(p(a[0]), "size=1m,ro")
            env["how"] = "read-only tmpfs"
        else:
            os.chmod(p(a[0]), 0o555)
            env["how"] = "mode 0555"
    elif kind == "full_dir":  # a directory on a full disk of a[1] KiB
        os.makedirs(p(a[0]), exist_ok=True)
        if ctx.can_mount:
            mounts.mount(p(a[0]), f"size={a[1]}k")
            env["how"] = f"{a[1]} KiB tmpfs"
        else:
            env["fsize"] = int(a[1]) * 1024
            env["how"] = f"RLIMIT_FSIZE {a[1]} KiB"
    elif kind == "fill_disk":  # fills a full_dir to the last byte
        try:
            with open(p(a[0]), "wb") as f:
                while True:
                    f.write(b"\0" * 4096)
                    f.flush()
        except OSError:
            pass
    elif kind == "hold_lock":  # another emb process writing this output: its lock's name
        out = os.path.realpath(p(a[0]))  # (libemb/io/output_lock.h) bound by this process
        st = os.stat(os.path.dirname(out))
        holder = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        holder.bind(f"\0emb-output/{st.st_dev:x}/{st.st_ino:x}/{os.path.basename(out)}")
        holder.listen(1)
        env.setdefault("fds", []).append(holder)
    else:
        raise ValueError(f"unknown setup step {kind}")


def digest(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


# --- one case ----------------------------------------------------------------------------

def run_case(case, ctx):
    name = case["name"]
    case_dir = os.path.join(ctx.work, "cases", name)
    if os.path.exists(case_dir):
        subprocess.run(["umount", "-R", "-l", case_dir], capture_output=True)
        subprocess.run(["chmod", "-R", "u+rwx", case_dir], capture_output=True)
        shutil.rmtree(case_dir, ignore_errors=True)
    os.makedirs(case_dir)
    mounts = Mounts()
    env = {}
    problems = []
    try:
        for step in case.get("setup", []):
            run_setup(step, ctx, case_dir, mounts, env)
        unchanged = {u: digest(os.path.join(case_dir, u)) for u in case.get("unchanged", [])}
        cmd = [ctx.expand(c, case_dir) for c in case["cmd"]]
        if env.get("fsize"):  # SIGXFSZ ignored: a write past the limit fails with EFBIG
            cmd = ["bash", "-c", f'trap "" XFSZ; ulimit -f {env["fsize"] // 1024}; exec "$@"',
                   "bash", *cmd]
        start = time.monotonic()
        proc_env = dict(os.environ, **case.get("env", {}))
        proc = subprocess.Popen(cmd, cwd=case_dir, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                stdin=subprocess.DEVNULL, text=True, errors="replace",
                                env=proc_env)
        sent = None
        sig = case.get("signal")
        timeout = case.get("timeout", 60)
        if sig:
            deadline = start + timeout
            wait_for = sig.get("when", "")
            while time.monotonic() < deadline and proc.poll() is None:
                if wait_for.startswith("exists:"):
                    if os.path.exists(os.path.join(case_dir, wait_for[7:])):
                        break
                elif time.monotonic() - start >= float(wait_for or 0):
                    break
                time.sleep(0.02)
            time.sleep(float(sig.get("delay", 0)))
            if proc.poll() is None:
                sent = SIGNALS[sig["sig"]]
                proc.send_signal(sent)
                # A signal case is timing-dependent: where the signal lands depends on the
                # machine's speed. Its report says when it was sent (the systematic sweep over
                # every moment is tests/tools/signal_timing_test.py).
                env["how"] = (f"timing-dependent: SIG{sig['sig']} sent "
                              f"{time.monotonic() - start:.2f} s after the start")
                if sig.get("again"):
                    time.sleep(float(sig["again"]))
                    if proc.poll() is None:
                        proc.send_signal(sent)
        try:
            out, err = proc.communicate(timeout=max(1.0, timeout - (time.monotonic() - start)))
        except subprocess.TimeoutExpired:
            proc.kill()
            out, err = proc.communicate()
            problems.append(f"HANG: no exit within {timeout} s")
        rc = proc.returncode
        seconds = time.monotonic() - start

        # Exit code.
        expected = case["exit"]
        if sig and isinstance(expected, str) and expected == "signal":
            if sent is None:
                problems.append(f"the command ended after {time.monotonic() - start:.2f} s, "
                                "before the signal could be sent (timing-dependent: this "
                                "machine ran it faster than the case assumes)")
            elif rc != -sent:
                problems.append(f"expected death by {sig['sig']}, got exit {rc}")
        elif rc < 0 and (sent is None or rc != -sent):
            problems.append(f"CRASH: killed by signal {-rc}")
        elif rc != expected:
            kind = "SILENT ACCEPTANCE" if rc == 0 else "WRONG EXIT"
            problems.append(f"{kind}: expected exit {expected}, got {rc}")
        if rc == 4:
            problems.append("INTERNAL ERROR (exit 4)")
        for frag in case.get("stderr", []):
            if frag.lower() not in err.lower():
                problems.append(f"stderr lacks '{frag}'")
        for frag in case.get("stderr_absent", []):
            if frag in err:
                problems.append(f"stderr holds '{frag}'")
        for bad in FORBIDDEN:
            if bad in err:
                problems.append(f"RAW FAILURE TEXT '{bad}' on stderr")
        # Files.
        for pattern in case.get("absent", []):
            for root, dirs, files in os.walk(case_dir):
                for n in files + dirs:
                    rel = os.path.relpath(os.path.join(root, n), case_dir)
                    if fnmatch.fnmatch(rel, pattern):
                        problems.append(f"'{rel}' exists (expected none matching '{pattern}')")
        for path in case.get("exists", []):
            if not os.path.exists(os.path.join(case_dir, path)):
                problems.append(f"'{path}' does not exist")
        for u, d in unchanged.items():
            if not os.path.exists(os.path.join(case_dir, u)) or digest(os.path.join(case_dir, u)) != d:
                problems.append(f"'{u}' was changed or removed")
        for path, attr, value in case.get("h5_attr", []):
            try:
                with h5py.File(os.path.join(case_dir, path), "r") as f:
                    got = f.attrs.get(attr)
                    got = got.decode() if isinstance(got, bytes) else got
                    if got != value:
                        problems.append(f"{path}@{attr} is '{got}', expected '{value}'")
            except OSError as e:
                problems.append(f"{path} unreadable: {e}")
        then = case.get("then")
        if then:  # a second command in the same directory, e.g. a rerun after a kill
            cmd2 = [ctx.expand(c, case_dir) for c in then["cmd"]]
            try:
                r2 = subprocess.run(cmd2, cwd=case_dir, capture_output=True, text=True,
                                    errors="replace", stdin=subprocess.DEVNULL, timeout=timeout)
                if r2.returncode != then["exit"]:
                    problems.append(f"second command: expected exit {then['exit']}, got "
                                    f"{r2.returncode}: {r2.stderr[-500:]}")
                for bad in FORBIDDEN:
                    if bad in r2.stderr:
                        problems.append(f"second command: RAW FAILURE TEXT '{bad}' on stderr")
            except subprocess.TimeoutExpired:
                problems.append(f"second command: HANG: no exit within {timeout} s")
        kill_left_them = sig and sig["sig"] == "KILL" and not then
        if not kill_left_them and not case.get("keep_temporaries"):
            for root, dirs, files in os.walk(case_dir):
                for n in files:
                    if any(fnmatch.fnmatch(n, t) for t in TEMPORARIES):
                        problems.append(f"temporary left: {os.path.relpath(os.path.join(root, n), case_dir)}")
        return {"name": name, "category": case["category"], "rc": rc, "seconds": seconds,
                "problems": problems, "stderr": err[-2000:], "how": env.get("how", "")}
    except Exception as e:  # a broken case is a failure too
        return {"name": name, "category": case["category"], "rc": None, "seconds": 0.0,
                "problems": [f"runner: {type(e).__name__}: {e}"], "stderr": "", "how": ""}
    finally:
        for holder in env.get("fds", []):
            holder.close()
        mounts.release()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--emb", required=True)
    ap.add_argument("--src", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--manifest", default="",
                    help="a JSON manifest (make_manifest.py --write) instead of the module")
    ap.add_argument("-j", type=int, default=2)
    ap.add_argument("--only", default="", help="run the cases whose name starts with this")
    ap.add_argument("--list", action="store_true", help="print the cases by category and exit")
    ap.add_argument("-v", action="store_true", help="print every case")
    args = ap.parse_args()
    if args.manifest:
        with open(args.manifest) as f:
            manifest = json.load(f)
    else:
        sys.path.insert(0, HERE)
        import make_manifest  # noqa: E402  (tests/corpus/make_manifest.py)
        manifest = make_manifest.manifest()
    cases = manifest["cases"]
    if args.list:
        counts = {}
        for c in cases:
            counts[c["category"]] = counts.get(c["category"], 0) + 1
        for k in sorted(counts):
            print(f"{k:10s} {counts[k]}")
        print(f"{'total':10s} {len(cases)}")
        return
    cases = [c for c in cases if c["name"].startswith(args.only)]
    os.makedirs(args.work, exist_ok=True)
    ctx = Context(args)
    make_fixtures(ctx, manifest["fixtures"])
    start = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.j) as pool:
        results = list(pool.map(lambda c: run_case(c, ctx), cases))
    failed = [r for r in results if r["problems"]]
    by_cat = {}
    for r in results:
        by_cat.setdefault(r["category"], [0, 0])
        by_cat[r["category"]][0] += 1
        by_cat[r["category"]][1] += bool(r["problems"])
    for r in results:
        if r["problems"] or args.v:
            print(f"{'FAIL' if r['problems'] else 'ok  '} {r['name']} (exit {r['rc']}, "
                  f"{r['seconds']:.1f} s{', ' + r['how'] if r['how'] else ''})")
            for p in r["problems"]:
                print(f"     {p}")
            if r["problems"]:
                print("     stderr: " + r["stderr"].strip().replace("\n", "\n             "))
    print(f"corpus: {len(results)} cases, {len(failed)} failed, "
          f"{time.monotonic() - start:.0f} s (full-disk and read-only faults: "
          f"{'tmpfs mounts' if ctx.can_mount else 'RLIMIT_FSIZE and mode 0555'})")
    for k in sorted(by_cat):
        print(f"  {k:10s} {by_cat[k][0]:4d} cases, {by_cat[k][1]} failed")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
