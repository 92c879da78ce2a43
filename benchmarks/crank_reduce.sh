#!/usr/bin/env bash
# Craig–Bampton reduction benchmark of the default inline-4 crankshaft (default interfaces:
# 5 journals + 4 pins RBE3, flange + nose RBE2).
#   sizes:      time per phase and peak memory at three mesh sizes (--band 3000: the modes a
#               0–3 kHz engine run needs), certificate included;
#   modes:      frequency error of the reduced body against the full FE model (same
#               couplings, up to 6 kHz) as a function of the fixed-interface modes kept,
#               against wall time;
#   stiffening: the default mesh reduced with and without the geometric-stiffness data.
# Usage: bash benchmarks/crank_reduce.sh [sizes|modes|stiffening|all]   (from the repository
# root, after tools/setup.sh build). Raw outputs out/bench/reduce_*.json; the numbers go to
# benchmarks/results/crank_reduce_{sizes,modes,stiffening}.json (benchmarks/record.py; modes
# also draws benchmarks/reduce_error_vs_time.png) and the tables are printed.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB_EXE:-$root/build/tools/emb/emb}
what=${1:-all}
record=("/usr/bin/python3" "$root/benchmarks/record.py")
render=("/usr/bin/python3" "$root/benchmarks/render_tables.py" --print)
mkdir -p "$root/out/bench"
geo="$root/meshes/crankshaft_i4.geo"
if [[ $what == sizes || $what == all ]]; then
  runs=()
  for h in 0.020 0.0095 0.0058; do   # ~35k, ~93k, ~293k DOF
    f="$root/out/bench/reduce_h$h.json"
    "$emb" reduce "$geo" --size "$h" --band 3000 -o "$root/out/bench/reduce_h$h.h5" --json -q > "$f"
    runs+=("$h=$f")
  done
  "${record[@]}" reduce-sizes crank_reduce_sizes --command "bash benchmarks/crank_reduce.sh sizes" "${runs[@]}"
  "${render[@]}" crank_reduce_sizes
fi
if [[ $what == modes || $what == all ]]; then
  files=()
  for n in 5 10 20 40 80 160; do
    f="$root/out/bench/reduce_n$n.json"
    "$emb" reduce "$geo" --size 0.0095 --modes "$n" --check-fmax 6000 --no-static-check \
      --no-mesh-shapes -o "$root/out/bench/reduce_n$n.h5" --json -q > "$f"
    files+=("$f")
  done
  "${record[@]}" reduce-modes crank_reduce_modes --command "bash benchmarks/crank_reduce.sh modes" "${files[@]}"
  "${render[@]}" crank_reduce_modes
fi
if [[ $what == stiffening || $what == all ]]; then
  # Default mesh (h = 8 mm), --band 3000, with and without the nine stress-stiffening cases.
  "$emb" reduce "$geo" --band 3000 -o "$root/out/bench/stiff_with.h5" --json -q \
    > "$root/out/bench/stiff_with.json"
  "$emb" reduce "$geo" --band 3000 --no-geometric-stiffness -o "$root/out/bench/stiff_without.h5" \
    --json -q > "$root/out/bench/stiff_without.json"
  "${record[@]}" stiffening crank_reduce_stiffening --command "bash benchmarks/crank_reduce.sh stiffening" \
    "with=$root/out/bench/stiff_with.json" "without=$root/out/bench/stiff_without.json"
  "${render[@]}" crank_reduce_stiffening
fi
