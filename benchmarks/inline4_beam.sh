#!/usr/bin/env bash
# The inline-4's beam crank (`model: beam`, elastic webs of the calibrated width): the
# condensed beam part (the default, `beam_nodes: condensed`: massless beams between the
# lumped webs, journals, pins, nose and flange, libemb/beam/beam_condensation.h) against the
# plain lumped beam FE model (`beam_nodes: all`: every beam node a body), issue 12.
#   benchmarks/inline4_beam.sh [T_PLAIN [T_CONDENSED]]   (default 0.015 s and 0.08 s)
# Runs (RUNS="..." to run only some and reuse the others' outputs; every run with outputs in
# the directory is recorded):
#   all_r7        every node, rtol 1e-7, to T_PLAIN: the reference
#   condensed_r6  condensed, rtol 1e-6, to T_CONDENSED (two cycles at 3000 rpm): the default
#   condensed_r8  condensed, rtol 1e-8, to T_CONDENSED: the condensed model converged in time
#   all_r6        (only if named in RUNS) every node, the scene's rtol 1e-6, to T_PLAIN
# The plain model is compared over its first T_PLAIN = 0.015 s (270 degrees: the firing of
# cylinders 1 and 3) only: beyond that it takes steps of a microsecond and less (hours per
# cycle at rtol 1e-7).
# Scenes: tools/scenes/inline4.yaml with the crank switched to `model: beam`, `beam_nodes:`
# and the five main bearings' forces as output channels, in out/bench_inline4_beam/. The
# numbers (RMS errors of the nose torsion, of each main bearing's |F| and big end 1's over the
# reference's span; wall time per cycle) go to benchmarks/results/inline4_beam.json.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB:-$root/build/tools/emb/emb}
command="bash benchmarks/inline4_beam.sh $*"
t_plain=${1:-0.015}
t_condensed=${2:-0.08}
dir=$root/out/bench_inline4_beam
mkdir -p "$dir"
channels="[nose_torsion.rz"
for k in 1 2 3 4 5; do channels+=", main_bearing$k.F.x, main_bearing$k.F.y"; done
channels+=", big_end1.F.x, big_end1.F.y, crank_speed.T.z]"
for nodes in all condensed; do
  sed -e "s/    model: cms   /    model: beam  /" -e "s#\.\./\.\./#$root/#g" \
      -e "s#^    webs: elastic #    beam_nodes: $nodes\n    webs: elastic #" \
      -e "s#  channels: \[.*\]#  channels: $channels#" \
      "$root/tools/scenes/inline4.yaml" > "$dir/$nodes.yaml"
  grep -q "beam_nodes: $nodes" "$dir/$nodes.yaml" || { echo "inline4.yaml changed: no webs: line" >&2; exit 1; }
done
runs=${RUNS:-all_r7 condensed_r6 condensed_r8}
for run in $runs; do
  nodes=${run%_r*}
  rtol=1e-${run##*_r}
  t_end=$t_plain
  [ "$nodes" = condensed ] && t_end=$t_condensed
  "$emb" run "$dir/$nodes.yaml" -q --json --t-end "$t_end" --rtol "$rtol" \
      -o "$dir/$run.h5" --csv "$dir/$run.csv" > "$dir/$run.json"
  echo "$run: $(/usr/bin/python3 -c "import json; d=json.load(open('$dir/$run.json'))['summary']; print(d['status'], d['steps'], 'steps', round(d['seconds_run'], 2), 's')")"
done
recorded=()
for run in all_r7 all_r6 condensed_r6 condensed_r8; do
  [ -s "$dir/$run.json" ] && recorded+=("$run")
done
/usr/bin/python3 "$root/benchmarks/record.py" inline4-beam inline4_beam "$dir" all_r7 \
    "${recorded[@]}" --command "${command% }"
/usr/bin/python3 "$root/benchmarks/render_tables.py" --print inline4_beam
