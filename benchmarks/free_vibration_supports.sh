#!/usr/bin/env bash
# NAFEMS FV5 (deep beam: RBE3, RBE2 and point supports) and FV52 (solid plate: line and face
# supports) under mesh refinement (build/benchmarks/free_vibration_supports).
# Usage: bash benchmarks/free_vibration_supports.sh [N_MAX_BEAM N_MAX_PLATE]  (default 8 8)
# The numbers go to benchmarks/results/free_vibration_supports.json.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${EMB_BUILD_DIR:-$root/build}
command="bash benchmarks/free_vibration_supports.sh $*"
/usr/bin/python3 "$root/benchmarks/record.py" run free_vibration_supports --command "${command% }" \
  -- "$build/benchmarks/free_vibration_supports" "$@"
/usr/bin/python3 "$root/benchmarks/render_tables.py" --print free_vibration_supports_fv5
/usr/bin/python3 "$root/benchmarks/render_tables.py" --print free_vibration_supports_fv52
