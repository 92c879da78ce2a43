#!/usr/bin/env bash
# Beam vs CMS vs 3-D FE benchmark (issue 6): `emb compare` on the inline-4 crankshaft
# (free-free and installed in its journals) and the driveshaft tube at benchmark mesh sizes;
# and the elastic-web beam crankshaft against its web width (h = 20 mm).
# Usage: bash benchmarks/beam_vs_cms.sh [crank|tube|webs|all]   (from the repository root,
# after building the emb tool). Reports, CSVs and PNG plots (frequency error vs mode; error
# vs wall time) in out/bench/compare/, copied to benchmarks/compare/; the numbers go to
# benchmarks/results/beam_vs_cms_{crank,tube}.json and beam_web_width.json.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB_EXE:-$root/build/tools/emb/emb}
cd "$root"  # part paths in the reports stay relative to the repository
what=${1:-all}
dir="$root/out/bench/compare"
record=("/usr/bin/python3" "$root/benchmarks/record.py")
render=("/usr/bin/python3" "$root/benchmarks/render_tables.py" --print)
mkdir -p "$dir" "$root/benchmarks/compare"
report() {  # copy a report and its plots into benchmarks/compare/
  /usr/bin/python3 "$root/benchmarks/compare_plots.py" "$dir/$1_compare.csv"
  cp "$dir/$1_compare.md" "$dir/$1_compare_error_vs_mode.png" "$dir/$1_compare_error_vs_time.png" \
    "$root/benchmarks/compare/"
}
if [[ $what == crank || $what == all ]]; then
  runs=()
  for support in free-free installed; do
    # h = 9.5 mm: ~95k DOF Tet10 (the size of the reduction benchmark's mode study).
    "$emb" compare meshes/crankshaft_i4.geo --size 0.0095 --support "$support" \
      --modes 12 --cms 5,10,20,40 --webs rigid,elastic -q --json --report-dir "$dir" \
      > "$dir/crankshaft_i4_${support}.json"
    runs+=("crank_${support}=$dir/crankshaft_i4_${support}.json")
    report "crankshaft_i4_${support}"
  done
  "${record[@]}" compare beam_vs_cms_crank --command "bash benchmarks/beam_vs_cms.sh crank" "${runs[@]}"
fi
if [[ $what == tube || $what == all ]]; then
  # Default swept mesh: 32 x 2 x 100 Hex20, ~106k DOF.
  "$emb" compare meshes/tube.geo --modes 20 --cms 5,10,20,40 -q --json --report-dir "$dir" \
    > "$dir/tube_free-free.json"
  report tube_free-free
  "${record[@]}" compare beam_vs_cms_tube --command "bash benchmarks/beam_vs_cms.sh tube" \
    "tube_free-free=$dir/tube_free-free.json"
fi
if [[ -f $root/benchmarks/results/beam_vs_cms_crank.json && -f $root/benchmarks/results/beam_vs_cms_tube.json ]]; then
  "${render[@]}" beam_vs_cms   # the table has both parts
fi
if [[ $what == webs || $what == all ]]; then
  # The elastic-web beam crankshaft against the arm width b (consistent mass), h = 20 mm.
  runs=()
  for b in 0.065 0.13 0.17 0.20 0.26; do
    "$emb" compare meshes/crankshaft_i4.geo --size 0.02 -n 8 --cms 2 --webs elastic \
      --web-width "$b" -q --json > "$dir/webs_$b.json"
    runs+=("$b=$dir/webs_$b.json")
  done
  "${record[@]}" web-width beam_web_width --command "bash benchmarks/beam_vs_cms.sh webs" "${runs[@]}"
  "${render[@]}" beam_web_width
fi
