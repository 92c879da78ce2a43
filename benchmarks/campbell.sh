#!/usr/bin/env bash
# Campbell diagram of the flexible inline-4 and the torsional vibration damper's effect on its
# nose torsion (issue 17).
#   benchmarks/campbell.sh [campbell|tvd|all] [TVD_RPM]
# campbell: `emb campbell tools/scenes/inline4.yaml --rpm 1000:6500:250` (full body-file basis,
#   108 elastic coordinates), its CPU time, the installed torsion and bending modes and their
#   crossings -> benchmarks/results/campbell_inline4.json.
# angles: the inline-4 at 3000 rpm linearised frozen at its start angle and cycle-averaged over
#   4, 8, 16, 32 angles of a revolution (emb campbell --linearise, --angles): convergence in the
#   number of angles and the spread of the frozen frequencies over them
#   -> benchmarks/results/campbell_angles.json.
# tvd: the inline-4 without and with the damper (tools/scenes/inline4_tvd.yaml) run to the
#   periodic steady state at TVD_RPM (default 3000, the scenes' speed; another speed is set the
#   way `emb campbell` sets it: the rpm motion, the initial velocities and the steady-state
#   period scaled), the nose torsion's order amplitudes from `emb spectrum --json` of the steady
#   cycle -> benchmarks/results/tvd_inline4.json (tvd_inline4_<rpm>.json at another speed).
# tvd-rubber: the inline-4 at TVD_RPM without damper and with the damper of `emb tvd-tune
#   --json` (cycle-averaged linearisation, 4e-3 kg m^2 ring) as a Kelvin-Voigt rubber (Den
#   Hartog's k, c) and as the one-arm Zener rubber tvd-tune prints (Den Hartog's loss factor,
#   and 0.2, a typical TVD rubber), all four scenes made from inline4_tvd.yaml with the damper
#   replaced (no number copied by hand): the nose torsion's order amplitudes and the IDA step
#   counts -> benchmarks/results/tvd_rubber_inline4.json.
# Needs out/crankshaft_i4.h5 (tools/setup.sh run). Quote the times only from a run under
# `flock -x /tmp/emb-cpu.lock`. EMB_BENCH_RESUME=1 keeps the emb outputs already in
# out/bench_campbell/ and only records them again.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB:-$root/build/tools/emb/emb}
what=${1:-all}
tvd_rpm=${2:-3000}
dir=$root/out/bench_campbell
mkdir -p "$dir"
[ -f "$root/out/crankshaft_i4.h5" ] || { echo "run tools/setup.sh run first (out/crankshaft_i4.h5)" >&2; exit 1; }

# scene NAME RPM [T_START]: tools/scenes/NAME.yaml with absolute paths, outputs in $dir, at
# RPM (starting at T_START s).
scene() {
  /usr/bin/python3 - "$root" "$dir" "$1" "$2" "${3:-}" <<'PY'
import sys, yaml
root, out, name, rpm, t_start = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4]), sys.argv[5]
s = yaml.safe_load(open(f"{root}/tools/scenes/{name}.yaml"))
for b in s["bodies"]:
    for key in ("body_file", "geometry"):
        if key in b:
            b[key] = b[key].replace("../../", root + "/")
(motion,) = [m for m in s["motions"] if "rpm" in m["function"]]
factor = rpm / motion["function"]["rpm"]
motion["function"]["rpm"] = rpm
for b in s["bodies"]:
    for key in ("velocity", "angular_velocity"):
        if key in b:
            b[key] = [factor * x for x in b[key]]
s["analysis"]["steady_state"]["period"] /= factor
s["analysis"]["output_step"] /= factor
tag = f"{name}_{rpm:g}"
if t_start:
    s["analysis"]["t_start"] = float(t_start)
    tag += f"_t{t_start}"
s["output"] = {"file": f"{out}/{tag}.h5", "channels": s["output"]["channels"]}
yaml.safe_dump(s, open(f"{out}/{tag}.yaml", "w"), sort_keys=False)
print(f"{out}/{tag}.yaml")
PY
}

