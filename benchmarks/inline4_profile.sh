#!/usr/bin/env bash
# Where the time of a flexible inline-4 run goes: `perf record` (sampling, 999 Hz) of the main
# job's run, tools/scenes/inline4.yaml as shipped (installed basis, to its steady state), then
# the share per library and the heaviest functions (self time). Needs perf (Debian
# linux-perf) and out/crankshaft_i4.h5.
#   benchmarks/inline4_profile.sh
# Raw outputs out/bench_profile/{perf.data,run.json,by_library.txt,by_function.txt}; the
# numbers go to benchmarks/results/inline4_profile.json.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB:-$root/build/tools/emb/emb}
command="bash benchmarks/inline4_profile.sh $*"
dir=$root/out/bench_profile
command -v perf >/dev/null || { echo "perf is not installed (apt-get install linux-perf)" >&2; exit 1; }
[ -f "$root/out/crankshaft_i4.h5" ] || { echo "run tools/setup.sh run first (out/crankshaft_i4.h5)" >&2; exit 1; }
mkdir -p "$dir"
perf record -q -F 999 -o "$dir/perf.data" -- \
  "$emb" run "$root/tools/scenes/inline4.yaml" --no-output -q --json > "$dir/run.json"
perf report -i "$dir/perf.data" --no-children --sort dso --stdio -g none 2>/dev/null |
  grep '%' > "$dir/by_library.txt"
perf report -i "$dir/perf.data" --no-children --sort symbol --stdio -g none 2>/dev/null |
  grep "%" | sed -n 1,30p | cut -c1-150 > "$dir/by_function.txt"
/usr/bin/python3 "$root/benchmarks/record.py" profile inline4_profile "$dir" --command "${command% }"
/usr/bin/python3 "$root/benchmarks/render_tables.py" --print inline4_profile
