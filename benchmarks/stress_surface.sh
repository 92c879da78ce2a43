#!/usr/bin/env bash
# The whole-surface stress field (issue 17) on the inline-4 crank (meshes/crankshaft_i4.geo,
# reduced as tools/setup.sh does: --band 2000 --band-factor 10, default fillet groups):
#   reduce: without and with --stress-surface: surface nodes and faces, the cost of the
#           surface modal stresses, the body file growth (they are stored as float32);
#           the error of that storage (below);
#   run:    the engine (tools/scenes/inline4.yaml) to its steady state with the fillet groups'
#           fields at four times, without and with the whole-surface field at the same times:
#           the cost of the surface field, the size of the .stress.h5, and where the surface's
#           largest von Mises stress is against the fillet groups'.
# float32 (how the surface modal stresses are stored): against the double route through the
# fillet groups, which hold the same rows in double — per modal entry (surface rows at the
# group nodes against the groups' rows, relative to each mode's largest entry) and on the run's
# fields (surface field at the group nodes against the group fields at the same samples,
# relative to the largest stress of those fields).
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
    out["surface_modal_mb"] = f["/stress/surface/modal"].dtype.itemsize * S.size / 1e6
    out["surface_nodes"] = int(nodes.size)
    out["face_types"] = [t.decode() for t in f["/stress/surface/face_types"][:]]
    out["faces"] = int(sum(f["/stress/surface/faces/" + t].shape[0] for t in out["face_types"]))
    out["elastic_modes"] = int(S.shape[1])
rows_err = 0.0
with h5py.File(os.path.join(d, "crank_surface.h5"), "r") as f:
    pos = {int(n): i for i, n in enumerate(nodes)}
    for g in [n.decode() for n in f["/stress/names"][:]]:
        G = f[f"/stress/{g}/modal"][:]
        idx = np.array([pos[int(n)] for n in f[f"/stress/{g}/nodes"][:]])
        rows = (6 * idx[:, None] + np.arange(6)[None, :]).reshape(-1)
        rows_err = max(rows_err, float((np.abs(S[rows] - G).max(axis=0) / np.abs(G).max(axis=0)).max()))
out["float32_entry_error"] = rows_err
with h5py.File(os.path.join(d, "run_surface.stress.h5"), "r") as f:
    surf = f["/fillets/surface/stress"][:]            # (k, s, 6)
    vm = f["/fillets/surface/von_mises"][:]
    times = f["/fillets/surface/times"][:]
    groups = [g for g in f["/fillets"] if g != "surface"]
    pos = {int(n): i for i, n in enumerate(f["/fillets/surface/nodes"][:])}
    group_vm = {g: f[f"/fillets/{g}/von_mises"][:] for g in groups}
    group_nodes = {g: f[f"/fillets/{g}/nodes"][:] for g in groups}
    diff = scale = 0.0
    for g in groups:
        gs = f[f"/fillets/{g}/stress"][:]             # (k, m, 6), same samples
        assert np.array_equal(f[f"/fillets/{g}/times"][:], times)
        idx = np.array([pos[int(n)] for n in group_nodes[g]])
        diff = max(diff, float(np.abs(surf[:, idx, :] - gs).max()))
        scale = max(scale, float(np.abs(gs).max()))
out["float32_field_error"] = diff / scale
rows = []
for k in range(surf.shape[0]):
    i = int(vm[k].argmax())
    hot = int(nodes[i])
    in_group = [g for g in groups if hot in set(group_nodes[g].tolist())]
    rows.append({"time": float(times[k]), "surface_max_von_mises_pa": float(vm[k].max()),
                 "surface_hot_node": hot, "hot_node_groups": in_group,
                 "fillets_max_von_mises_pa": float(max(v[k].max() for v in group_vm.values()))})
out["fields"] = rows
json.dump(out, open(os.path.join(d, "extras.json"), "w"), indent=1)
print(json.dumps(out, indent=1))
PY
/usr/bin/python3 "$root/benchmarks/record.py" merge stress_surface_i4 \
  --command "flock -x /tmp/emb-cpu.lock bash benchmarks/stress_surface.sh" \
  "reduce_groups=$dir/reduce_groups.json" "reduce_surface=$dir/reduce_surface.json" \
  "run_groups=$dir/run_groups.json" "run_surface=$dir/run_surface.json" \
  "extras=$dir/extras.json"
