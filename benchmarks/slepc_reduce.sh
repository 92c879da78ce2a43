#!/usr/bin/env bash
# The distributed reduction (emb reduce --backend slepc: constraint modes by MUMPS's
# saddle-point factorisation with blocked solves, fixed-interface modes by SLEPc, over MPI)
# against the default CHOLMOD path, on the inline-4 crankshaft with its default interfaces.
# Usage (repository root, after tools/setup.sh build; timings are quoted, so alone):
#   flock -x /tmp/emb-cpu.lock bash benchmarks/slepc_reduce.sh [H] [BAND]
# H: mesh size [m] or "default" (the .geo's own mesh, the default); BAND: --band [Hz], 3000
# (the modes a 0-3 kHz engine run needs, as benchmarks/crank_reduce.sh). The mesh is made once
# (emb mesh --save-mesh) and every run and rank reads that .msh. Runs: cholmod (the default
# path, its threads on all cores), slepc on 1 and on 2 MPI ranks with one thread per rank
# (a rank per core; rank 0's certificate and the rest then run on one thread). Raw outputs
# out/bench/slepcred_*; numbers to benchmarks/results/slepc_reduce.json (record.py
# slepc-reduce, which also compares the body files); table printed (render_tables.py updates
# the docs).
set -euo pipefail
command="bash benchmarks/slepc_reduce.sh $*"
band=${2:-3000}
PREFIX=slepcred
# shellcheck source=benchmarks/slepc_common.sh
source "$(dirname "${BASH_SOURCE[0]}")/slepc_common.sh"
runs=()
run() {  # LABEL COMMAND...
  local label=$1
  shift
  /usr/bin/time -f "%e %M" -o "$out/slepcred_$label.time" "$@" \
    "$msh" --band "$band" -o "$out/slepcred_$label.h5" --no-xdmf --json -q \
    > "$out/slepcred_$label.json"
  runs+=("$label=$out/slepcred_$label.json,$out/slepcred_$label.time,$out/slepcred_$label.h5")
}
run cholmod "$emb" reduce
run slepc1 "${mpi[@]}" -n 1 "$emb" reduce --backend slepc
run slepc2 "${mpi[@]}" -n 2 "$emb" reduce --backend slepc
/usr/bin/python3 "$root/benchmarks/record.py" slepc-reduce slepc_reduce --command "${command% }" "${runs[@]}"
/usr/bin/python3 "$root/benchmarks/render_tables.py" --print slepc_reduce
