#!/usr/bin/env bash
# CalculiX 2.20 (*FREQUENCY, Debian calculix-ccx) and `emb modes` on the same exported mesh of
# the default inline-4 crankshaft at three sizes, 30 modes free-free: wall time and peak memory
# of each (`/usr/bin/time -v`), emb's phases, the frequencies of both, the ratio and a fitted
# cost growth t ∝ DOF^p. Each mesh is made once by emb (--save-mesh .msh), written by gmsh as
# Abaqus .inp for CalculiX (benchmarks/ccx_deck.py deck), and read back by emb from the .msh.
# Usage: bash benchmarks/ccx_vs_emb.sh [H ...]     (from the repository root, after
# tools/setup.sh build; default H = 0.012 0.008 0.0058 m). Raw outputs out/bench/ccx/;
# numbers to benchmarks/results/ccx_vs_emb.json; table in benchmarks/README.md.
# CalculiX runs as Debian ships it (OMP_NUM_THREADS unset: one thread for SPOOLES).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB_EXE:-$root/build/tools/emb/emb}
py=/usr/bin/python3
modes=30
sizes=("$@")
((${#sizes[@]})) || sizes=(0.012 0.008 0.0058)
dir="$root/out/bench/ccx"
mkdir -p "$dir"
command -v ccx >/dev/null || { echo "ccx_vs_emb.sh: CalculiX (ccx) not found: apt-get install calculix-ccx" >&2; exit 1; }
runs=()
for h in "${sizes[@]}"; do
  base="$dir/crank_h$h"
  "$emb" mesh "$root/meshes/crankshaft_i4.geo" --size "$h" --save-mesh "$base.msh" -q >/dev/null
  gmsh "$base.msh" -save -o "${base}_gmsh.inp" >/dev/null 2>&1
  "$py" "$root/benchmarks/ccx_deck.py" deck "${base}_gmsh.inp" "$base.inp" "$modes"
  (cd "$dir" && /usr/bin/time -v ccx -i "crank_h$h" > "$base.ccx.log" 2> "$base.ccx.time")
  "$py" "$root/benchmarks/ccx_deck.py" result "$base.dat" "$base.ccx.time" "$base.ccx.json"
  /usr/bin/time -v "$emb" modes "$base.msh" --modes "$modes" --no-output --json -q \
    > "$base.emb.json" 2> "$base.emb.time"
  runs+=("$h=$base.emb.json,$base.emb.time,$base.ccx.json")
done
"$py" "$root/benchmarks/record.py" ccx ccx_vs_emb --command "bash benchmarks/ccx_vs_emb.sh $*" "${runs[@]}"
"$py" "$root/benchmarks/render_tables.py" --print ccx_vs_emb
