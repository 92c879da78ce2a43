# Shared by benchmarks/slepc_modes.sh and slepc_reduce.sh (sourced, with H = $1 and PREFIX):
# the emb binary, the output folder, the mesh made once from the inline-4 crankshaft
# (emb mesh --save-mesh, H: mesh size [m] or "default"/empty for the .geo's own) at $msh,
# and the mpirun prefix for one thread per rank (a rank per core) as $mpi.
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB_EXE:-$root/build/tools/emb/emb}
h=${1:-}
[ "$h" = default ] && h=""
out="$root/out/bench"
mkdir -p "$out"
msh="$out/${PREFIX}_crank.msh"
size=()
[ -n "$h" ] && size=(--size "$h")
"$emb" mesh "$root/meshes/crankshaft_i4.geo" "${size[@]}" --save-mesh "$msh" -q > /dev/null
mpi=(env OMPI_MCA_plm=isolated OMPI_MCA_btl_vader_single_copy_mechanism=none
     OMPI_MCA_rmaps_base_oversubscribe=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
     EMB_NUM_THREADS=1 mpirun --allow-run-as-root)
