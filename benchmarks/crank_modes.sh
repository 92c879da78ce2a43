#!/usr/bin/env bash
# Modal-analysis benchmark of the default inline-4 crankshaft at three mesh sizes.
# Usage: bash benchmarks/crank_modes.sh [MODES] [H ...]      (run from the repository root,
# after tools/setup.sh build). Writes out/bench/crank_h<H>.json and prints a Markdown table.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB_EXE:-$root/build/tools/emb/emb}
modes=${1:-30}
shift || true
sizes=("$@")
((${#sizes[@]})) || sizes=(0.020 0.0095 0.0058)   # ~36k, ~100k, ~300k DOF
mkdir -p "$root/out/bench"
files=()
for h in "${sizes[@]}"; do
  f="$root/out/bench/crank_h$h.json"
  "$emb" modes "$root/meshes/crankshaft_i4.geo" --size "$h" --modes "$modes" --no-output --json -q > "$f"
  files+=("$f")
done
python3 "$root/benchmarks/modes_table.py" "${files[@]}"
