#!/usr/bin/env bash
# Driveline clonk (issue 13): the scene tools/scenes/driveline_clonk.yaml with its propshaft
# tube as a CMS body keeping its modes to 2 kHz (the scene's default) or 5 kHz, and as a beam
# (one word), against a tight reference (CMS to 5 kHz, rtol 1e-8): wall time per simulated
# second, events per second, and the error in the gearbox lash torque, the tube's mid-span
# radial acceleration, its 1/3-octave band levels and the radiated-noise proxy.
#   flock -x /tmp/emb-cpu.lock bash benchmarks/driveline_clonk.sh [T_END]    (default 0.8 s)
# Needs out/tube.h5 (the reduce command in the scene's header; another with TUBE=...). Runs in
# out/bench_clonk/ (BENCH_DIR=...); the numbers go to benchmarks/results/driveline_clonk.json.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB:-$root/build/tools/emb/emb}
command="bash benchmarks/driveline_clonk.sh $*"
t_end=${1:-0.8}
dir=${BENCH_DIR:-$root/out/bench_clonk}
tube=${TUBE:-$root/out/tube.h5}  # the CMS tube's body file
mkdir -p "$dir"
[ -f "$tube" ] || { echo "make $tube first (see tools/scenes/driveline_clonk.yaml)" >&2; exit 1; }
# name model fmax_hz rtol
runs=("ref cms 5000 1e-8" "cms5k cms 5000 1e-6" "cms2k cms 2000 1e-6" "cms2k_rtol1e-5 cms 2000 1e-5"
      "beam beam 2000 1e-6")
names=()
for r in "${runs[@]}"; do
  read -r name model fmax rtol <<< "$r"
  sed -e "s/    model: cms   /    model: $model   /" -e "s/    fmax_hz: 2000 /    fmax_hz: $fmax /" \
      -e "s#body_file: \.\./\.\./out/tube.h5#body_file: $tube#" \
      -e "s#\.\./\.\./#$root/#g" -e "s#file: $root/out/driveline_clonk.h5#file: $dir/$name.h5#" \
      -e "s#csv: $root/out/driveline_clonk.csv#csv: $dir/$name.csv#" \
      "$root/tools/scenes/driveline_clonk.yaml" > "$dir/$name.yaml"
  "$emb" run "$dir/$name.yaml" -q --json --t-end "$t_end" --rtol "$rtol" > "$dir/$name.json"
  /usr/bin/python3 "$root/tools/plots/clonk_plots.py" "$dir/$name.h5" --out "$dir/${name}_png" \
      --json > "$dir/${name}_metrics.json"
  echo "$name: $(/usr/bin/python3 -c "import json; d=json.load(open('$dir/$name.json'))['summary']; print(d['status'], d['steps'], 'steps', d.get('events', 0), 'events', round(d['seconds_run'], 1), 's')")"
  names+=("$name")
done
/usr/bin/python3 "$root/benchmarks/record.py" clonk driveline_clonk "$dir" "${names[@]}" --command "${command% }"
/usr/bin/python3 "$root/benchmarks/render_tables.py" --print driveline_clonk
