#!/usr/bin/env bash
# Driveline clonk (issue 13): the scene tools/scenes/driveline_clonk.yaml with its propshaft
# tube as a CMS body on its installed basis with a 5 kHz band (the scene's default) or 2 kHz,
# on all its free-free modes or subsets to 5 kHz or 2 kHz, and as a beam (one word), against
# a tight reference (the scene's default model at rtol 1e-8): wall time per simulated second,
# events per second, and the error in the gearbox lash torque, the tube's mid-span radial
# acceleration, its 1/3-octave band levels and the radiated-noise proxy.
#   flock -x /tmp/emb-cpu.lock bash benchmarks/driveline_clonk.sh [T_END]    (default 0.8 s)
# Needs out/tube.h5 (the reduce command in the scene's header; another with TUBE=...). Runs in
# out/bench_clonk/ (BENCH_DIR=...); the numbers go to benchmarks/results/driveline_clonk.json.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB:-$root/build/tools/emb/emb}
command="bash benchmarks/driveline_clonk.sh $*"
t_end=${1:-0.8}
dir=${BENCH_DIR:-$root/out/bench_clonk}
tube_file=${TUBE:-$root/out/tube.h5}  # the CMS tube's body file
mkdir -p "$dir"
[ -f "$tube_file" ] || { echo "make $tube_file first (see tools/scenes/driveline_clonk.yaml)" >&2; exit 1; }
# name model basis band rtol: basis installed (band = dynamic_band_hz), free-free (band =
# fmax_hz, "all": every coordinate of the body file) or - (beam)
runs=("ref cms installed 5000 1e-8" "inst5k cms installed 5000 1e-6" "inst2k cms installed 2000 1e-6"
      "full cms free-free all 1e-6" "ff5k cms free-free 5000 1e-6" "ff2k cms free-free 2000 1e-6"
      "beam beam - - 1e-6")
names=()
for r in "${runs[@]}"; do
  read -r name model basis band rtol <<< "$r"
  case "$basis" in
    installed) tube=(-e "s/    dynamic_band_hz: [0-9]* /    dynamic_band_hz: $band /") ;;
    free-free) if [ "$band" = all ]; then band_line="s/    dynamic_band_hz: [0-9]* .*//"
               else band_line="s/    dynamic_band_hz: [0-9]* /    fmax_hz: $band /"; fi
               tube=(-e "s/    basis: installed /    basis: free-free /" -e "$band_line") ;;
    *) tube=() ;;
  esac
  sed -e "s/    model: cms   /    model: $model   /" "${tube[@]}" \
      -e "s#body_file: \.\./\.\./out/tube.h5#body_file: $tube_file#" \
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
