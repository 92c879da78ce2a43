#!/usr/bin/env bash
# Inline-4 engine with the crankshaft as `rigid`, `beam` (elastic webs, calibrated width) and
# `cms` (20 modes): the same scene with one word changed (issue 6's transient comparison).
# Writes out/bench_inline4/model_{rigid,beam,cms}.{csv,json}; run benchmarks/inline4_flex.sh
# modes first for the reference run `ref`, then benchmarks/inline4_table.py prints the RMS
# differences of nose torsion and main-bearing-3 force against it, with wall times.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB:-$root/build/tools/emb/emb}
dir=$root/out/bench_inline4
mkdir -p "$dir"
for m in rigid beam cms; do
  sed -e "s/    model: cms   /    model: $m   /" -e "s#\.\./\.\./#$root/#g" \
      -e "s#file: $root/out/inline4.h5#file: $dir/model_$m.h5#" -e "s#csv: $root/out/inline4.csv#csv: $dir/model_$m.csv#" \
      "$root/tools/scenes/inline4.yaml" > "$dir/model_$m.yaml"
  "$emb" run "$dir/model_$m.yaml" -q --json > "$dir/model_$m.json"
  echo "$m: $(/usr/bin/python3 -c "import json; d=json.load(open('$dir/model_$m.json'))['summary']; print(d['status'], d['steps'], 'steps', round(d['seconds_run'], 2), 's')")"
done
/usr/bin/python3 "$root/benchmarks/inline4_table.py" "$dir"
