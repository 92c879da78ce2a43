#!/usr/bin/python3
"""Renders the benchmark tables of the documentation from benchmarks/results/*.json.

The documents (benchmarks/README.md, README.md and the pages of docs/, symbolic links left
out) mark what is generated:
    <!-- table:NAME -->  ...  <!-- /table:NAME -->        a table below (TABLES), with a
                                                          line naming its results file,
                                                          commit, date and machine
    <!-- value:FILE/PATH|FORMAT -->42.0<!-- /value -->  one number in running text: the
        field PATH of benchmarks/results/FILE.json's "data" ('/'-separated: dict keys, list
        indices (negative from the end) or, in a list of objects, the one whose name, route
        or label is the segment; a last segment @min, @max, @maxabs or @count reduces a
        list, nulls left out), printed with the Python format spec FORMAT (default 'g')
Usage (stdlib only; run with /usr/bin/python3 from anywhere):
    render_tables.py            rewrite the marked parts of the documents in place
    render_tables.py --check    exit 1 (listing them) if a marked part differs from its
                                rendering, a marker names an unknown table or value, or a
                                results file is missing; the ctest benchmarks_render_tables_test
    render_tables.py --print NAME   print one table (the benchmark scripts do)
    --root DIR                  the repository root (default: this file's)
"""
import argparse
import json
import math
import os
import re
import sys

def documents(root):
    """The documents that may hold markers, relative to the repository root."""
    docs = ["benchmarks/README.md", "README.md"]
    for d, _, files in sorted(os.walk(os.path.join(root, "docs"))):
        for f in sorted(files):
            path = os.path.join(d, f)
            if f.endswith(".md") and not os.path.islink(path):
                docs.append(os.path.relpath(path, root))
    return docs
TABLE_RE = re.compile(r"(<!-- table:([\w-]+) -->\n)(.*?)(<!-- /table:\2 -->)", re.S)
VALUE_RE = re.compile(r"(<!-- value:([^|>]+?)(?:\|([^>]*?))? -->)(.*?)(<!-- /value -->)", re.S)


class RenderError(Exception):
    pass


class Results:
    """Loads benchmarks/results/NAME.json on first use."""

    def __init__(self, root):
        self.dir = os.path.join(root, "benchmarks", "results")
        self.cache = {}

    def __call__(self, name):
        if name not in self.cache:
            path = os.path.join(self.dir, name + ".json")
            if not os.path.exists(path):
                raise RenderError(f"benchmarks/results/{name}.json does not exist (run its benchmark)")
            with open(path) as f:
                self.cache[name] = json.load(f)
        return self.cache[name]


# --------------------------------------------------------------------------- formatting
def num(x, spec="g"):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "–"
    return format(x, spec)


def sig3(x):
    """Three significant digits without an exponent: 1.64, 37.3, 408, 1130."""
    if x is None:
        return "–"
    if abs(x) >= 1000:
        return f"{x:.0f}"
    return format(x, "#.3g").rstrip(".")


def thousands(n):
    return f"{n:,}".replace(",", " ")


def table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return out


def source(doc, name):
    m = doc["machine"]
    line = (f"Source: `benchmarks/results/{name}.json` — commit {doc['commit'][:7]}"
            f"{' (with uncommitted changes)' if doc['dirty'] else ''}, {doc['date'][:10]}, "
            f"{m['cpu']}, {m['cores']} cores, {m['memory_gb']:g} GB; `{doc['command']}`")
    if doc.get("note"):
        line += f"; {doc['note']}"
    return line + "."


REDUCERS = {"@min": min, "@max": max, "@maxabs": lambda xs: max(abs(x) for x in xs),
            "@count": len}


def find(data, path):
    node = data
    for seg in path:
        if seg in REDUCERS:
            if not isinstance(node, list):
                raise RenderError(f"'{seg}' of a non-list")
            values = [x for x in node if x is not None]
            if not values and seg != "@count":
                raise RenderError(f"'{seg}' of an empty list")
            node = REDUCERS[seg](values)
        elif isinstance(node, dict):
            if seg not in node:
                raise RenderError(f"no key '{seg}'")
            node = node[seg]
        elif isinstance(node, list):
            if re.fullmatch(r"-?\d+", seg):
                node = node[int(seg)]
            else:
                match = [x for x in node if isinstance(x, dict) and
                         seg in (x.get("name"), x.get("route"), x.get("label"))]
                if not match:
                    raise RenderError(f"no element named '{seg}'")
                node = match[0]
        else:
            raise RenderError(f"'{seg}' below a number")
    return node


# --------------------------------------------------------------------------- tables
def crank_modes(res, name="crank_modes"):
    doc = res(name)
    rows = []
    for r in doc["data"]["runs"]:
        s = r["seconds"]
        rows.append([r["dofs"], f"{r['nnz_factor'] / 1e6:.1f}M", num(s["mesh"], ".1f"),
                     num(s["assembly"], ".2f"), num(s["factorisation"], ".2f"),
                     num(s["eigen-solve"], ".2f"), num(s["checks"], ".2f"), num(s["total"], ".1f"),
                     num(s["eigen-solve"] / factorisation_cost(r), ".2f"), r["solves"],
                     num(r["peak_memory_mb"], ".0f"), num(r["elastic_hz"][0], ".2f"),
                     num(r["max_change_vs_finest"], ".2e"), r["status"], r["rigid_modes"],
                     num(r["max_backward_error"], ".1e")])
    return table(["DOF", "nnz(L)", "mesh s", "assembly s", "factorisation s", "eigen-solve s",
                  "checks s", "total s", "eigen/factor", "solves", "peak MB", "f7 Hz",
                  "max \\|Δf\\|/f vs finest", "status", "rigid modes", "max backward error"],
                 rows), [doc]


def crank_modes_1m(res):
    return crank_modes(res, "crank_modes_1m")


def slepc_modes(res):
    doc = res("slepc_modes")
    rows = []
    for r in doc["data"]["runs"]:
        s = r["seconds"]
        flops = r["factor_flops"]
        rows.append([r["name"], r["ranks"], r["dofs"], f"{r['nnz_factor'] / 1e6:.1f}M",
                     sig3(flops / 1e9 if flops else None), num(s.get("factorisation"), ".2f"),
                     num(s.get("eigen-solve"), ".2f"), num(s["total"], ".1f"),
                     num(r["wall_s"], ".1f"), num(r["factor_peak_mb"], ".0f"),
                     num(r["rank0_peak_memory_mb"], ".0f"), r["solves"],
                     num(r["max_rel_diff_vs_cholmod"], ".1e"), r["status"]])
    return table(["run", "ranks", "DOF", "factor entries", "factor GFlop", "factorisation s",
                  "eigen-solve s", "emb total s", "wall s", "MUMPS MB (largest rank)",
                  "rank-0 peak MB", "solves", "max \\|Δf\\|/f vs cholmod", "status"],
                 rows), [doc]


