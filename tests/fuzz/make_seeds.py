#!/usr/bin/python3
"""Seeds of emb's libFuzzer targets (issue 14), into OUT/<target>/:

    /usr/bin/python3 tests/fuzz/make_seeds.py --emb build-asan/tools/emb/emb --out DIR

The committed seeds and findings (tests/fuzz/seeds/<target>/: text files, and any input a
fuzzer once crashed on, kept as a regression), the repository's own .geo files and scenes,
and HDF5 and mesh files made with the emb under test: a small body file, a results file and
a saved mesh (binary files are made, not committed).
"""

import argparse
import glob
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SRC = os.path.dirname(os.path.dirname(HERE))
TARGETS = ["geo_script", "scene", "body_file", "results_file", "mesh"]

# The corpus's fixtures, a shorter run of the disc (smaller HDF5 seeds fuzz faster).
sys.path.insert(0, os.path.join(SRC, "tests", "corpus"))
from make_manifest import BAR_GEO, DISC  # noqa: E402
DISC = DISC.replace("t_end: 0.08, output_step: 0.0001", "t_end: 0.02, output_step: 0.002")
assert "t_end: 0.02" in DISC


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--emb", required=True)
    ap.add_argument("--out", required=True)
    args = ap.parse_args()
    shutil.rmtree(args.out, ignore_errors=True)
    for t in TARGETS:
        os.makedirs(os.path.join(args.out, t))
        for f in glob.glob(os.path.join(HERE, "seeds", t, "*")):
            shutil.copy(f, os.path.join(args.out, t))
    for f in glob.glob(os.path.join(SRC, "meshes", "*.geo")):
        shutil.copy(f, os.path.join(args.out, "geo_script"))
    for f in glob.glob(os.path.join(SRC, "tools", "scenes", "*.yaml")):
        shutil.copy(f, os.path.join(args.out, "scene"))
    with tempfile.TemporaryDirectory() as work:
        for name, text in (("bar.geo", BAR_GEO), ("disc.yaml", DISC)):
            with open(os.path.join(work, name), "w") as f:
                f.write(text)
        shutil.copy(os.path.join(work, "bar.geo"), os.path.join(args.out, "geo_script"))
        shutil.copy(os.path.join(work, "disc.yaml"), os.path.join(args.out, "scene"))
        for cmd in (["mesh", "bar.geo", "--save-mesh", "bar.msh"],
                    ["reduce", "bar.geo", "-i", "x0", "-i", "x1:rbe3", "-n", "2",
                     "--no-reference", "--no-xdmf", "--stress-surface", "-o", "body.h5"],
                    ["run", "disc.yaml", "-o", "disc.h5"]):
            r = subprocess.run([args.emb, *cmd, "-q"], cwd=work, capture_output=True, text=True)
            if r.returncode != 0:
                sys.exit(f"make_seeds: emb {' '.join(cmd)} failed ({r.returncode}): {r.stderr}")
        for name, target in (("bar.msh", "mesh"), ("body.h5", "body_file"),
                             ("disc.h5", "results_file")):
            shutil.copy(os.path.join(work, name), os.path.join(args.out, target))
    for t in TARGETS:
        print(f"{t}: {len(os.listdir(os.path.join(args.out, t)))} seeds")


if __name__ == "__main__":
    main()
