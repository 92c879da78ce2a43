#!/usr/bin/env bash
# Work-precision of the flexible inline-4 engine (issue 12): error against the full basis of
# the body file at a tight tolerance vs wall seconds per engine cycle, for the shipped
# configuration (installed basis, 2 kHz band, rtol 1e-4) and its alternatives: other bands,
# other tolerances, the lowest N free-free modes (the former default), the rigid crank.
# Every run starts quasi-statically and runs to its own periodic steady state (the scene's
# analysis.steady_state); the steady cycles are compared (benchmarks/engine_errors.py).
#   benchmarks/inline4_basis.sh [3000|6000|load-step|ocvirk|1cyl|all]
# EMB_BENCH_RESUME=1 keeps the runs already in out/bench_basis/. Needs the main job's body file out/crankshaft_i4.h5 (tools/setup.sh run makes it). Runs in
# out/bench_basis/ one at a time; the cost is the run's CPU time (user + system: the run is
# single-threaded, so on an idle machine its wall time), recorded with the wall time. The numbers go
# to benchmarks/results/inline4_basis{,_6000,_load_step}.json (benchmarks/record.py engine).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB:-$root/build/tools/emb/emb}
what=${1:-all}
dir=$root/out/bench_basis
mkdir -p "$dir"
[ -f "$root/out/crankshaft_i4.h5" ] || { echo "run tools/setup.sh run first (out/crankshaft_i4.h5)" >&2; exit 1; }

# run SCENE NAME BASIS RTOL [STEADY_TOL] [ANALYSIS_KEY]: BASIS = installed:BAND_HZ[:RELAXATION] |
# modes:N | all | rigid; ANALYSIS_KEY: one more `analysis:` line (e.g. the integrator)
run() {
  local scene=$1 name=$2 basis=$3 rtol=$4 steady=${5:-} extra=${6:-}
  local f=$dir/$name.yaml
  if [ "${EMB_BENCH_RESUME:-0}" = 1 ] && [ -s "$dir/$name.json" ]; then echo "$name: kept"; return; fi
  sed -e "s#body_file: ../../out/#body_file: $root/out/#" -e "s#geometry: ../../meshes/#geometry: $root/meshes/#" \
      -e "s#file: ../../out/[a-z0-9_]*.h5#file: $dir/$name.h5#" -e "s#csv: ../../out/[a-z0-9_]*.csv#csv: $dir/$name.csv#" \
      "$root/tools/scenes/$scene.yaml" > "$f"
  case $basis in
    installed:*:*)
      local spec=${basis#installed:}
      sed -i "s#^\( *\)dynamic_band_hz: 2000 .*#\1dynamic_band_hz: ${spec%%:*}\n\1quasi_static_relaxation: ${spec#*:}#" "$f" ;;
    installed:*) sed -i "s#dynamic_band_hz: 2000 #dynamic_band_hz: ${basis#installed:} #" "$f" ;;
    modes:*|all|rigid)
      /usr/bin/python3 - "$f" "$basis" <<'EOF'
import re, sys
path, basis = sys.argv[1], sys.argv[2]
s = open(path).read()
keep = "    modes: %s\n" % basis[6:] if basis.startswith("modes:") else ""
s = re.sub(r"    basis: installed[^\n]*\n    dynamic_band_hz: \d+[^\n]*\n( +#[^\n]*\n)*", keep, s)
if basis == "rigid":
    s = s.replace("    model: cms ", "    model: rigid ")
open(path, "w").write(s)
EOF
      ;;
  esac
  sed -i "s#^  rtol: [0-9.e-]*#  rtol: $rtol#; s#^  atol: [0-9.e-]*#  atol: $(/usr/bin/python3 -c "print($rtol * 1e-3)")#" "$f"
  if [ -n "$extra" ]; then sed -i "s#^  type: dynamic#  type: dynamic\n  $extra#" "$f"; fi
  if [ -n "$steady" ]; then sed -i "s#^    tolerance: [0-9.e-]*#    tolerance: $steady#" "$f"; fi
  # A run that ends without its steady state (exit 3) is a result too: its row says so.
  /usr/bin/time -f "%U %S %e" -o "$dir/$name.time" "$emb" run "$f" -q --json > "$dir/$name.json" || true
  echo "$name: $(/usr/bin/python3 -c "import json; d=json.load(open('$dir/$name.json'))['summary']; print(d['status'], d.get('steady_state', ''), d['steps'], 'steps', round(d['seconds_run'], 2), 's')")"
}
record() {  # record NAME CYCLE_S REF RUN...
  local name=$1
  shift
  /usr/bin/python3 "$root/benchmarks/record.py" engine "$name" "$dir" "$@" \
    --command "bash benchmarks/inline4_basis.sh $what"
  /usr/bin/python3 "$root/benchmarks/render_tables.py" --print "$name"
}

if [ "$what" = 3000 ] || [ "$what" = all ]; then
  run inline4 default installed:2000 1e-4
  run inline4 ref all 1e-7 5e-4
  run inline4 ref_half all 5e-8 5e-4
  for b in 1000 3000 5000; do run inline4 band$b installed:$b 1e-4; done
  for r in 1e-3 1e-5; do run inline4 rtol$r installed:2000 "$r"; done
  run inline4 galpha installed:2000 1e-4 "" "integrator: generalized-alpha"
  for x in 0.01 1; do run inline4 relax$x installed:2000:$x 1e-4; done
  run inline4 newton0.33 installed:2000 1e-4 "" "newton_convergence_factor: 0.33"
  for m in 13 20 40; do run inline4 lowest$m modes:$m 1e-4; done
  run inline4 former_default modes:20 1e-6
  run inline4 rigid rigid 1e-4
  record inline4_basis 0.04 ref ref_half default band1000 band3000 band5000 rtol1e-3 rtol1e-5 galpha \
    relax0.01 relax1 newton0.33 \
    lowest13 lowest20 lowest40 former_default rigid
fi
if [ "$what" = 6000 ] || [ "$what" = all ]; then
  run inline4_6000 ref6000 all 1e-7 5e-4
  run inline4_6000 default6000 installed:2000 1e-4
  record inline4_basis_6000 0.02 ref6000 default6000
fi
if [ "$what" = ocvirk ] || [ "$what" = all ]; then
  run inline4_ocvirk ref_ocvirk all 1e-7 5e-4
  run inline4_ocvirk default_ocvirk installed:2000 1e-5
  record inline4_basis_ocvirk 0.04 ref_ocvirk default_ocvirk
fi
if [ "$what" = 1cyl ] || [ "$what" = all ]; then
  run engine_1cyl_cms ref_1cyl all 1e-7 5e-4
  run engine_1cyl_cms default_1cyl installed:2000 1e-5
  record engine_1cyl_basis 0.04 ref_1cyl default_1cyl
fi
if [ "$what" = load-step ] || [ "$what" = all ]; then
  run inline4_load_step ref_step all 1e-7
  run inline4_load_step default_step installed:2000 1e-4
  record inline4_basis_load_step 0.04 ref_step default_step
fi