def slepc_reduce(res):
    doc = res("slepc_reduce")
    rows = []
    for r in doc["data"]["runs"]:
        s = r["seconds"]
        d = r["max_rel_diff_vs_cholmod"]
        mumps = (f"{num(r['static_factor_peak_mb'], '.0f')} / {num(r['eigen_factor_peak_mb'], '.0f')}"
                 if r.get("static_factor_peak_mb") is not None else "-")
        rows.append([r["name"], r["ranks"], r["dofs"], r["fixed_interface_modes"],
                     num(s.get("factorisation"), ".2f"), num(s.get("shifted factorisation"), ".2f"),
                     num(s.get("eigen-solve"), ".2f"), num(s.get("constraint modes"), ".2f"),
                     num(s.get("static load cases"), ".2f"), num(s.get("certificate"), ".1f"),
                     num(s["total"], ".1f"), num(r["wall_s"], ".1f"), num(r["peak_mb"], ".0f"),
                     mumps, num(d["fixed_interface_hz"], ".1e"), num(d["K"], ".1e"),
                     num(d["M"], ".1e"), "passed" if r["certificate_passed"] else "FAILED"])
    return table(["run", "ranks", "DOF", "fixed-interface modes", "factorisation s",
                  "shifted factorisation s", "eigen-solve s", "constraint modes s",
                  "static load cases s", "certificate s", "emb total s", "wall s",
                  "peak MB (largest process)", "MUMPS MB static / shifted (largest rank)",
                  "max \\|Δf\\|/f fixed-interface", "K̂ rel. diff", "M̂ rel. diff",
                  "certificate"], rows), [doc]


def factorisation_cost(run):
    """One factorisation's seconds: the phase, plus the METIS ordering where `emb modes` ran it
    beside the assembly (ordering_s; then not in the factorisation phase)."""
    s = run.get("seconds") or run["emb_seconds"]
    return s["factorisation"] + (run.get("ordering_s") or 0.0)


def ccx_vs_emb(res):
    doc = res("ccx_vs_emb")
    rows = []
    for r in doc["data"]["runs"]:
        s = r["emb_seconds"]
        rows.append([r["dofs"], num(r["ccx_wall_s"], ".1f"), num(r["emb_wall_s"], ".2f"),
                     num(r["ratio"], ".1f"), num(s.get("assembly"), ".2f"),
                     num(s.get("factorisation"), ".2f"), num(s.get("eigen-solve"), ".2f"),
                     num(s.get("eigen-solve", 0) / factorisation_cost(r), ".2f"),
                     num(s.get("checks"), ".2f"), r["solves"],
                     num(r["ccx_peak_mb"], ".0f"), num(r["emb_peak_mb"], ".0f"),
                     num(r["max_rel_freq_diff"], ".1e"), r["status"]])
    g = doc["data"].get("growth_exponent", {})
    lines = table(["DOF", "CalculiX s", "emb s", "CalculiX / emb", "assembly s", "factorisation s",
                   "eigen-solve s", "eigen/factor", "checks s", "solves", "CalculiX MB",
                   "emb MB", "max \\|Δf\\|/f", "status"], rows)
    if g:
        lines += ["", f"Fitted cost growth t ∝ DOF^p: emb p = {num(g.get('emb'), '.2f')}, "
                      f"CalculiX p = {num(g.get('ccx'), '.2f')}."]
    return lines, [doc]


def block_solve(res):
    doc = res("block_solve")
    rows = []
    for r in doc["data"]["runs"]:
        per = {b["block"]: b["seconds_per_rhs"] for b in r["blocks"]}
        rows.append([f"h = {float(r['name']) * 1000:g} mm", r["unknowns"], f"{r['nnz_factor'] / 1e6:.1f}M",
                     num(r["seconds_analyse"], ".2f"), num(r["seconds_factorise"], ".2f")] +
                    [num(per.get(b), ".4f") for b in (1, 2, 4, 8, 16, 32)] +
                    [num(per[1] / per[16], ".1f") if 1 in per and 16 in per else "–"])
    return table(["mesh", "dof", "nnz(L)", "analyse s", "factorise s", "b = 1", "2", "4", "8", "16",
                  "32", "single / b=16"], rows), [doc]


def free_vibration_supports_fv5(res):
    doc = res("free_vibration_supports")
    d = doc["data"]
    t = d["targets_hz"]
    by = {}
    for r in d["fv5"]:
        by.setdefault(r["n"], {})[r["support"]] = r

    def pct(x, ref):
        return num(100.0 * (x / ref - 1.0), "+.2f")

    rows = []
    for n, s in sorted(by.items()):
        rbe3, rbe2, point = s.get("rbe3"), s.get("rbe2"), s.get("point")
        row = [f"{5 * n} × {n} × {n}", rbe3["dofs"]]
        row += [num(rbe3["frequencies_hz"][0], ".3f"), pct(rbe3["frequencies_hz"][0], t["fv5_flexural_1"]),
                num(rbe3["frequencies_hz"][2], ".2f"), num(rbe3["frequencies_hz"][3], ".2f"),
                pct(rbe3["frequencies_hz"][3], t["fv5_extensional"])]
        row += [num(rbe2["frequencies_hz"][0], ".3f"), pct(rbe2["frequencies_hz"][0], t["fv5_flexural_1"])]
        if point:
            f1 = point["frequencies_hz"][point["rigid_modes"]]
            row += [num(f1, ".3f"), pct(f1, t["fv5_flexural_1"]), point["rigid_modes"]]
        else:
            row += ["–", "–", "–"]
        rows.append(row)
    return table(["Hex20 cells", "dof", "RBE3 f1 Hz", "vs 42.649 %", "RBE3 torsion Hz", "RBE3 axial Hz",
                  "vs 125 %", "RBE2 f1 Hz", "vs 42.649 %", "point f1 Hz", "vs 42.649 %", "point rigid"],
                 rows), [doc]


def free_vibration_supports_fv52(res):
    doc = res("free_vibration_supports")
    d = doc["data"]
    ref = d["targets_hz"]["fv52_mode_4"]
    by = {}
    for r in d["fv52"]:
        by.setdefault(r["n"], {})[r["support"]] = r
    rows = []
    for n, s in sorted(by.items()):
        e, f = s["bottom edges"], s["side faces"]
        fe = e["frequencies_hz"][e["rigid_modes"]]
        ff = f["frequencies_hz"][f["rigid_modes"]]
        rows.append([f"{4 * n} × {4 * n} × {n}", e["dofs"], e["rigid_modes"], num(fe, ".3f"),
                     num(100.0 * (fe / ref - 1.0), "+.2f"), num(ff, ".3f"),
                     num(100.0 * (ff / ref - 1.0), "+.2f")])
    return table(["Hex20 cells", "dof", "rigid (edges)", "edges: first bending Hz", "vs 45.897 %",
                  "faces: first bending Hz", "vs 45.897 %"], rows), [doc]


# emb reduce's phases in pipeline order ("total" is their sum without "write").
REDUCE_PHASES = ["mesh", "assembly", "interfaces", "partition", "factorisation", "eigen-solve",
                 "checks", "constraint modes", "basis", "reduced matrices", "orthonormalisation",
                 "invariants", "static load cases", "geometric stiffness", "modal stresses",
                 "certificate", "write"]