if [ "$what" = campbell ] || [ "$what" = all ]; then
  f=$(scene inline4 3000)
  [ "${EMB_BENCH_RESUME:-0}" = 1 ] && [ -s "$dir/campbell.json" ] || /usr/bin/time -f "%U %S %e" -o "$dir/campbell.time" \
    "$emb" campbell "$f" --rpm 1000:6500:250 --fmax 2500 -q --json -o "$dir/campbell_diagram.json" \
    > "$dir/campbell.json"
  /usr/bin/python3 - "$dir" <<'PY'
import json, sys
d = sys.argv[1]
run = json.load(open(f"{d}/campbell.json"))
diagram = json.load(open(f"{d}/campbell_diagram.json"))
user, system, wall = (float(x) for x in open(f"{d}/campbell.time").read().split()[-3:])
rpm = diagram["rpm"]
def at(m, n):
    return m["hz"][rpm.index(n)]
modes = [{"name": "mode%d" % m["index"], "index": m["index"], "class": m["class"],
          "whirl": m["whirl"], "hz_1000": at(m, 1000.0), "hz_3000": at(m, 3000.0),
          "hz_6500": at(m, 6500.0), "min_mac": min(x for x in m["mac"] if x is not None),
          "torsion_3000": m["torsion"][rpm.index(3000.0)],
          "bending_3000": m["bending"][rpm.index(3000.0)]} for m in diagram["modes"]]
main = [dict(name="order%g_mode%d" % (c["order"], c["mode_index"]), **c)
        for c in run["crossings"] if c["order"] in (2, 4, 6, 8)]
json.dump({"speeds": len(rpm), "cpu_s": user + system, "wall_s": wall,
           "cpu_s_per_speed": (user + system) / len(rpm), "summary": run["summary"],
           "modes": modes, "main_order_crossings": main,
           "num_crossings": len(run["crossings"])}, open(f"{d}/campbell_record.json", "w"), indent=1)
PY
  /usr/bin/python3 "$root/benchmarks/record.py" merge campbell_inline4 inline4="$dir/campbell_record.json" \
    --command "bash benchmarks/campbell.sh campbell"
  /usr/bin/python3 "$root/benchmarks/render_tables.py" --print campbell_inline4
fi

if [ "$what" = angles ] || [ "$what" = all ]; then
  f=$(scene inline4 3000)
  "$emb" campbell "$f" --rpm 3000 --fmax 800 --linearise frozen -q --json -o "$dir/angles_frozen.json" > /dev/null
  for n in 4 8 16 32; do
    "$emb" campbell "$f" --rpm 3000 --fmax 800 --angles $n -q --json -o "$dir/angles_$n.json" > /dev/null
  done
  /usr/bin/python3 - "$dir" <<'PY'
import json, sys
d = sys.argv[1]
rows = []
for name, n in (("frozen", 1), ("n4", 4), ("n8", 8), ("n16", 16), ("n32", 32)):
    g = json.load(open(f"{d}/angles_{'frozen' if n == 1 else n}.json"))
    modes = [{"class": m["class"], "hz": m["hz"][0], "decay": m["decay"][0],
              "hz_angle_min": m["hz_angle_min"][0], "hz_angle_max": m["hz_angle_max"][0]}
             for m in g["modes"]]
    tors = [m for m in modes if m["class"] == "torsion"]
    rows.append({"name": name, "linearisation": g["linearisation"], "num_angles": n,
                 "modes": modes, "torsion_hz": [m["hz"] for m in tors],
                 "torsion_angle_min_hz": [m["hz_angle_min"] for m in tors],
                 "torsion_angle_max_hz": [m["hz_angle_max"] for m in tors],
                 "min_decay": min(m["decay"] for m in modes)})
# Convergence: the change of every tracked frequency when the angles double.
for a, b in zip(rows[1:], rows[2:]):
    b["max_change_pct_vs_half"] = max(abs(y["hz"] / x["hz"] - 1) * 100
                                      for x, y in zip(a["modes"], b["modes"]))
