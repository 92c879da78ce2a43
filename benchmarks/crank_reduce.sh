#!/usr/bin/env bash
# Craig–Bampton reduction benchmark of the default inline-4 crankshaft (default interfaces:
# 5 journals + 4 pins RBE3, flange + nose RBE2).
#   sizes: time per phase and peak memory at three mesh sizes (--band 3000: the modes a
#          0–3 kHz engine run needs), certificate included;
#   modes: frequency error of the reduced body against the full FE model (same couplings,
#          up to 6 kHz) as a function of the fixed-interface modes kept, against wall time.
# Usage: bash benchmarks/crank_reduce.sh [sizes|modes|all]   (from the repository root, after
# tools/setup.sh build). Writes out/bench/reduce_*.json, prints Markdown tables and saves
# out/bench/reduce_error_vs_time.png.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB_EXE:-$root/build/tools/emb/emb}
what=${1:-all}
mkdir -p "$root/out/bench"
geo="$root/meshes/crankshaft_i4.geo"
if [[ $what == sizes || $what == all ]]; then
  files=()
  for h in 0.020 0.0095 0.0058; do   # ~35k, ~93k, ~293k DOF
    f="$root/out/bench/reduce_h$h.json"
    "$emb" reduce "$geo" --size "$h" --band 3000 -o "$root/out/bench/reduce_h$h.h5" --json -q > "$f"
    files+=("$f")
  done
  /usr/bin/python3 "$root/benchmarks/reduce_table.py" sizes "${files[@]}"
fi
if [[ $what == modes || $what == all ]]; then
  files=()
  for n in 5 10 20 40 80 160; do
    f="$root/out/bench/reduce_n$n.json"
    "$emb" reduce "$geo" --size 0.0095 --modes "$n" --check-fmax 6000 --no-static-check \
      --no-mesh-shapes -o "$root/out/bench/reduce_n$n.h5" --json -q > "$f"
    files+=("$f")
  done
  /usr/bin/python3 "$root/benchmarks/reduce_table.py" modes "${files[@]}"
fi