def crank_reduce_sizes(res):
    doc = res("crank_reduce_sizes")
    runs = doc["data"]["runs"]
    unknown = sorted({p for r in runs for p in r["seconds"]} - set(REDUCE_PHASES) -
                     {"total", "elapsed"})
    if unknown:
        raise RenderError(f"crank_reduce_sizes: phases {unknown} not in REDUCE_PHASES")
    rows = []
    for r in runs:
        s = r["seconds"]
        c = r["certificate"]
        rows.append([r["dofs"], r["fixed_interface_modes"]] +
                    [num(s.get(p, 0.0), ".1f") for p in REDUCE_PHASES] +
                    [num(s.get("elapsed", s["total"] + s.get("write", 0.0)), ".1f"),
                     num(r["peak_memory_mb"], ".0f"),
                     num(r["max_error_pct"], ".3f"), "passed" if c["passed"] else "FAILED",
                     num(c["static_error"], ".1e")])
    return table(["FE DOF", "kept modes"] + [p + " s" for p in REDUCE_PHASES] +
                 ["elapsed s (whole command)", "peak MB", "max error % (≤ band)", "certificate",
                  "static error"],
                 rows), [doc]


def crank_reduce_modes(res):
    doc = res("crank_reduce_modes")
    rows = [[r["fixed_interface_modes"], r["elastic_modes"], num(r["seconds_reduction"], ".1f"),
             num(r["seconds"].get("eigen-solve"), ".1f"), num(r["max_error_pct_6khz"], ".3f"),
             num(r["max_error_pct_3khz"], ".3f"), r["certificate"]["unrepresented"],
             num(r["certificate"]["min_mac"], ".4f")] for r in doc["data"]["runs"]]
    return table(["fixed-interface modes", "elastic coords", "reduction s (without certificate)",
                  "of which eigen-solve s", "max error % ≤ 6 kHz", "max error % ≤ 3 kHz",
                  "not represented", "min MAC"], rows), [doc]


def crank_reduce_stiffening(res):
    doc = res("crank_reduce_stiffening")
    rows = []
    for r in doc["data"]["runs"]:
        s = r["seconds"]
        with_k = "static load cases" in s
        rows.append(["with (default)" if r["name"] == "with" else "`--no-geometric-stiffness`",
                     r["dofs"], r["elastic_modes"],
                     num(s.get("static load cases"), ".1f") if with_k else "—",
                     num(s.get("geometric stiffness"), ".1f") if with_k else "—",
                     num(s["total"] - s.get("certificate", 0.0), ".1f"), num(s.get("certificate"), ".1f"),
                     num(s.get("write"), ".1f"), num(s["total"] + s.get("write", 0.0), ".1f"),
                     num(r["peak_memory_mb"], ".0f"), num(r["file_mb"], ".2f")])
    return table(["run", "FE DOF", "elastic modes", "static load cases s", "geometric stiffness s",
                  "total − certificate − write s", "certificate s", "write s", "total s", "peak MB",
                  "file MB"],
                 rows), [doc]


def stress_recovery_runs(res, crank):
    doc = res("stress_recovery_" + crank)
    return doc, {r["name"]: r for r in doc["data"]["runs"]}


def stress_recovery_cost(res, crank):
    doc, runs = stress_recovery_runs(res, crank)
    sizes = runs["extras"]["file_mb"]
    rows = []
    for key, label in [("with", "fillet stress groups (default)"), ("without", "`--no-stress`")]:
        s = runs["reduce_" + key]["summary"]
        r = runs["run_" + key]["summary"]
        rows.append([label, s["dofs"], s["elastic_modes"],
                     num(s.get("seconds_modal stresses"), ".2f") if key == "with" else "—",
                     num(s.get("seconds_elapsed", s["seconds_total"]), ".1f"), num(sizes[key], ".2f"),
                     num(r["seconds_run"], ".1f"), r["steps"], r["samples"]])
    return table(["body file", "FE DOF", "elastic modes", "modal stresses s", "reduce elapsed s",
                  "file MB", "engine run s (to steady state)", "IDA steps", "samples"], rows), [doc]


def stress_recovery_hot_spots(res, crank):
    doc, runs = stress_recovery_runs(res, crank)
    checks = {r["group"]: r for r in runs["reduce_with"]["stress"]}
    fatigue = {r["group"]: r for r in runs["run_with"]["fatigue"]}
    rows = []
    for g in runs["extras"]["hot_spots"]["groups"]:
        c, f = checks[g["name"]], fatigue[g["name"]]
        rows.append([f"`{g['name']}`", c["nodes"], num(c["check_error"], ".1e"),
                     num(g["max_von_mises_pa"] / 1e6, ".1f"), g["max_von_mises_node"],
                     num(g["min_principal_pa"] / 1e6, ".1f") + " .. " + num(g["max_principal_pa"] / 1e6, ".1f"),
                     num(f["max_range"] / 1e6, ".1f"), num(f["damage"], ".2e"),
                     num(f["life"], ".2e") if f["life"] is not None else "∞"])
    return table(["group", "nodes", "modal vs full FE (static)", "max von Mises MPa", "at node",
                  "group max σ₁ over the cycle, min .. max MPa", "worst node's max rainflow range MPa",
                  "damage per cycle", "life, engine cycles"], rows), [doc]


def stress_recovery_1cyl(res):
    return stress_recovery_cost(res, "1cyl")


def stress_recovery_1cyl_fatigue(res):
    return stress_recovery_hot_spots(res, "1cyl")


def stress_recovery_i4(res):
    return stress_recovery_cost(res, "i4")


def stress_recovery_i4_fatigue(res):
    return stress_recovery_hot_spots(res, "i4")


def beam_vs_cms(res):
    crank, tube = res("beam_vs_cms_crank"), res("beam_vs_cms_tube")
    cases = crank["data"]["cases"] + tube["data"]["cases"]
    order = []
    for c in cases:
        for r in c["routes"]:
            if r["route"] not in order:
                order.append(r["route"])

    def cell(case, route):
        r = next((x for x in case["routes"] if x["route"] == route), None)
        if r is None:
            return "—"
        err = "0" if r["method"] == "fe" else num(r["max_abs_error_pct"], ".3g")
        return f"{r['paired']}/{r['judged']}, {err}, {num(r['seconds'], '.3g')}"

    names = {"fe": "3-D FE (reference)"}
    rows = [[names.get(route, route)] + [cell(c, route) for c in cases] for route in order]
    header = ["route"] + [f"{c['part']} {c['name'].split('_')[-1]} ({thousands(c['fe_dofs'])} DOF): "
                          "paired/judged, max \\|err\\| %, s" for c in cases]
    return table(header, rows), [crank, tube]