json.dump({"rpm": 3000.0, "fmax_hz": 800.0, "angles": rows}, open(f"{d}/angles_record.json", "w"), indent=1)
PY
  /usr/bin/python3 "$root/benchmarks/record.py" merge campbell_angles inline4="$dir/angles_record.json" \
    --command "bash benchmarks/campbell.sh angles"
  /usr/bin/python3 "$root/benchmarks/render_tables.py" --print campbell_angles
fi

if [ "$what" = tvd-rubber ] || [ "$what" = all ]; then
  "$emb" tvd-tune -q "$root/tools/scenes/inline4.yaml" --rpm "$tvd_rpm" --hub crank_nose \
    --ring-inertia 0.004 --json > "$dir/tvd_tune_$tvd_rpm.json"
  "$emb" tvd-tune -q "$root/tools/scenes/inline4.yaml" --rpm "$tvd_rpm" --hub crank_nose \
    --ring-inertia 0.004 --loss-factor 0.2 --json > "$dir/tvd_tune_${tvd_rpm}_eta02.json"
  base=$(scene inline4_tvd "$tvd_rpm")
  names="none kelvin_voigt zener zener_eta02"
  /usr/bin/python3 - "$base" "$dir" "$tvd_rpm" $names <<'PY'
import json, sys, yaml
base, d, rpm, names = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
tune = json.load(open(f"{d}/tvd_tune_{rpm}.json"))
tune02 = json.load(open(f"{d}/tvd_tune_{rpm}_eta02.json"))
def zener(t):
    z = t["zener"]
    return {"rubber": {"static_stiffness": z["static_stiffness"],
                       "arms": [{"stiffness": z["arm_stiffness"],
                                 "relaxation_time": z["relaxation_time"]}]}}
damper = {"kelvin_voigt": {"stiffness": tune["summary"]["stiffness"],
                           "damping": tune["summary"]["damping"]},
          "zener": zener(tune), "zener_eta02": zener(tune02)}
for n in names:
    s = yaml.safe_load(open(base))
    (i,) = [k for k, f in enumerate(s["forces"]) if f.get("type") == "torsional-damper"]
    if n == "none":
        del s["forces"][i]
    else:
        f = {k: v for k, v in s["forces"][i].items() if k not in ("stiffness", "damping")}
        f.update(damper[n])
        s["forces"][i] = f
    s["output"]["file"] = f"{d}/tvd_rubber_{n}_{rpm}.h5"
    yaml.safe_dump(s, open(f"{d}/tvd_rubber_{n}_{rpm}.yaml", "w"), sort_keys=False)
PY
  for n in $names; do
    tag=tvd_rubber_${n}_$tvd_rpm
    if [ "${EMB_BENCH_RESUME:-0}" = 1 ] && [ -s "$dir/$tag.spectrum.json" ]; then continue; fi
    /usr/bin/time -f "%U %S %e" -o "$dir/$tag.time" "$emb" run "$dir/$tag.yaml" -q --json > "$dir/$tag.run.json" || true
    "$emb" spectrum "$dir/$tag.h5" --channel nose_torsion.rz --angle crank --orders 12 --json \
      > "$dir/$tag.spectrum.json"
  done
  /usr/bin/python3 - "$dir" "$tvd_rpm" $names <<'PY'
import json, re, sys
d, rpm, names = sys.argv[1], sys.argv[2], sys.argv[3:]
rows = {}
for n in names:
    sp = json.load(open(f"{d}/tvd_rubber_{n}_{rpm}.spectrum.json"))
    run = json.load(open(f"{d}/tvd_rubber_{n}_{rpm}.run.json"))["summary"]
    rows[n] = {"orders": {("%g" % o["order"]): o["amplitude"] for o in sp["orders"]},
               "status": run["status"], "steady_state": run.get("steady_state", ""),
               "steps": run["steps"], "residual_evals": run.get("residual_evals"),
               "cpu_s": sum(float(x) for x in open(f"{d}/tvd_rubber_{n}_{rpm}.time").read().split()[:2])}
    m = re.search(r"after (\d+) cycles", rows[n]["steady_state"])
    rows[n]["cycles"] = int(m.group(1)) if m else None
    rows[n]["steps_per_cycle"] = rows[n]["steps"] / rows[n]["cycles"] if m else None
