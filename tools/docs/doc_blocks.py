#!/usr/bin/python3
"""Runs the runnable command blocks of a documentation page, as a reader would.

A fenced block is runnable when the line just before its opening fence is
    <!-- doc-run -->
The blocks of one page run in order, in one scratch copy of the repository (a page is one
session: a block may use what the blocks before it wrote), from its root, with `bash -e -o
pipefail`: `build/tools/emb/emb` is the built tool, `meshes/`, `tools/plots/` and the other
folders are the repository's (read-only use), `tools/scenes/` is a copy (scenes write their
results next to themselves) and `out/` is empty at the start.

Usage (stdlib only; /usr/bin/python3):
    doc_blocks.py run PAGE --root SRC --build BUILD [--timeout SECONDS] [--keep DIR]
    doc_blocks.py list PAGE...        print the runnable blocks with their line numbers
The ctests docs_run_<page> run the task pages this way (tests/docs/CMakeLists.txt).
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

MARKER = "<!-- doc-run -->"
FENCE = re.compile(r"^(```+|~~~+)\s*([\w+-]*)")


def fenced_blocks(text):
    """(first line number, info string, body, runnable) of every fenced block of `text`."""
    lines = text.split("\n")
    blocks, i = [], 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        fence, info, start = m.group(1), m.group(2), i
        body = []
        i += 1
        while i < len(lines) and not lines[i].startswith(fence):
            body.append(lines[i])
            i += 1
        runnable = start > 0 and lines[start - 1].strip() == MARKER
        blocks.append((start + 1, info, "\n".join(body), runnable))
        i += 1
    return blocks


def runnable_blocks(path):
    with open(path, encoding="utf-8") as f:
        return [(n, body) for n, _, body, run in fenced_blocks(f.read()) if run]


def scratch_tree(root, build, work):
    """The repository as a reader's working copy: links to the sources, a copy of the scenes,
    the built tool at build/tools/emb/emb and an empty out/."""
    for name in os.listdir(root):
        if name in ("tools", "out", ".git") or name.startswith("build"):
            continue
        os.symlink(os.path.join(root, name), os.path.join(work, name))
    os.mkdir(os.path.join(work, "tools"))
    for name in os.listdir(os.path.join(root, "tools")):
        src = os.path.join(root, "tools", name)
        if name == "scenes":
            shutil.copytree(src, os.path.join(work, "tools", name))
        else:
            os.symlink(src, os.path.join(work, "tools", name))
    os.makedirs(os.path.join(work, "build", "tools", "emb"))
    os.symlink(os.path.join(build, "tools", "emb", "emb"), os.path.join(work, "build", "tools", "emb", "emb"))
    for name in ("examples", "benchmarks"):
        if os.path.isdir(os.path.join(build, name)):
            os.symlink(os.path.join(build, name), os.path.join(work, "build", name))
    os.mkdir(os.path.join(work, "out"))


def run_page(page, root, build, timeout, keep):
    blocks = runnable_blocks(page)
    if not blocks:
        sys.exit(f"doc_blocks.py: {page} has no block marked {MARKER}")
    work = keep or tempfile.mkdtemp(prefix="emb-doc-")
    os.makedirs(work, exist_ok=True)
    scratch_tree(root, build, work)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    try:
        for line, body in blocks:
            t0 = time.monotonic()
            print(f"--- {os.path.basename(page)}:{line}\n{body}", flush=True)
            r = subprocess.run(["bash", "-e", "-o", "pipefail", "-c", body], cwd=work, env=env,
                               capture_output=True, text=True, timeout=timeout)
            print(r.stdout[-4000:], end="")
            if r.returncode != 0:
                print(r.stderr[-4000:], file=sys.stderr)
                print(f"doc_blocks.py: {page}:{line}: the block failed with exit code {r.returncode}",
                      file=sys.stderr)
                return 1
            print(f"--- ok in {time.monotonic() - t0:.1f} s", flush=True)
    finally:
        if not keep:
            shutil.rmtree(work, ignore_errors=True)
    return 0


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="what", required=True)
    r = sub.add_parser("run")
    r.add_argument("page")
    r.add_argument("--root", required=True)
    r.add_argument("--build", required=True)
    r.add_argument("--timeout", type=float, default=300.0, help="per block [s]")
    r.add_argument("--keep", help="run in this directory and keep it")
    ls = sub.add_parser("list")
    ls.add_argument("pages", nargs="+")
    a = p.parse_args()
    if a.what == "list":
        for page in a.pages:
            for line, body in runnable_blocks(page):
                print(f"{page}:{line}\n{body}\n")
        return 0
    return run_page(os.path.abspath(a.page), os.path.abspath(a.root), os.path.abspath(a.build),
                    a.timeout, a.keep and os.path.abspath(a.keep))


if __name__ == "__main__":
    sys.exit(main())
