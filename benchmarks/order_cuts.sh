#!/usr/bin/env bash
# Order cuts of the inline-4's nose torsion over 1000:6500:250 rpm (issue 17), without and
# with the torsional vibration damper (tools/scenes/inline4.yaml, inline4_tvd.yaml: `emb sweep
# -j 2`, every speed to its steady state), and the check of the Campbell diagram against them:
# for each main order (4, 6, 8) the speed of the order cut's peak (a parabola through the
# largest amplitude and its two neighbours on the 250 rpm grid) against the speed where
# `emb campbell` predicts that order crosses the first installed torsion mode.
# `emb campbell` runs with its default linearisation (the cycle average over a revolution);
# the record also names, per order, the crossing of any class nearest the sweep's peak.
#   flock -x /tmp/emb-cpu.lock bash benchmarks/order_cuts.sh
# Needs out/crankshaft_i4.h5 (tools/setup.sh run). Runs in out/bench_order_cuts/; the numbers
# go to benchmarks/results/order_cuts_inline4.json, the PNG order cuts next to the sweeps.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
emb=${EMB:-$root/build/tools/emb/emb}
rpm=1000:6500:250
dir=$root/out/bench_order_cuts
mkdir -p "$dir"
[ -f "$root/out/crankshaft_i4.h5" ] || { echo "run tools/setup.sh run first (out/crankshaft_i4.h5)" >&2; exit 1; }
[ "${EMB_BENCH_RESUME:-0}" = 1 ] && [ -s "$dir/campbell.json" ] || \
  "$emb" campbell "$root/tools/scenes/inline4.yaml" --rpm "$rpm" --fmax 2500 -q --json > "$dir/campbell.json"
for scene in inline4 inline4_tvd; do
  # Points that do not settle make the sweep exit 3: the file and its statuses are the result.
  [ "${EMB_BENCH_RESUME:-0}" = 1 ] && [ -s "$dir/$scene.json" ] || \
    "$emb" sweep "$root/tools/scenes/$scene.yaml" --rpm "$rpm" -j 2 --json -q -o "$dir/$scene.h5" \
      > "$dir/$scene.json" || true
  /usr/bin/python3 "$root/tools/plots/sweep_plots.py" "$dir/$scene.h5" --channel nose_torsion.rz \
    --out "$dir/${scene}_png" --critical "$dir/campbell.json" --orders 4,6,8 --critical-class torsion > /dev/null
done
/usr/bin/python3 - "$dir" "$rpm" <<'PY'
import json, sys
d, rpm_list = sys.argv[1], sys.argv[2]
campbell_doc = json.load(open(f"{d}/campbell.json"))
campbell = campbell_doc["crossings"]
channel = "nose_torsion.rz"

def cuts(name):
    s = json.load(open(f"{d}/{name}.json"))
    rpm = [p["rpm"] for p in s["points"]]
    status = [p["status"] for p in s["points"]]
    return s, rpm, status

def peak(rpm, amp):
    i = max(range(len(amp)), key=lambda k: amp[k])
    if 0 < i < len(amp) - 1:  # vertex of the parabola through three equally spaced points
        a, b, c = amp[i - 1], amp[i], amp[i + 1]
        den = a - 2 * b + c
        shift = 0.5 * (a - c) / den if den != 0 else 0.0
        return rpm[i] + shift * (rpm[i + 1] - rpm[i]), amp[i]
    return rpm[i], amp[i]

out = {"rpm": rpm_list, "channel": channel, "orders": [],
       "campbell_linearisation": campbell_doc["summary"].get("linearisation", "frozen at the start angle"),
       "campbell_num_angles": campbell_doc["summary"].get("num_angles", 1),
       "campbell_max_angle_spread_pct": campbell_doc["summary"].get("max_angle_spread_pct")}
plain, rpm, status = cuts("inline4")
tvd, rpm_t, status_t = cuts("inline4_tvd")
out["points_not_converged"] = {"inline4": [r for r, s in zip(rpm, status) if s != "converged"],
                               "inline4_tvd": [r for r, s in zip(rpm_t, status_t) if s != "converged"]}
orders = [0.5 * (k + 1) for k in range(len(plain["amplitude"][0][channel]))]
for order in (4.0, 6.0, 8.0):
    k = orders.index(order)
    a = [p[channel][k] for p in plain["amplitude"]]
    at = [p[channel][k] for p in tvd["amplitude"]]
    n_peak, a_peak = peak(rpm, a)
    n_peak_t, a_peak_t = peak(rpm_t, at)
    torsion = [c for c in campbell if c["order"] == order and c["class"] == "torsion"]
    first = min(torsion, key=lambda c: c["mode_hz"]) if torsion else None
    row = {"order": order, "sweep_peak_rpm": n_peak, "sweep_peak_amplitude": a_peak,
           "sweep_peak_hz": n_peak * order / 60.0,
           "tvd_peak_rpm": n_peak_t, "tvd_peak_amplitude": a_peak_t,
           "tvd_peak_ratio": a_peak_t / a_peak,
           "campbell_rpm": first["rpm"] if first else None,
           "campbell_mode_hz": first["mode_hz"] if first else None}
    if first:
        row["campbell_minus_sweep_rpm"] = first["rpm"] - n_peak
        row["campbell_error_pct"] = 100.0 * (first["rpm"] - n_peak) / n_peak
    # Not the check (that is the first torsion line above): the crossing of this order, of any
    # class, nearest the sweep's peak, to show which installed mode the peak belongs to.
    same = [c for c in campbell if c["order"] == order]
    if same:
        near = min(same, key=lambda c: abs(c["rpm"] - n_peak))
        row.update({"nearest_rpm": near["rpm"], "nearest_mode_hz": near["mode_hz"],
                    "nearest_mode_index": near["mode_index"], "nearest_class": near["class"],
                    "nearest_error_pct": 100.0 * (near["rpm"] - n_peak) / n_peak})
    out["orders"].append(row)
json.dump(out, open(f"{d}/order_cuts_record.json", "w"), indent=1)
PY
/usr/bin/python3 "$root/benchmarks/record.py" merge order_cuts_inline4 inline4="$dir/order_cuts_record.json" \
  --command "flock -x /tmp/emb-cpu.lock bash benchmarks/order_cuts.sh"
/usr/bin/python3 "$root/benchmarks/render_tables.py" --print order_cuts_inline4
