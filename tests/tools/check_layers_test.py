#!/usr/bin/env python3
"""tools/checks/check_layers.py: the real tree has no upward include, and the checker does
find one (a synthetic tree where mbs/core includes mbs/dae), so a pass means something."""
import pathlib
import subprocess
import sys
import tempfile

root = pathlib.Path(sys.argv[1])
checker = root / "tools" / "checks" / "check_layers.py"

real = subprocess.run([sys.executable, str(checker), str(root)], capture_output=True, text=True)
if real.returncode != 0:
    print(real.stdout, real.stderr)
    sys.exit("the source tree has layer violations")

with tempfile.TemporaryDirectory() as tmp:
    t = pathlib.Path(tmp)
    (t / "libemb/mbs/core").mkdir(parents=True)
    (t / "libemb/mbs/dae").mkdir(parents=True)
    (t / "libemb/mbs/dae/ggl_dae.h").write_text('#include "libemb/mbs/core/system.h"\n')
    (t / "libemb/mbs/core/system.h").write_text('#pragma once\n#include "libemb/mbs/dae/ggl_dae.h"\n')
    bad = subprocess.run([sys.executable, str(checker), str(t)], capture_output=True, text=True)
    if bad.returncode != 1 or "libemb/mbs/core/system.h:2" not in bad.stdout:
        print(bad.stdout, bad.stderr)
        sys.exit("the checker missed an upward include")
print("layers: ok")