tune = {k: json.load(open(f"{d}/tvd_tune_{rpm}{s}.json")) for k, s in (("zener", ""), ("zener_eta02", "_eta02"))}
base = rows["none"]["orders"]
orders = []
for k in base:
    if not (float(k) > 0 and float(k) == int(float(k))):
        continue
    o = {"name": "order" + k, "order": float(k), "none_rad": base[k]}
    for n in names[1:]:
        o[n + "_rad"] = rows[n]["orders"][k]
        o[n + "_ratio"] = rows[n]["orders"][k] / base[k] if base[k] > 0 else None
    orders.append(o)
json.dump({"rpm": float(rpm), "runs": rows, "orders": orders,
           "tuning": {k: {"summary": t["summary"], "zener": t["zener"]} for k, t in tune.items()},
           "zener_steps_vs_kelvin_voigt": rows["zener"]["steps"] / rows["kelvin_voigt"]["steps"],
           "zener_steps_per_cycle_vs_kelvin_voigt":
               rows["zener"]["steps_per_cycle"] / rows["kelvin_voigt"]["steps_per_cycle"]},
          open(f"{d}/tvd_rubber_record.json", "w"), indent=1)
PY
  /usr/bin/python3 "$root/benchmarks/record.py" merge tvd_rubber_inline4 "rpm$tvd_rpm=$dir/tvd_rubber_record.json" \
    --command "bash benchmarks/campbell.sh tvd-rubber $tvd_rpm"
  /usr/bin/python3 "$root/benchmarks/render_tables.py" --print tvd_rubber_inline4
fi

if [ "$what" = tvd ] || [ "$what" = all ]; then
  for name in inline4 inline4_tvd; do
    f=$(scene $name "$tvd_rpm")
    tag=${name}_$tvd_rpm
    if [ "${EMB_BENCH_RESUME:-0}" = 1 ] && [ -s "$dir/$tag.spectrum.json" ]; then continue; fi
    /usr/bin/time -f "%U %S %e" -o "$dir/$tag.time" "$emb" run "$f" -q --json > "$dir/$tag.run.json" || true
    "$emb" spectrum "$dir/$tag.h5" --channel nose_torsion.rz --angle crank --orders 12 --json \
      > "$dir/$tag.spectrum.json"
  done
  /usr/bin/python3 - "$dir" "$tvd_rpm" <<'PY'
import json, sys
d, rpm = sys.argv[1], sys.argv[2]
rows = {}
for name in ("inline4", "inline4_tvd"):
    sp = json.load(open(f"{d}/{name}_{rpm}.spectrum.json"))
    run = json.load(open(f"{d}/{name}_{rpm}.run.json"))["summary"]
    rows[name] = {"orders": {("%g" % o["order"]): o["amplitude"] for o in sp["orders"]},
                  "status": run["status"], "steady_state": run.get("steady_state", ""),
                  "steps": run["steps"]}
base, tvd = rows["inline4"]["orders"], rows["inline4_tvd"]["orders"]
orders = [{"name": "order" + k, "order": float(k), "without_rad": base[k], "with_rad": tvd[k],
           "ratio": tvd[k] / base[k] if base[k] > 0 else None}
          for k in base if float(k) > 0 and float(k) == int(float(k))]
json.dump({"rpm": float(rpm), "runs": rows, "orders": orders},
          open(f"{d}/tvd_record.json", "w"), indent=1)
PY
  record=tvd_inline4
  [ "$tvd_rpm" = 3000 ] || record=tvd_inline4_$tvd_rpm
  /usr/bin/python3 "$root/benchmarks/record.py" merge $record "rpm$tvd_rpm=$dir/tvd_record.json" \
    --command "bash benchmarks/campbell.sh tvd $tvd_rpm"
  /usr/bin/python3 "$root/benchmarks/render_tables.py" --print $record
fi
