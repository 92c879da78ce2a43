#!/usr/bin/env bash
# Inline-4 engine with the crankshaft as `rigid`, `beam` (elastic webs, calibrated width) and
# `cms` (installed basis): the shipped scene with one word changed (issue 6's transient
# comparison), each run to its steady state like the scene.
#   benchmarks/inline4_models.sh [MODEL ...]     (default: rigid beam cms)
# Runs in out/bench_basis/model_*.{csv,json,time}, compared with the reference run `ref` of
# benchmarks/inline4_basis.sh 3000 (run it first); the numbers go to
# benchmarks/results/inline4_models.json (benchmarks/record.py engine).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB:-$root/build/tools/emb/emb}
command="bash benchmarks/inline4_models.sh $*"
models=("$@")
((${#models[@]})) || models=(rigid beam cms)
dir=$root/out/bench_basis
mkdir -p "$dir"
[ -f "$dir/ref.csv" ] || { echo "run benchmarks/inline4_basis.sh 3000 first (the reference run)" >&2; exit 1; }
names=()
for m in "${models[@]}"; do
  sed -e "s/    model: cms   /    model: $m   /" -e "s#\.\./\.\./#$root/#g" \
      -e "s#file: $root/out/inline4.h5#file: $dir/model_$m.h5#" -e "s#csv: $root/out/inline4.csv#csv: $dir/model_$m.csv#" \
      "$root/tools/scenes/inline4.yaml" > "$dir/model_$m.yaml"
  /usr/bin/time -f "%U %S %e" -o "$dir/model_$m.time" "$emb" run "$dir/model_$m.yaml" -q --json > "$dir/model_$m.json"
  echo "$m: $(/usr/bin/python3 -c "import json; d=json.load(open('$dir/model_$m.json'))['summary']; print(d['status'], d['steps'], 'steps', round(d['seconds_run'], 2), 's')")"
  names+=("model_$m")
done
/usr/bin/python3 "$root/benchmarks/record.py" engine inline4_models "$dir" 0.04 ref "${names[@]}" --command "${command% }"
/usr/bin/python3 "$root/benchmarks/render_tables.py" --print inline4_models
