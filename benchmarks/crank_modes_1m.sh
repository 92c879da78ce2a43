#!/usr/bin/env bash
# Issue 16: the default inline-4 crankshaft meshed to about a million DOF (Tet10), 30 lowest
# modes free-free by `emb modes` on this machine: time per phase, factor fill, peak memory.
# Usage: bash benchmarks/crank_modes_1m.sh [H]     (from the repository root, after
# tools/setup.sh build; default H = 0.00357 m, ~1.0M DOF; run it alone: it needs ~15 GB and
# both cores). The mesh is made once (out/bench/big/crank_h<H>.msh) and reused; the numbers
# go to benchmarks/results/crank_modes_1m.json, the table to benchmarks/README.md.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB_EXE:-$root/build/tools/emb/emb}
h=${1:-0.00357}
dir="$root/out/bench/big"
mkdir -p "$dir"
mesh="$dir/crank_h$h.msh"
[ -f "$mesh" ] || "$emb" mesh "$root/meshes/crankshaft_i4.geo" --size "$h" --save-mesh "$mesh" -q > /dev/null
"$emb" modes "$mesh" --modes 30 --no-output --json -q > "$dir/crank_h$h.json"
/usr/bin/python3 "$root/benchmarks/record.py" modes crank_modes_1m \
  --command "bash benchmarks/crank_modes_1m.sh $*" "$h=$dir/crank_h$h.json"
/usr/bin/python3 "$root/benchmarks/render_tables.py" --print crank_modes_1m
