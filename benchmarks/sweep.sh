#!/usr/bin/env bash
# Cost of a speed sweep (issue 17): the flexible inline-4 (tools/scenes/inline4.yaml,
# installed basis) over 23 speeds 1000:6500:250 rpm, each run to its periodic steady state,
# with -j 1 and -j 2 (operating points as parallel processes: the scaling on this machine).
#   benchmarks/sweep.sh [RPM_LIST]     (default 1000:6500:250; a subset, e.g. 1000:6500:750,
#                                       is recorded with its list so the table says so)
# Needs out/crankshaft_i4.h5 (tools/setup.sh run). Every run starts with an empty point
# directory (no resume). Run the whole script under the exclusive CPU lock, nothing else on the
# machine: flock -x /tmp/emb-cpu.lock benchmarks/sweep.sh
# The numbers (wall time from /usr/bin/time, CPU time per point from the sweep file, cycles to
# settle, statuses) go to benchmarks/results/sweep_inline4.json (benchmarks/record.py merge).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB:-$root/build/tools/emb/emb}
rpm=${1:-1000:6500:250}
dir=$root/out/bench_sweep
mkdir -p "$dir"
[ -f "$root/out/crankshaft_i4.h5" ] || { echo "run tools/setup.sh run first (out/crankshaft_i4.h5)" >&2; exit 1; }

for j in 1 2; do
  rm -rf "$dir/j$j.h5" "$dir/j$j.h5.points"
  # A sweep with points that did not settle exits 3: its file and table are a result too.
  /usr/bin/time -f "%U %S %e" -o "$dir/j$j.time" \
    "$emb" sweep "$root/tools/scenes/inline4.yaml" --rpm "$rpm" -j "$j" --json -q \
    -o "$dir/j$j.h5" > "$dir/j$j.sweep.json" || true
  /usr/bin/python3 - "$dir/j$j" "$j" "$rpm" <<'PY'
import json, sys
base, jobs, rpm = sys.argv[1], int(sys.argv[2]), sys.argv[3]
user, system, wall = (float(x) for x in open(base + ".time").read().split()[-3:])
d = json.load(open(base + ".sweep.json"))
points = d["points"]
json.dump({"jobs": jobs, "rpm": rpm, "wall_seconds": wall, "user_seconds": user,
           "system_seconds": system, "points": len(points),
           "converged": sum(p["status"] == "converged" for p in points),
           "not_converged": sum(p["status"] == "not-converged" for p in points),
           "failed": sum(p["status"] == "failed" for p in points),
           "point_cpu_seconds": sum(p["cpu_seconds"] for p in points),
           "cycles": sum(p["cycles"] for p in points),
           "max_cycles": max(p["cycles"] for p in points),
           "per_point": [{"rpm": p["rpm"], "status": p["status"], "cycles": p["cycles"],
                          "cpu_seconds": p["cpu_seconds"]} for p in points]},
          open(base + ".json", "w"), indent=1)
print("-j %d: %d points in %.1f s wall" % (jobs, len(points), wall))
PY
done
/usr/bin/python3 "$root/benchmarks/record.py" merge sweep_inline4 j1="$dir/j1.json" j2="$dir/j2.json" \
  --command "flock -x /tmp/emb-cpu.lock bash benchmarks/sweep.sh $rpm"
/usr/bin/python3 "$root/benchmarks/render_tables.py" --print sweep_inline4
