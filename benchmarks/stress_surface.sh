#!/usr/bin/env bash
# The whole-surface stress field (issue 17) on the inline-4 crank (meshes/crankshaft_i4.geo,
# reduced as tools/setup.sh does: --band 2000 --band-factor 10, default fillet groups):
#   reduce: without and with --stress-surface: surface nodes and faces, the cost of the
#           surface modal stresses, the body file growth; the error float32 storage of the
#           surface modal stresses would introduce (measured on the run's fields, below);
#   run:    the engine (tools/scenes/inline4.yaml) to its steady state with the fillet groups'
#           fields at four times, without and with the whole-surface field at the same times:
#           the cost of the surface field, the size of the .stress.h5, and where the surface's
#           largest von Mises stress is against the fillet groups'.
# float32: for each surface field sigma (k, s, 6) the elastic coordinates xi that produce it
# are recovered by least squares from the stored Sigma (6 s x ne; the residual says the field
# is in Sigma's range), then max |fl32(Sigma) xi - Sigma xi| / max |sigma| is the error.
# Usage: flock -x /tmp/emb-cpu.lock bash benchmarks/stress_surface.sh   (from the repository
# root, after tools/setup.sh build). Raw outputs in out/bench/stress_surface/; the numbers go
# to benchmarks/results/stress_surface_i4.json (benchmarks/record.py).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB_EXE:-$root/build/tools/emb/emb}
dir="$root/out/bench/stress_surface"
mkdir -p "$dir"
geo="$root/meshes/crankshaft_i4.geo"
"$emb" reduce "$geo" --band 2000 --band-factor 10 -o "$dir/crank_groups.h5" --json -q \
  > "$dir/reduce_groups.json"
"$emb" reduce "$geo" --band 2000 --band-factor 10 --stress-surface -o "$dir/crank_surface.h5" \
  --json -q > "$dir/reduce_surface.json"
# The engine scene two levels below the root like tools/scenes (its relative paths hold).
for kind in groups surface; do
  scene="$root/out/bench/stress_surface_$kind.yaml"
  sed "s#../../out/crankshaft_i4.h5#stress_surface/crank_surface.h5#" \
    "$root/tools/scenes/inline4.yaml" > "$scene"
  cat >> "$scene" <<'YAML'
stress_outputs:
  - name: fillets                    # every fillet group of the body file
    body: crank
    field_times: [0.08, 0.09, 0.10, 0.11]
YAML
  if [[ $kind == surface ]]; then
    echo "    surface_field_times: [0.08, 0.09, 0.10, 0.11]" >> "$scene"
  fi
  "$emb" run "$scene" -q --json -o "$dir/run_$kind.h5" > "$dir/run_$kind.json"
done
/usr/bin/python3 - "$dir" <<'PY'
import json, os, sys
import h5py
import numpy as np
d = sys.argv[1]
mb = lambda f: os.path.getsize(os.path.join(d, f)) / 1e6
out = {"file_mb": {"groups": mb("crank_groups.h5"), "surface": mb("crank_surface.h5"),
                   "fields_groups": mb("run_groups.stress.h5"),
                   "fields_surface": mb("run_surface.stress.h5")}}
with h5py.File(os.path.join(d, "crank_surface.h5"), "r") as f:
    S = f["/stress/surface/modal"][:]
    nodes = f["/stress/surface/nodes"][:]
    out["surface_modal_mb"] = S.nbytes / 1e6
    out["surface_nodes"] = int(nodes.size)
    out["face_types"] = [t.decode() for t in f["/stress/surface/face_types"][:]]
    out["faces"] = int(sum(f["/stress/surface/faces/" + t].shape[0] for t in out["face_types"]))
    out["elastic_modes"] = int(S.shape[1])
S32 = S.astype(np.float32).astype(np.float64)
col = np.abs(S).max(axis=0)
out["float32_entry_error"] = float((np.abs(S32 - S).max(axis=0) / col).max())
with h5py.File(os.path.join(d, "run_surface.stress.h5"), "r") as f:
    sig = f["/fillets/surface/stress"][:]            # (k, s, 6)
    vm = f["/fillets/surface/von_mises"][:]
    times = f["/fillets/surface/times"][:]
    groups = [g for g in f["/fillets"] if g != "surface"]
    group_vm = {g: f[f"/fillets/{g}/von_mises"][:] for g in groups}
    group_nodes = {g: f[f"/fillets/{g}/nodes"][:] for g in groups}
rows = []
for k in range(sig.shape[0]):
    s = sig[k].reshape(-1)                          # row 6 i + c, as Sigma
    xi, *_ = np.linalg.lstsq(S, s, rcond=None)
    scale = np.abs(s).max()
    residual = np.abs(S @ xi - s).max() / scale
    err32 = np.abs(S32 @ xi - S @ xi).max() / scale
    i = int(vm[k].argmax())
    hot = int(nodes[i])
    in_group = [g for g in groups if hot in set(group_nodes[g].tolist())]
    rows.append({"time": float(times[k]), "surface_max_von_mises_pa": float(vm[k].max()),
                 "surface_hot_node": hot, "hot_node_groups": in_group,
                 "fillets_max_von_mises_pa": float(max(v[k].max() for v in group_vm.values())),
                 "lstsq_residual": float(residual), "float32_field_error": float(err32)})
out["fields"] = rows
out["float32_field_error"] = max(r["float32_field_error"] for r in rows)
out["lstsq_residual"] = max(r["lstsq_residual"] for r in rows)
json.dump(out, open(os.path.join(d, "extras.json"), "w"), indent=1)
print(json.dumps(out, indent=1))
PY
/usr/bin/python3 "$root/benchmarks/record.py" merge stress_surface_i4 \
  --command "flock -x /tmp/emb-cpu.lock bash benchmarks/stress_surface.sh" \
  "reduce_groups=$dir/reduce_groups.json" "reduce_surface=$dir/reduce_surface.json" \
  "run_groups=$dir/run_groups.json" "run_surface=$dir/run_surface.json" \
  "extras=$dir/extras.json"
