#!/usr/bin/env bash
# Stress recovery at the crank fillets (issue 17), per crank: the single-throw crankshaft
# (meshes/crankshaft_1cyl.geo, `-n 30` as tools/scenes/engine_1cyl_cms.yaml says) and the
# inline-4 (meshes/crankshaft_i4.geo, `--band 2000 --band-factor 10` as tools/setup.sh
# reduces it for tools/scenes/inline4.yaml), default meshes:
#   reduce: with the default fillet stress groups and with --no-stress: the cost of computing
#           and storing the modal stresses, the file size, and the modal-vs-full-FE static
#           check at every fillet group;
#   run:    the engine to its periodic steady state with a stress output on every fillet
#           group (hot spots, fatigue against a typical quenched-and-tempered crank steel's
#           S-N curve, stress fields at four times) and without it: the cost of recovering.
# Usage: flock -x /tmp/emb-cpu.lock bash benchmarks/stress_recovery.sh [1cyl|i4|all]   (from
# the repository root, after tools/setup.sh build). Raw outputs in out/bench/stress_<crank>/;
# the numbers go to benchmarks/results/stress_recovery_<crank>.json (benchmarks/record.py) and
# the tables are printed.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB_EXE:-$root/build/tools/emb/emb}
what=${1:-all}
record=("/usr/bin/python3" "$root/benchmarks/record.py")
render=("/usr/bin/python3" "$root/benchmarks/render_tables.py" --print)

# bench NAME GEO SCENE BODY_FILE_IN_SCENE REDUCE_OPTIONS...
bench() {
  local name=$1 geo=$2 scene_in=$3 body_in=$4
  shift 4
  local dir="$root/out/bench/stress_$name"
  mkdir -p "$dir"
  "$emb" reduce "$geo" "$@" -o "$dir/crank_stress.h5" --json -q > "$dir/reduce_with.json"
  "$emb" reduce "$geo" "$@" --no-stress -o "$dir/crank_plain.h5" --json -q > "$dir/reduce_without.json"
  # The engine scene two levels below the root like tools/scenes (its relative paths hold),
  # on the body file with stresses; with and without the stress output.
  local plain="$root/out/bench/${name}_plain.yaml" scene="$root/out/bench/${name}_stress.yaml"
  sed "s#$body_in#stress_$name/crank_stress.h5#" "$scene_in" > "$plain"
  cp "$plain" "$scene"
  cat >> "$scene" <<'YAML'
stress_outputs:
  - name: fillets                    # every fillet group of the body file
    body: crank
    field_times: [0.08, 0.09, 0.10, 0.11]
    fatigue:                         # quenched and tempered steel (42CrMo4-like), typical values
      measure: max_principal
      fatigue_strength_coefficient: 1.3e9
      exponent: -0.085
      ultimate_strength: 1.0e9
YAML
  "$emb" run "$scene" -q --json -o "$dir/run_with.h5" --csv "$dir/run_with.csv" > "$dir/run_with.json"
  "$emb" run "$plain" -q --json -o "$dir/run_without.h5" --csv "$dir/run_without.csv" \
    > "$dir/run_without.json"
  # File sizes, and the hot spots over the steady cycle from the results file.
  /usr/bin/python3 - "$dir" <<'PY'
import json, os, sys
import h5py
d = sys.argv[1]
out = {"file_mb": {n: os.path.getsize(os.path.join(d, f)) / 1e6
                   for n, f in [("with", "crank_stress.h5"), ("without", "crank_plain.h5")]}}
with h5py.File(os.path.join(d, "run_with.h5"), "r") as f:
    t = f["/time"][:]
    t0, t1 = float(f.attrs["steady_state_cycle_start"]), float(f.attrs["steady_state_cycle_end"])
    window = (t >= t0) & (t <= t1)
    names = [c.decode() for c in f["/model/output_point_channels"][:]]
    v = f["/output_points"][:]
    groups = []
    for i, c in enumerate(names):
        if c.startswith("fillets.") and c.endswith(".von_mises"):
            g = c[len("fillets."):-len(".von_mises")]
            vm = v[window, i]
            p1 = v[window, names.index(f"fillets.{g}.max_principal")]
            k = int(vm.argmax())
            groups.append({"name": g, "max_von_mises_pa": float(vm.max()),
                           "max_von_mises_node": int(v[window, i + 1][k]),
                           "max_principal_pa": float(p1.max()), "min_principal_pa": float(p1.min())})
    out["hot_spots"] = {"cycle_start": t0, "cycle_end": t1, "groups": groups}
json.dump(out, open(os.path.join(d, "extras.json"), "w"))
PY
  "${record[@]}" merge "stress_recovery_$name" \
    --command "flock -x /tmp/emb-cpu.lock bash benchmarks/stress_recovery.sh $name" \
    "reduce_with=$dir/reduce_with.json" "reduce_without=$dir/reduce_without.json" \
    "run_with=$dir/run_with.json" "run_without=$dir/run_without.json" "extras=$dir/extras.json"
  "${render[@]}" "stress_recovery_$name"
  "${render[@]}" "stress_recovery_${name}_fatigue"
}

if [[ $what == 1cyl || $what == all ]]; then
  bench 1cyl "$root/meshes/crankshaft_1cyl.geo" "$root/tools/scenes/engine_1cyl_cms.yaml" \
    "../../out/crankshaft_1cyl.h5" -n 30
fi
if [[ $what == i4 || $what == all ]]; then
  bench i4 "$root/meshes/crankshaft_i4.geo" "$root/tools/scenes/inline4.yaml" \
    "../../out/crankshaft_i4.h5" --band 2000 --band-factor 10
fi
