#!/usr/bin/env bash
# The distributed eigen-solve backend (emb modes --backend slepc: SLEPc Krylov-Schur with MUMPS
# shift-invert over MPI) against the default CHOLMOD path, on the inline-4 crankshaft.
# Usage (repository root, after tools/setup.sh build; timings are quoted, so alone):
#   flock -x /tmp/emb-cpu.lock bash benchmarks/slepc_modes.sh [H] [MODES]
# H: mesh size [m] or "default" (the .geo's own mesh, the default); MODES: 20. The mesh is made once
# (emb mesh --save-mesh) and every run and rank reads that .msh. Runs: cholmod (the default
# path, its own threads on all cores), slepc on 1 and on 2 MPI ranks with one thread per rank
# (OMP_NUM_THREADS=OPENBLAS_NUM_THREADS=1: a rank per core). Raw outputs out/bench/slepc_*;
# numbers to benchmarks/results/slepc_modes.json (benchmarks/record.py); table printed
# (benchmarks/render_tables.py updates the docs).
set -euo pipefail
command="bash benchmarks/slepc_modes.sh $*"
modes=${2:-20}
PREFIX=slepc
# shellcheck source=benchmarks/slepc_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/slepc_common.sh"
runs=()
run() {  # LABEL COMMAND...
  local label=$1
  shift
  /usr/bin/time -f "%e" -o "$out/slepc_$label.time" "$@" \
    "$msh" --modes "$modes" --no-output --json -q > "$out/slepc_$label.json"
  runs+=("$label=$out/slepc_$label.json,$out/slepc_$label.time")
}
run cholmod "$emb" modes
run slepc1 "${mpi[@]}" -n 1 "$emb" modes --backend slepc
run slepc2 "${mpi[@]}" -n 2 "$emb" modes --backend slepc
/usr/bin/python3 "$root/benchmarks/record.py" slepc slepc_modes --command "${command% }" "${runs[@]}"
/usr/bin/python3 "$root/benchmarks/render_tables.py" --print slepc_modes