def beam_web_width(res):
    doc = res("beam_web_width")
    runs = doc["data"]["runs"]
    n = len(doc["data"]["reference_hz"])
    rows = [[f"{r['width_m']:g}"] + [num(e, "+.1f") for e in r["errors_pct"]] for r in runs]
    return table(["b [m]"] + [f"{k + 1} ({doc['data']['reference_hz'][k]:.0f} Hz)" for k in range(n)],
                 rows), [doc]


def inline4_rows(doc, names=None):
    rows = []
    for r in doc["data"]["runs"]:
        rows.append([names.get(r["name"], r["name"]) if names else r["name"], r["modal_coordinates"],
                     f"{r['rtol']:.0e}", r["status"], r["steps"], num(r["seconds_per_cycle"], ".2f"),
                     num(r["nose_rms_error_pct"], ".3g"), num(r["bearing3_rms_error_pct"], ".3g"),
                     num(r["max_nose_torsion_mrad"], ".3g")])
    return rows


INLINE4_HEADER = ["run", "modal coordinates", "rtol", "status", "IDA steps", "wall s / cycle",
                  "nose torsion RMS error %", "bearing 3 force RMS error %", "max nose torsion mrad"]


ENGINE_LABELS = {
    "ref": "full basis, rtol 1e-7 (reference)", "ref_half": "full basis, rtol 5e-8",
    "default": "installed 2 kHz, rtol 1e-4 (scene default)", "band1000": "installed 1 kHz",
    "band3000": "installed 3 kHz", "band5000": "installed 5 kHz",
    "rtol1e-3": "installed 2 kHz, rtol 1e-3", "rtol1e-5": "installed 2 kHz, rtol 1e-5",
    "galpha": "installed 2 kHz, generalized-α (ρ∞ 0.5), rtol 1e-4",
    "lowest13": "lowest 13 free-free modes", "lowest20": "lowest 20 free-free modes",
    "lowest40": "lowest 40 free-free modes",
    "former_default": "lowest 20 modes, rtol 1e-6 (former default)", "rigid": "rigid crank",
    "ref6000": "full basis, rtol 1e-7 (reference)", "default6000": "installed 2 kHz, rtol 1e-4 (scene default)",
    "relax0.01": "installed 2 kHz, relaxation 0.01", "relax1": "installed 2 kHz, relaxation 1",
    "newton0.33": "installed 2 kHz, Newton convergence factor 0.33 (SUNDIALS' default)",
    "ref_ocvirk": "full basis, rtol 1e-7 (reference)", "default_ocvirk": "installed 2 kHz, rtol 1e-5 (scene default)",
    "ref_1cyl": "full basis, rtol 1e-7 (reference)", "default_1cyl": "installed 2 kHz, rtol 1e-5 (scene default)",
    "ref_step": "full basis, rtol 1e-7 (reference)", "default_step": "installed 2 kHz, rtol 1e-4 (scene default)",
}


def engine_rows(doc):
    rows = []
    for r in doc["data"]["runs"]:
        steady = r.get("steady_state") or ""
        steady = "—" if not steady else ("reached" if steady.startswith("reached") else "not reached")
        rows.append([ENGINE_LABELS.get(r["name"], r["name"]), r["modal_coordinates"], f"{r['rtol']:.0e}",
                     r["status"], steady, num(r["cycles"], ".0f"), r["steps"], num(r["cpu_seconds_per_cycle"], ".2f"),
                     num(r["nose_torsion_error_pct"], ".2g"), num(r["main_bearing_error_pct"], ".2g"),
                     num(r["big_end_error_pct"], ".2g")])
    return rows


ENGINE_HEADER = ["configuration", "modal coordinates", "rtol", "status", "steady state", "cycles run", "IDA steps",
                 "CPU s per cycle", "nose torsion error %", "main bearings, worst %", "big ends, worst %"]


def inline4_basis(res):
    doc = res("inline4_basis")
    return table(ENGINE_HEADER, engine_rows(doc)), [doc]


def inline4_basis_6000(res):
    doc = res("inline4_basis_6000")
    return table(ENGINE_HEADER, engine_rows(doc)), [doc]


def inline4_basis_ocvirk(res):
    doc = res("inline4_basis_ocvirk")
    return table(ENGINE_HEADER, engine_rows(doc)), [doc]


def engine_1cyl_basis(res):
    doc = res("engine_1cyl_basis")
    return table(ENGINE_HEADER, engine_rows(doc)), [doc]


def inline4_basis_load_step(res):
    doc = res("inline4_basis_load_step")
    return table(ENGINE_HEADER, engine_rows(doc)), [doc]


def inline4_flex_modes(res):
    doc = res("inline4_flex_modes")
    names = {"ref": "reference (60 modes)", "modes0": "0 modes (rigid crank)", "modes10": "10 modes",
             "modes20": "20 modes (scene default)", "modes40": "40 modes"}
    return table(INLINE4_HEADER, inline4_rows(doc, names)), [doc]


def inline4_flex_tolerance(res):
    doc = res("inline4_flex_tolerance")
    return table(INLINE4_HEADER, inline4_rows(doc)), [doc]


def inline4_models(res):
    doc = res("inline4_models")
    labels = {"model_rigid": "rigid crank", "model_beam": "beam crank (elastic webs, condensed)",
              "model_cms": "CMS crank (installed basis, 2 kHz)"}
    rows = engine_rows(doc)
    for row, r in zip(rows, doc["data"]["runs"]):
        row[0] = labels.get(r["name"], r["name"])
    return table(ENGINE_HEADER, rows), [doc]


def inline4_beam(res):
    doc = res("inline4_beam")
    names = {"all_r7": "every node (reference)", "all_r6": "every node",
             "condensed_r6": "condensed (default)", "condensed_r8": "condensed"}
    rows = []
    for r in doc["data"]["runs"]:
        rows.append([names.get(r["name"], r["name"]), r["bodies"], f"{r['rtol']:.0e}", r["status"],
                     r["steps"], r["error_test_failures"], num(r["seconds_per_cycle"], ".3g"),
                     num(r["nose_rms_error_pct"], ".2g"), num(r["bearing_max_rms_error_pct"], ".2g"),
                     " / ".join(num(e, ".2g") for e in r["bearing_rms_error_pct"]),
                     num(r["big_end1_rms_error_pct"], ".2g")])
    return table(["beam crank", "bodies", "rtol", "status", "steps", "error test failures",
                  "wall s per cycle", "nose torsion error %", "main bearings max error %",
                  "bearings 1 / 2 / 3 / 4 / 5 error %", "big end 1 error %"], rows), [doc]


