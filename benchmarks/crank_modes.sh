#!/usr/bin/env bash
# Modal-analysis benchmark of the default inline-4 crankshaft at three mesh sizes.
# Usage: bash benchmarks/crank_modes.sh [MODES] [H ...]      (run from the repository root,
# after tools/setup.sh build). Raw outputs out/bench/crank_h<H>.json; the numbers go to
# benchmarks/results/crank_modes.json (benchmarks/record.py) and the table is printed
# (benchmarks/render_tables.py updates the docs from it).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB_EXE:-$root/build/tools/emb/emb}
command="bash benchmarks/crank_modes.sh $*"
modes=${1:-30}
shift || true
sizes=("$@")
((${#sizes[@]})) || sizes=(0.020 0.0095 0.0058)   # ~36k, ~100k, ~300k DOF
mkdir -p "$root/out/bench"
runs=()
for h in "${sizes[@]}"; do
  f="$root/out/bench/crank_h$h.json"
  "$emb" modes "$root/meshes/crankshaft_i4.geo" --size "$h" --modes "$modes" --no-output --json -q > "$f"
  runs+=("$h=$f")
done
/usr/bin/python3 "$root/benchmarks/record.py" modes crank_modes --command "${command% }" "${runs[@]}"
/usr/bin/python3 "$root/benchmarks/render_tables.py" --print crank_modes
