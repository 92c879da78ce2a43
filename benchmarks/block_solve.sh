#!/usr/bin/env bash
# Sparse solves with blocks of right-hand sides (build/benchmarks/block_solve) on the default
# crankshaft meshed at h = 8 mm and 5.8 mm (or the sizes given).
# Usage: bash benchmarks/block_solve.sh [H ...]   (from the repository root, after building).
# Meshes out/bench/crank_h<H>.msh; the numbers go to benchmarks/results/block_solve.json.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${EMB_BUILD_DIR:-$root/build}
command="bash benchmarks/block_solve.sh $*"
sizes=("$@")
((${#sizes[@]})) || sizes=(0.008 0.0058)
mkdir -p "$root/out/bench"
runs=()
for h in "${sizes[@]}"; do
  mesh="$root/out/bench/crank_h$h.msh"
  [ -f "$mesh" ] || "$build/tools/emb/emb" mesh "$root/meshes/crankshaft_i4.geo" --size "$h" \
    --save-mesh "$mesh" -q > /dev/null
  "$build/benchmarks/block_solve" "$mesh" --json > "$root/out/bench/block_h$h.json"
  runs+=("$h=$root/out/bench/block_h$h.json")
done
/usr/bin/python3 "$root/benchmarks/record.py" merge block_solve --command "${command% }" "${runs[@]}"
/usr/bin/python3 "$root/benchmarks/render_tables.py" --print block_solve