def driveline_clonk(res):
    doc = res("driveline_clonk")
    names = {"ref": "CMS installed basis 5 kHz, rtol 1e-8 (reference)",
             "inst5k": "CMS installed basis 5 kHz (scene default)",
             "inst2k": "CMS installed basis 2 kHz", "full": "CMS, every free-free mode of the file",
             "ff5k": "CMS, free-free modes to 5 kHz", "ff2k": "CMS, free-free modes to 2 kHz",
             "beam": "beam tube"}
    rows = []
    for r in doc["data"]["runs"]:
        tip = r["windows"][1] if len(r["windows"]) > 1 else (r["windows"] or [{}])[0]
        rows.append([names.get(r["name"], r["name"]), r["modal_coordinates"], f"{r['rtol']:.0e}",
                     r["status"], r["steps"], r["events"], r["contacts"],
                     num(r["seconds_run"], ".1f"), num(r["seconds_per_simulated_second"], ".1f"),
                     num(r["events_per_simulated_second"], ".0f"),
                     num(r["gear_torque_rms_error_pct"], ".2g"), num(r["tube_accel_rms_error_pct"], ".2g"),
                     num(tip.get("peak_accel"), ".3g"), num(tip.get("max_abs_band_error_db"), ".1f"),
                     num(tip.get("peak_sound_power_level_db"), ".1f")])
    return table(["tube", "modal coords", "rtol", "status", "steps", "events", "contacts", "wall s",
                  "wall s per simulated s", "events per simulated s", "gear torque error %",
                  "surface accel error %", "tip-in peak accel m/s²", "tip-in max band error dB",
                  "tip-in peak L_W dB"], rows), [doc]


def driveline_clonk_bands(res):
    doc = res("driveline_clonk")
    centres = doc["data"]["band_centres_hz"]
    rows = []
    for r in doc["data"]["runs"]:
        for w in r["windows"]:
            rows.append([r["name"], num(w["start"], ".3f")] + [num(x, ".1f") for x in w["band_levels_db"]])
    return table(["run", "window from s"] + [f"{c} Hz" for c in centres], rows), [doc]


def inline4_profile(res, name="inline4_profile"):
    doc = res(name)
    lib = doc["data"]["by_library"][:8]
    fun = doc["data"]["by_function"][:15]
    out = table(["library", "share of samples %"], [[x["library"], num(x["share_pct"], ".1f")] for x in lib])
    out += [""] + table(["function (self time)", "share %"],
                        [[x["symbol"].replace("|", "\\|"), num(x["share_pct"], ".1f")] for x in fun])
    return out, [doc]


def inline4_profile_before(res):
    return inline4_profile(res, "inline4_profile_before")


def mbs_work_precision(res):
    doc = res("mbs_work_precision")
    rows = [[r["model"], f"{r['rtol']:.0e}", r["status"], r["steps"], r["residual_evals"],
             r["jacobian_evals"], r["linear_solver"], num(r["seconds"], ".3f"), num(r["max_error_m"], ".1e")]
            for r in doc["data"]["work_precision"]]
    return table(["model", "rtol", "status", "steps", "residuals", "Jacobians", "linear solver",
                  f"wall s (best of {doc['data']['repeats']})", "max error m"], rows), [doc]


def mbs_multiplier_rule(res):
    doc = res("mbs_work_precision")
    rows = [[r["model"], f"{r['rtol']:.0e}", f"{r['fixed_multiplier_atol']:.1e}",
             r["fixed"]["steps"], num(r["fixed_max_error_m"], ".1e"),
             f"{r['follows_rtol_multiplier_atol']:.1e}", r["follows_rtol"]["steps"],
             num(r["follows_rtol_max_error_m"], ".1e")]
            for r in doc["data"]["multiplier_rule"]]
    return table(["model", "rtol", "fixed: atol λ", "steps", "max error m",
                  "follows rtol: atol λ", "steps", "max error m"], rows), [doc]


def mbs_chains(res):
    doc = res("mbs_work_precision")
    rows = [[r["bodies"], r["unknowns"], r["linear_solver"], r["status"], r["steps"], r["jacobian_evals"],
             r["full_factorizations"], thousands(r["jacobian_nonzeros"]), num(r["seconds"], ".3f"),
             r["repeats"]] for r in doc["data"]["chains"]]
    return table(["bodies", "unknowns", "solver", "status", "steps", "Jacobians", "full LU", "nnz",
                  "wall s", "best of"], rows), [doc]


def mbs_residual(res):
    doc = res("mbs_residual_benchmark")
    by = {}
    for b in doc["data"]["benchmarks"]:
        kind, n = b["name"].split("/")
        scale = {"ns": 1e-3, "us": 1.0, "ms": 1e3}[b["time_unit"]]
        by.setdefault(int(n), {})[kind] = b["real_time"] * scale
        by[int(n)]["unknowns"] = int(b.get("unknowns", 0))
        if "nnz" in b:
            by[int(n)]["nnz"] = int(b["nnz"])
    rows = [[n, v["unknowns"], sig3(v.get("BM_Residual")), sig3(v.get("BM_Jacobian")),
             sig3(v.get("BM_SparseJacobian")), thousands(v.get("nnz", 0))] for n, v in sorted(by.items())]
    return table(["N", "unknowns", "residual µs", "dense Jacobian µs", "sparse Jacobian µs", "nnz"],
                 rows), [doc]


def steady_state(res):
    doc = res("steady_state")
    rows = [[f"`{r['scene']}`", r["elastic_start"], num(r["speed_factor"]),
             f"{r['cycles']}" + ("" if r["converged"] else " (not converged)"),
             thousands(r["steps"]), sig3(r["cpu_s"]), sig3(r["cpu_s_per_cycle"]),
             num(r["change"], ".2g"),
             f"{num(r['cycle1_error'], '.2g')} ({r['cycle1_worst_channel']})",
             f"{num(r['cycle2_error'], '.2g')} ({r['cycle2_worst_channel']})",
             num(r.get("transient_decay_per_cycle"), ".2f")]
            for r in doc["data"]["runs"]]
    return table(["scene", "elastic start", "initial speed ×", "cycles to steady state",
                  "IDA steps", "CPU [s]", "CPU per cycle [s]", "last change", "cycle 1 vs steady",
                  "cycle 2 vs steady", "transient decay per cycle"], rows), [doc]


def campbell_inline4(res):
    doc = res("campbell_inline4")
    r = doc["data"]["runs"][0]
    rows = [[m["index"], m["class"], m["whirl"], sig3(m["hz_1000"]), sig3(m["hz_3000"]),
             sig3(m["hz_6500"]), num(m["torsion_3000"], ".2f"), num(m["bending_3000"], ".2f"),
             num(m["min_mac"], ".3f")] for m in r["modes"]]
    lines = table(["mode", "class", "whirl", "f at 1000 rpm [Hz]", "f at 3000 rpm [Hz]",
                   "f at 6500 rpm [Hz]", "torsion fraction", "bending fraction", "min MAC"], rows)
    lines += ["", "Crossings of the orders 2, 4, 6, 8 in 1000-6500 rpm:", ""]
    lines += table(["order", "rpm", "f [Hz]", "mode", "class"],
                   [[num(c["order"]), sig3(c["rpm"]), sig3(c["mode_hz"]), c["mode_index"],
                     c["class"]] for c in r["main_order_crossings"]])
    return lines, [doc]


