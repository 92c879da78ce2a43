#!/usr/bin/env bash
# Run-up with order tracking against the steady sweep (issue 17), on the rigid single-cylinder
# engine: `emb sweep tools/scenes/engine_1cyl_rigid.yaml --rpm 1000:6000:500` (each speed to
# its steady state) and one run of tools/scenes/engine_1cyl_rigid_runup.yaml (1000 -> 6000 rpm
# in 2 s) tracked by `emb runup`; the flywheel bolt torque's orders 0.5..6 compared at the
# sweep's speeds (the run-up's windows interpolated linearly in rpm), with the CPU time of
# both routes. Run alone: flock -x /tmp/emb-cpu.lock bash benchmarks/runup_vs_sweep.sh
# Numbers: benchmarks/results/runup_vs_sweep.json (benchmarks/record.py merge).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB:-$root/build/tools/emb/emb}
dir=$root/out/bench_runup
rm -rf "$dir" && mkdir -p "$dir"
cd "$root"
channel=flywheel_bolt.T.z
orders=0.5:6:0.5
/usr/bin/time -f "%U %S %e" -o "$dir/sweep.time" "$emb" sweep tools/scenes/engine_1cyl_rigid.yaml \
  --rpm 1000:6000:500 --channels $channel --orders $orders -j 1 -q --json -o "$dir/steady.h5" \
  > "$dir/steady.json" || true
/usr/bin/time -f "%U %S %e" -o "$dir/run.time" "$emb" run tools/scenes/engine_1cyl_rigid_runup.yaml \
  -q --json -o "$dir/runup_run.h5" --csv "$dir/runup_run.csv" > "$dir/run.json"
/usr/bin/time -f "%U %S %e" -o "$dir/runup.time" "$emb" runup "$dir/runup_run.h5" \
  --angle dyno_bearing --channels $channel --orders $orders -q --json -o "$dir/runup.h5" \
  > "$dir/runup.json"
/usr/bin/python3 - "$dir" <<'PY'
import json, sys
import h5py, numpy as np
d = sys.argv[1]
def cpu(name):
    u, s, w = (float(x) for x in open(f"{d}/{name}.time").read().split()[-3:])
    return u + s, w
with h5py.File(f"{d}/steady.h5") as s, h5py.File(f"{d}/runup.h5") as r:
    orders = s["orders"][:]
    rs, As = s["rpm"][:], s["amplitude"][:, 0, :]
    status = [x.decode() if isinstance(x, bytes) else x for x in s["status"][:]]
    rr, Ar = r["rpm"][:], r["amplitude"][:, 0, :]
inside = (rs >= rr.min()) & (rs <= rr.max())
rows = []
for k, o in enumerate(orders):
    a_run = np.interp(rs[inside], rr, Ar[:, k])
    a_st = As[inside, k]
    top = a_st.max()
    diff = np.abs(a_run - a_st)
    i = int(np.argmax(diff))
    rows.append({"name": "%g" % o, "order": float(o), "steady_min": float(a_st.min()),
                 "steady_max": float(top), "max_abs_difference": float(diff.max()),
                 "max_difference_relative": float(diff.max() / top), "at_rpm": float(rs[inside][i])})
sweep_cpu, sweep_wall = cpu("sweep")
run_cpu, run_wall = cpu("run")
track_cpu, _ = cpu("runup")
json.dump({"channel": "flywheel_bolt.T.z", "steady_rpm": [float(x) for x in rs],
           "steady_status": status, "compared_rpm": [float(x) for x in rs[inside]],
           "windows": int(len(rr)), "window_rpm_min": float(rr.min()), "window_rpm_max": float(rr.max()),
           "sweep_cpu_seconds": sweep_cpu, "sweep_wall_seconds": sweep_wall,
           "runup_cpu_seconds": run_cpu + track_cpu, "runup_wall_seconds": run_wall,
           "orders": rows}, open(f"{d}/compare.json", "w"), indent=1)
print("compared at", list(rs[inside]))
PY
/usr/bin/python3 "$root/benchmarks/record.py" merge runup_vs_sweep compare="$dir/compare.json" \
  --command "flock -x /tmp/emb-cpu.lock bash benchmarks/runup_vs_sweep.sh"
/usr/bin/python3 "$root/benchmarks/render_tables.py" --print runup_vs_sweep
