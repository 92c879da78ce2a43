#!/usr/bin/env bash
# Inline-4 engine with a flexible (CMS) crankshaft: wall time per engine cycle against the
# error in nose torsion and main-bearing force, for 0/10/20/40 kept modes, against a
# many-mode, tight-tolerance reference; and an IDA tolerance sweep at 20 modes.
#   benchmarks/inline4_flex.sh [modes|tolerance|all] [T_END]
# T_END (default 0.08 s = two cycles at 3000 rpm) shortens every run for a quick check; the
# errors are taken over the second half of the run. Needs out/crankshaft_i4.h5
# (tools/setup.sh run makes it). Runs in out/bench_inline4/; the numbers go to
# benchmarks/results/inline4_flex_{modes,tolerance}.json (benchmarks/record.py).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB:-$root/build/tools/emb/emb}
what=${1:-all}
t_end=${2:-0.08}
dir=$root/out/bench_inline4
mkdir -p "$dir"
scene=$root/tools/scenes/inline4.yaml
[ -f "$root/out/crankshaft_i4.h5" ] || { echo "run tools/setup.sh run first (out/crankshaft_i4.h5)" >&2; exit 1; }

run() {  # run NAME MODES RTOL ATOL
  local name=$1 modes=$2 rtol=$3 atol=$4
  sed -e "s#modes: 20 #modes: $modes #" -e "s#body_file: ../../out/#body_file: $root/out/#" \
      -e "s#file: ../../out/inline4.h5#file: $dir/$name.h5#" -e "s#csv: ../../out/inline4.csv#csv: $dir/$name.csv#" \
      "$scene" > "$dir/$name.yaml"
  if [ "$modes" = 0 ]; then sed -i "s#    model: cms #    model: rigid#" "$dir/$name.yaml"; fi
  "$emb" run "$dir/$name.yaml" -q --json --rtol "$rtol" --atol "$atol" --t-end "$t_end" > "$dir/$name.json"
  echo "$name: $(/usr/bin/python3 -c "import json; d=json.load(open('$dir/$name.json'))['summary']; print(d['status'], d['steps'], 'steps', round(d['seconds_run'], 2), 's')")"
}
record() {  # record NAME RUN...
  local name=$1
  shift
  /usr/bin/python3 "$root/benchmarks/record.py" inline4 "$name" "$dir" "$@" \
    --command "bash benchmarks/inline4_flex.sh $what $t_end"
  /usr/bin/python3 "$root/benchmarks/render_tables.py" --print "$name"
}

if [ "$what" = modes ] || [ "$what" = all ]; then
  run ref 60 1e-7 1e-10
  for m in 0 10 20 40; do run modes$m "$m" 1e-6 1e-9; done
  record inline4_flex_modes ref modes0 modes10 modes20 modes40
fi
if [ "$what" = tolerance ] || [ "$what" = all ]; then
  [ -f "$dir/ref.json" ] || run ref 60 1e-7 1e-10
  tols=()
  for r in 1e-4 1e-5 1e-6 1e-7; do
    a=$(/usr/bin/python3 -c "print($r * 1e-3)")
    run tol$r 20 "$r" "$a"
    tols+=("tol$r")
  done
  record inline4_flex_tolerance "${tols[@]}"
fi
