#!/usr/bin/env bash
# Beam vs CMS vs 3-D FE benchmark (issue 6): `emb compare` on the inline-4 crankshaft
# (free-free and installed in its journals) and the driveshaft tube at benchmark mesh sizes,
# Markdown/CSV reports and PNG plots (frequency error vs mode; error vs wall time).
# Usage: bash benchmarks/beam_vs_cms.sh [crank|tube|all]   (from the repository root, after
# building the emb tool). Writes out/bench/compare/*.{md,csv,png,txt}.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB_EXE:-$root/build/tools/emb/emb}
cd "$root"  # part paths in the reports stay relative to the repository
what=${1:-all}
dir="$root/out/bench/compare"
mkdir -p "$dir"
csvs=()
if [[ $what == crank || $what == all ]]; then
  for support in free-free installed; do
    # h = 9.5 mm: ~95k DOF Tet10 (the size of the reduction benchmark's mode study).
    "$emb" compare meshes/crankshaft_i4.geo --size 0.0095 --support "$support" \
      --modes 12 --cms 5,10,20,40 --webs rigid,elastic -q --report-dir "$dir" \
      > "$dir/crankshaft_i4_${support}.txt"
    csvs+=("$dir/crankshaft_i4_${support}_compare.csv")
  done
fi
if [[ $what == tube || $what == all ]]; then
  # Default swept mesh: 32 x 2 x 100 Hex20, ~106k DOF.
  "$emb" compare meshes/tube.geo --modes 20 --cms 5,10,20,40 -q --report-dir "$dir" \
    > "$dir/tube_free-free.txt"
  csvs+=("$dir/tube_free-free_compare.csv")
fi
/usr/bin/python3 "$root/benchmarks/compare_plots.py" "${csvs[@]}"
