#!/usr/bin/env bash
# Inline-4 engine with the crankshaft as `rigid`, `beam` (elastic webs, calibrated width) and
# `cms` (20 modes): the same scene with one word changed (issue 6's transient comparison).
#   benchmarks/inline4_models.sh [T_END] [MODEL ...]     (default 0.08 s; rigid beam cms)
# Runs in out/bench_inline4/model_*.{csv,json}, compared with the reference run `ref` of
# benchmarks/inline4_flex.sh modes (run it first, with the same T_END); the numbers go to
# benchmarks/results/inline4_models.json.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB:-$root/build/tools/emb/emb}
command="bash benchmarks/inline4_models.sh $*"
t_end=${1:-0.08}
shift || true
models=("$@")
((${#models[@]})) || models=(rigid beam cms)
dir=$root/out/bench_inline4
mkdir -p "$dir"
[ -f "$dir/ref.csv" ] || { echo "run benchmarks/inline4_flex.sh modes first (the reference run)" >&2; exit 1; }
names=()
for m in "${models[@]}"; do
  sed -e "s/    model: cms   /    model: $m   /" -e "s#\.\./\.\./#$root/#g" \
      -e "s#file: $root/out/inline4.h5#file: $dir/model_$m.h5#" -e "s#csv: $root/out/inline4.csv#csv: $dir/model_$m.csv#" \
      "$root/tools/scenes/inline4.yaml" > "$dir/model_$m.yaml"
  "$emb" run "$dir/model_$m.yaml" -q --json --t-end "$t_end" > "$dir/model_$m.json"
  echo "$m: $(/usr/bin/python3 -c "import json; d=json.load(open('$dir/model_$m.json'))['summary']; print(d['status'], d['steps'], 'steps', round(d['seconds_run'], 2), 's')")"
  names+=("model_$m")
done
/usr/bin/python3 "$root/benchmarks/record.py" inline4 inline4_models "$dir" "${names[@]}" --command "${command% }"
/usr/bin/python3 "$root/benchmarks/render_tables.py" --print inline4_models