def tvd_inline4(res, name="tvd_inline4"):
    doc = res(name)
    r = doc["data"]["runs"][0]
    rows = [[num(o["order"]), num(o["without_rad"] * 1e3, ".3g"), num(o["with_rad"] * 1e3, ".3g"),
             num(o["ratio"], ".2f")] for o in r["orders"]]
    lines = table(["order", "nose torsion without TVD [mrad]", "with TVD [mrad]", "with / without"],
                  rows)
    runs = r["runs"]
    lines += ["", "Runs at %g rpm: " % r["rpm"] + "; ".join(
        "`%s` %s, steady state %s, %s IDA steps" % (k, v["status"], v["steady_state"], v["steps"])
        for k, v in runs.items()) + "."]
    return lines, [doc]


def campbell_angles(res):
    doc = res("campbell_angles")
    r = doc["data"]["runs"][0]
    rows = [[a["linearisation"], num(a["num_angles"], "d"), ", ".join(sig3(f) for f in a["torsion_hz"]),
             ", ".join(f"{sig3(lo)}–{sig3(hi)}" for lo, hi in
                       zip(a["torsion_angle_min_hz"], a["torsion_angle_max_hz"]) if lo is not None) or "–",
             ", ".join("%s %s" % (m["class"], sig3(m["hz"])) for m in a["modes"]),
             num(a.get("max_change_pct_vs_half"), ".2g"), num(a["min_decay"], ".3g")] for a in r["angles"]]
    return table(["linearisation", "angles", "torsion modes [Hz]",
                  "torsion: frozen range over the angles [Hz]", "all modes below 800 Hz",
                  "largest change vs half the angles [%]", "smallest decay [1/s]"], rows), [doc]


def tvd_rubber_inline4(res):
    doc = res("tvd_rubber_inline4")
    r = doc["data"]["runs"][0]
    rows = [[num(o["order"]), num(o["none_rad"] * 1e3, ".3g"),
             num(o["kelvin_voigt_rad"] * 1e3, ".3g"), num(o["kelvin_voigt_ratio"], ".2f"),
             num(o["zener_rad"] * 1e3, ".3g"), num(o["zener_ratio"], ".2f"),
             num(o["zener_eta02_rad"] * 1e3, ".3g"), num(o["zener_eta02_ratio"], ".2f")]
            for o in r["orders"]]
    lines = table(["order", "no TVD [mrad]", "Kelvin-Voigt [mrad]", "KV / none",
                   "Zener, Den Hartog's η [mrad]", "Zener / none", "Zener, η = 0.2 [mrad]",
                   "Zener 0.2 / none"], rows)
    lines += ["", "Runs at %g rpm: " % r["rpm"] + "; ".join(
        "`%s` %s, steady state %s, %s IDA steps, %s CPU s" % (k, v["status"], v["steady_state"],
                                                            v["steps"], num(v["cpu_s"], ".1f"))
        for k, v in r["runs"].items()) + "."]
    return lines, [doc]


def tvd_inline4_3250(res):
    return tvd_inline4(res, "tvd_inline4_3250")


def sweep_inline4(res):
    doc = res("sweep_inline4")
    runs = doc["data"]["runs"]
    base = next((r for r in runs if r["jobs"] == 1), None)
    rows = [[f"-j {r['jobs']}", r["rpm"], r["points"], r["converged"], r["not_converged"],
             r["failed"], r["cycles"], num(r["wall_seconds"], ".1f"),
             num(r["wall_seconds"] / r["points"], ".2f"), num(r["point_cpu_seconds"], ".1f"),
             num(r["point_cpu_seconds"] / r["cycles"], ".3f"),
             num(base["wall_seconds"] / r["wall_seconds"], ".2f") if base else "–"]
            for r in runs]
    return table(["processes", "speeds [rpm]", "points", "converged", "not settled", "failed",
                  "cycles run", "wall [s]", "wall per point [s]", "CPU of the points [s]",
                  "CPU per cycle [s]", "speed-up vs -j 1"], rows), [doc]


def runup_vs_sweep(res):
    doc = res("runup_vs_sweep")
    d = doc["data"]["runs"][0]
    rows = [[r["name"], num(r["steady_min"], ".1f") + " – " + num(r["steady_max"], ".1f"),
             num(r["max_abs_difference"], ".2f"), num(100 * r["max_difference_relative"], ".1f"),
             num(r["at_rpm"], ".0f")] for r in d["orders"]]
    lines = table(["order", "steady amplitude [N m]", "max \\|run-up − steady\\| [N m]",
                   "of the largest steady [%]", "at [rpm]"], rows)
    lines += ["", f"Compared at {len(d['compared_rpm'])} steady speeds "
                  f"{num(min(d['compared_rpm']), '.0f')}–{num(max(d['compared_rpm']), '.0f')} rpm "
                  f"({d['windows']} run-up windows). CPU: steady sweep "
                  f"{num(d['sweep_cpu_seconds'], '.1f')} s, run-up (run + tracking) "
                  f"{num(d['runup_cpu_seconds'], '.1f')} s."]
    unsettled = [num(n, ".0f") for n, st in zip(d["steady_rpm"], d["steady_status"])
                 if st != "converged"]
    if unsettled:
        lines[-1] += (f" Steady points without a steady state within the scene's max_cycles "
                      f"(their last cycle used, flagged in the sweep file): {', '.join(unsettled)} rpm.")
    return lines, [doc]


def order_cuts_inline4(res):
    doc = res("order_cuts_inline4")
    d = doc["data"]["runs"][0] if isinstance(doc["data"].get("runs"), list) else doc["data"]["inline4"]
    rows = [[num(r["order"], "g"), num(r["sweep_peak_rpm"], ".0f"), num(r["sweep_peak_hz"], ".0f"),
             (f'{num(r["campbell_rpm"], ".0f")} (mode {r["campbell_mode_index"]}, '
              f'{num(r["campbell_mode_hz"], ".0f")} Hz, torsion {num(r["campbell_torsion_share"], ".2f")})'
              if "campbell_rpm" in r else "–"),
             num(r.get("campbell_error_pct"), "+.1f"),
             str(len(r.get("candidates", []))),
             (f'{num(r["torsion_class_rpm"], ".0f")} ({num(r["torsion_class_mode_hz"], ".0f")} Hz)'
              if "torsion_class_rpm" in r else "–"),
             num(r.get("torsion_class_error_pct"), "+.1f"), num(r["sweep_peak_amplitude"] * 1e3, ".3f"),
             num(r["tvd_peak_amplitude"] * 1e3, ".3f"), num(r["tvd_peak_ratio"], ".2f")]
            for r in d["orders"]]
    lines = table(["order", "sweep peak [rpm]", "sweep peak × order [Hz]",
                   f"Campbell crossing of a torsion-carrying mode (share ≥ {d.get('torsion_share_min', 0.25):g}) [rpm]",
                   "Campbell vs sweep %", "such crossings of the order",
                   "crossing of the lowest torsion-class mode [rpm]", "that vs sweep %",
                   "peak torsion [mrad]", "with TVD: peak [mrad]", "with / without"], rows)
    lin = d.get("campbell_linearisation")
    if lin:
        lines += ["", (f"Campbell linearisation: {lin}; largest spread of a tracked mode's frozen frequency "
                      f"over the angles {num(d.get('campbell_max_angle_spread_pct'), '.1f')} %.")]
    unsettled = {k: v for k, v in d["points_not_converged"].items() if v}
    if unsettled:
        lines[-1] += " Points without a steady state within max_cycles: " + "; ".join(
            f"{k}: {', '.join(str(int(x)) for x in v)} rpm" for k, v in unsettled.items()) + "."
    return lines, [doc]


def reynolds_bearing_grids(res):
    doc = res("reynolds_bearing")
    d = doc["data"]
    rows = []
    for r in d["grids"]:
        rows.append([r["name"], r["unknowns"], sig3(r["eval_jacobian_us"]), sig3(r["eval_us"]),
                     sig3(r["cold_eval_jacobian_us"]),
                     f"{r['iterations_warm']:.2f} / {r['iterations_cold']:.1f}",
                     num(r["load_error_pct"], ".2f"), num(r["h_min_error_pct"], ".2f"),
                     num(r["p_max_error_pct"], ".1f"),
                     "**yes**" if r["name"] == d["converged_grid"] else ""])
    return table(["grid N × Nz", "unknowns", "eval + Jacobian µs", "eval µs",
                  "cold eval + Jacobian µs", "Newton iterations warm / cold",
                  "load error %", "h_min error %", "p_max error %", "first within 1 %"],
                 rows), [doc]


def reynolds_bearing_reference(res):
    doc = res("reynolds_bearing")
    d = doc["data"]
    rows = [[f"{r['load_n'] / 1e3:g}", num(r["eccentricity_ratio"], ".3f"), num(r["h_min_um"], ".2f"),
             num(r["p_max_mpa"], ".1f"), num(r["friction_power_w"], ".0f"),
             num(r["side_flow_l_per_min"], ".2f")] for r in d["reference"]]
    return table(["load kN", "eccentricity ratio", "h_min µm", "p_max MPa", "friction power W",
                  "side flow l/min"], rows), [doc]


def reynolds_bearing_solvers(res):
    doc = res("reynolds_bearing")
    rows = [[r["name"], r["grid"], num(r["cold_iterations"], ".2f"), sig3(r["cold_us"]),
             num(r["warm_iterations"], ".2f"), sig3(r["warm_us"]),
             num(r["force_vs_switch_rel"], ".1e")] for r in doc["data"]["solvers"]]
    return table(["complementarity solver", "grid", "cold iterations", "cold µs (with Jacobian)",
                  "warm iterations", "warm µs (with Jacobian)", "\\|ΔF\\|/F vs switch"], rows), [doc]


def reynolds_bearing_ocvirk(res):
    doc = res("reynolds_bearing")
    o = doc["data"]["ocvirk"]
    ref = {r["load_n"]: r for r in doc["data"]["reference"]}
    rows = [[f"{r['load_n'] / 1e3:g}", num(ref[r["load_n"]]["h_min_um"], ".2f"), num(r["h_min_um"], ".2f"),
             num(r["h_min_error_pct"], "+.1f"), num(r["load_error_pct"], "+.1f")] for r in o["loads"]]
    return table(["load kN", "h_min µm, finite width (reference)", "h_min µm, Ocvirk",
                  "Ocvirk h_min error %", "Ocvirk force error at the reference eccentricity %"],
                 rows), [doc]


def film_engine(res):
    doc = res("film_engine")

    def pct(r, key):
        return num(100.0 * r[key], "+.1f") if key in r else "–"

    def get(r, key, f):
        return f(r[key]) if key in r else "–"

    rows = [[r["route"], r["status"], r["cycles"], thousands(r["steps"]), sig3(r["cpu_s"]), sig3(r.get("cpu_s_per_cycle")),
             get(r, "peak_load_n", lambda x: sig3(x / 1e3)), pct(r, "peak_load_vs_reference"),
             get(r, "min_film_m", lambda x: num(x * 1e6, ".2f")), pct(r, "min_film_vs_reference"),
             get(r, "peak_pressure_pa", lambda x: sig3(x / 1e6)),
             get(r, "mean_friction_power_w", sig3), pct(r, "mean_friction_power_vs_reference"),
             get(r, "mean_cavitated_fraction", lambda x: num(x, ".2f"))]
            for r in doc["data"]["runs"]]
    return table(["route", "status", "cycles", "IDA steps", "CPU [s]",
                  "CPU per cycle [s]", "peak load [kN]", "vs reference %", "h_min [µm]",
                  "vs reference %", "p_max [MPa]", "friction [W]", "vs reference %",
                  "cavitated"], rows), [doc]


def validation_status(res):
    """The README's status of validation: one row per yardstick, the worst agreement its
    benchmark measured, the results file and the page that has the whole table."""
    rows, docs = [], []

    def by_name(name):
        return {r["name"]: r for r in res(name)["data"]["runs"]}

    def row(what, against, measured, name, page):
        doc = res(name)
        docs.append(doc)
        rows.append([what, against, measured, f"`{name}.json` ({doc['commit'][:7]}, {doc['date'][:10]})",
                     f"[details](docs/{page})"])

    d = res("ccx_vs_emb")["data"]
    row(f"FE modes of the inline-4 crank (Tet10, {len(d['runs'])} meshes)", "CalculiX on the same mesh",
        f"max \\|Δf\\|/f {num(max(r['max_rel_freq_diff'] for r in d['runs']), '.1e')}", "ccx_vs_emb",
        "validation.md#fe-modes-against-calculix")
    d = res("free_vibration_supports")["data"]
    fine = max(r["n"] for r in d["fv5"] if r["support"] == "rbe3")
    f5 = next(r for r in d["fv5"] if r["support"] == "rbe3" and r["n"] == fine)["frequencies_hz"][0]
    fine52 = max(r["n"] for r in d["fv52"] if r["support"] == "side faces")
    p52 = next(r for r in d["fv52"] if r["support"] == "side faces" and r["n"] == fine52)
    f52 = p52["frequencies_hz"][p52["rigid_modes"]]
    row("NAFEMS FV5 deep beam, FV52 plate (Hex20, finest mesh)", "published targets",
        f"FV5 f₁ {num(100 * (f5 / d['targets_hz']['fv5_flexural_1'] - 1), '+.2f')} %, "
        f"FV52 {num(100 * (f52 / d['targets_hz']['fv52_mode_4'] - 1), '+.2f')} %",
        "free_vibration_supports", "validation.md#supports-nafems-fv5-and-fv52")
    d = res("crank_reduce_modes")["data"]["runs"][-1]
    row(f"Craig–Bampton crank, {d['fixed_interface_modes']} fixed-interface modes", "the full FE model",
        f"max error {num(d['max_error_pct_3khz'], '.3f')} % to 3 kHz, "
        f"{num(d['max_error_pct_6khz'], '.3f')} % to 6 kHz", "crank_reduce_modes",
        "validation.md#craig-bampton-reduction")
    d = res("beam_vs_cms_crank")["data"]["cases"][0]
    cms = next(r for r in d["routes"] if r["route"] == "cms 40")
    beam = next(r for r in d["routes"] if r["route"] == "beam lumped, elastic webs")
    row("Beam and CMS crank, free-free", "the full FE model",
        f"CMS (40 modes) {num(cms['max_abs_error_pct'], '.2f')} %, elastic-web beam "
        f"{num(beam['max_abs_error_pct'], '.0f')} %", "beam_vs_cms_crank", "validation.md#beam-vs-cms")
    d = by_name("inline4_basis")
    row("Inline-4 engine, installed basis (2 kHz)", f"the full basis at rtol {num(d['ref']['rtol'], 'g')}",
        f"{num(d['default']['max_error_pct'], '.2f')} % (lowest 20 free-free modes: "
        f"{num(d['lowest20']['max_error_pct'], '.0f')} %)", "inline4_basis",
        "validation.md#inline-4-engine-installed-basis")
    d = by_name("slepc_modes")
    worst = max(r["max_rel_diff_vs_cholmod"] for n, r in d.items() if n != "cholmod")
    row("Distributed eigen-solve (SLEPc, 1 and 2 ranks)", "the default CHOLMOD path",
        f"max \\|Δf\\|/f {num(worst, '.1e')}", "slepc_modes", "validation.md#distributed-runs")
    d = res("order_cuts_inline4")["data"]["runs"][0]
    errs = [abs(o["campbell_error_pct"]) for o in d["orders"] if o.get("campbell_error_pct") is not None]
    row("Campbell diagram (cycle-averaged) of the inline-4", "resonance peaks of the steady sweep",
        f"within {num(max(errs), '.1f')} % in speed (orders "
        f"{', '.join(num(o['order'], 'g') for o in d['orders'])})", "order_cuts_inline4",
        "validation.md#campbell-diagram-against-the-running-engine")
    d = by_name("driveline_clonk")
    row("Driveline clonk, CMS tube on its installed basis (5 kHz)",
        f"the same model at rtol {num(d['ref']['rtol'], 'g')}",
        f"gear torque {num(d['inst5k']['gear_torque_rms_error_pct'], '.2f')} % RMS, tube "
        f"acceleration {num(d['inst5k']['tube_accel_rms_error_pct'], '.1f')} % RMS", "driveline_clonk",
        "validation.md#driveline-clonk")
    d = by_name("stress_recovery_1cyl")
    row("Fillet stresses from modal coordinates", "full FE static solves, same mesh",
        f"{num(d['reduce_with']['summary']['stress_check_error'], '.1e')} of the peak",
        "stress_recovery_1cyl", "validation.md#stress-recovery")
    d = res("runup_vs_sweep")["data"]["runs"][0]
    worst = max(o["max_difference_relative"] for o in d["orders"])
    row("Run-up order tracking (1000 → 6000 rpm in 2 s)", "steady speed sweep",
        f"within {num(100 * worst, '.1f')} % of the largest steady amplitude", "runup_vs_sweep",
        "validation.md#run-up-against-the-steady-sweep")
    return table(["yardstick", "against", "measured", "results", "page"], rows), []


TABLES = {f.__name__: f for f in [
    campbell_inline4, campbell_angles, tvd_inline4, tvd_inline4_3250, tvd_rubber_inline4,
    inline4_basis, inline4_basis_6000, inline4_basis_load_step, inline4_basis_ocvirk, engine_1cyl_basis,
    crank_modes, crank_modes_1m, slepc_modes, slepc_reduce, ccx_vs_emb, block_solve, free_vibration_supports_fv5, free_vibration_supports_fv52,
    crank_reduce_sizes, crank_reduce_modes, crank_reduce_stiffening, stress_recovery_1cyl,
    stress_recovery_1cyl_fatigue, stress_recovery_i4, stress_recovery_i4_fatigue,
    beam_vs_cms, beam_web_width, inline4_flex_modes, inline4_flex_tolerance, inline4_models,
    inline4_beam, inline4_profile, inline4_profile_before, mbs_work_precision, mbs_multiplier_rule,
    mbs_chains, mbs_residual, driveline_clonk, driveline_clonk_bands, steady_state, sweep_inline4, runup_vs_sweep,
    order_cuts_inline4, validation_status, reynolds_bearing_grids, reynolds_bearing_reference,
    reynolds_bearing_solvers, reynolds_bearing_ocvirk, film_engine]}


def render_table(name, res):
    if name not in TABLES:
        raise RenderError(f"unknown table '{name}' (known: {', '.join(TABLES)})")
    lines, docs = TABLES[name](res)
    for d in docs:
        lines += ["", source(d, d["benchmark"])]
    return "\n".join(lines) + "\n"


def render_value(spec, fmt, res):
    file, _, path = spec.strip().partition("/")
    try:
        x = find(res(file)["data"], [p for p in path.split("/") if p])
    except RenderError as e:
        raise RenderError(f"value '{spec}': {e}")
    if not isinstance(x, (int, float)):
        raise RenderError(f"value '{spec}' is not a number: {x!r}")
    return num(x, fmt or "g")


def render_document(text, res, problems):
    def table_sub(m):
        try:
            return m.group(1) + render_table(m.group(2), res) + m.group(4)
        except RenderError as e:
            problems.append(str(e))
            return m.group(0)

    def value_sub(m):
        try:
            return m.group(1) + render_value(m.group(2), m.group(3), res) + m.group(5)
        except RenderError as e:
            problems.append(str(e))
            return m.group(0)

    return VALUE_RE.sub(value_sub, TABLE_RE.sub(table_sub, text))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--check", action="store_true")
    p.add_argument("--print", metavar="NAME")
    p.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    a = p.parse_args()
    res = Results(a.root)
    if a.print:
        try:
            sys.stdout.write(render_table(a.print, res))
        except RenderError as e:
            sys.exit(f"render_tables.py: {e}")
        return 0
    problems, stale = [], []
    for rel in documents(a.root):
        path = os.path.join(a.root, rel)
        with open(path, encoding="utf-8") as f:
            text = f.read()
        new = render_document(text, res, problems)
        if new == text:
            continue
        if a.check:
            names = [m.group(2) for m in TABLE_RE.finditer(text)
                     if m.group(0) not in new]
            values = [m.group(2) for m in VALUE_RE.finditer(text) if m.group(0) not in new]
            stale.append(f"{rel}: differs from the results in tables {names or '-'}, values {values or '-'}")
        else:
            with open(path + ".tmp", "w", encoding="utf-8") as f:
                f.write(new)
            os.replace(path + ".tmp", path)
            print(f"updated {rel}")
    for msg in problems + stale:
        print(f"render_tables.py: {msg}", file=sys.stderr)
    if problems or stale:
        if stale:
            print("render_tables.py: run /usr/bin/python3 benchmarks/render_tables.py to regenerate",
                  file=sys.stderr)
        return 1
    if a.check:
        print("benchmark tables and values: up to date")
    return 0


if __name__ == "__main__":
    sys.exit(main())
