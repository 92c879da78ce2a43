#!/usr/bin/python3
"""emb's corpus of bad inputs and faults (issue 14), as data: run_corpus.py imports this
module and runs CASES with FIXTURES (nothing generated is committed).

    /usr/bin/python3 tests/corpus/make_manifest.py                 # counts by category
    /usr/bin/python3 tests/corpus/make_manifest.py --check 300     # fails below 300 cases
    /usr/bin/python3 tests/corpus/make_manifest.py --write m.json  # the cases as JSON

The cases are built from reading the code — every option of every subcommand, every scene
key, every dataset and attribute a reader uses — not only from the classes of the issue.
Each case: a name, a category, setup steps, the command, the exit code it must end with,
fragments its stderr must hold (and must not hold), and files that must not exist or not
change afterwards (run_corpus.py says what the steps mean). Placeholders: {emb} the
executable, {src} the repository, {fix} the fixtures (bar.geo, bar.msh, body.h5,
pendulum.yaml, pendulum.h5, disc.yaml, disc.h5), {work} the case's directory (also the
working directory).
"""

import base64
import json
import os
import sys

CASES = []
NAMES = set()


def case(name, category, cmd, exit, stderr=(), setup=(), absent=(), unchanged=(), exists=(),
         h5_attr=(), timeout=60, signal=None, keep_temporaries=False, stderr_absent=(),
         then=None, env=None):
    """`then`: a second command run in the same directory after the first (and its checks
    of files) with its own expected exit code: {"cmd": [...], "exit": N}."""
    assert name not in NAMES, name
    NAMES.add(name)
    c = {"name": name, "category": category, "cmd": ["{emb}", *cmd], "exit": exit,
         "stderr": list(stderr), "setup": [list(s) for s in setup]}
    if stderr_absent:
        c["stderr_absent"] = list(stderr_absent)
    if then:
        c["then"] = {"cmd": ["{emb}", *then["cmd"]], "exit": then["exit"]}
    if env:
        c["env"] = dict(env)
    for key, value in (("absent", absent), ("unchanged", unchanged), ("exists", exists),
                       ("h5_attr", h5_attr)):
        if value:
            c[key] = [list(v) if isinstance(v, tuple) else v for v in value]
    if timeout != 60:
        c["timeout"] = timeout
    if signal:
        c["signal"] = signal
    if keep_temporaries:
        c["keep_temporaries"] = True
    CASES.append(c)


def b64(data):
    return base64.b64encode(data).decode()


# A solid to append .geo commands to (meshes in well under a second).
BOX = ('SetFactory("OpenCASCADE");\nBox(1) = {0, 0, 0, 1, 1, 1};\n'
       'Physical Volume("box") = {1};\nMesh.MeshSizeMax = 0.5;\n')
MARKER = "{work}/pwned"

# --- .geo scripts: what gmsh would run, and malformed parameters ------------------------

REFUSED_GEO = {
    "systemcall": 'SystemCall "touch ' + MARKER + '";\n',
    "system": 'System "touch ' + MARKER + '";\n',
    "nonblocking": 'NonBlockingSystemCall "touch ' + MARKER + '";\n',
    "onelabrun_call": 'OnelabRun("x", "touch ' + MARKER + '");\n',
    "onelabrun_cmd": 'OnelabRun "touch ' + MARKER + '";\n',
    "s2n": 'S2N[StrCat("System", "Call")] "touch ' + MARKER + '";\n',
    "stringtoname": 'StringToName["SystemCall"] "touch ' + MARKER + '";\n',
    "save": 'Save "' + MARKER + '";\n',
    "save_view": 'Save View[0] "' + MARKER + '";\n',
    "print": 'Print "' + MARKER + '.png";\n',
    "printf_redirect": 'Printf("x") > "' + MARKER + '";\n',
    "printf_append": 'Printf("%g", 1) >> "' + MARKER + '";\n',
    "createdir": 'CreateDir "' + MARKER + '";\n',
    "exit": "Exit;\n",
    "sleep": "Sleep 1e6;\n",
    "plugin": "Plugin(Smooth).Run;\n",
    "tmpfilename": 'General.TmpFileName = "../../victim";\n',
    "errorfilename": 'General.ErrorFileName = "' + MARKER + '";\n',
    "abortonerror": "General.AbortOnError = 4;\n",
    "solver_exe": 'Solver.Executable0 = "/bin/sh";\n',
    "include_computed": 'Include StrCat("a", ".geo");\n',
    "merge_computed": "s = \"a.geo\";\nMerge s;\n",
    "shapefromfile_computed": 'v() = ShapeFromFile(StrCat("a", ".brep"));\n',
    "macro_body": 'Macro M\nSystemCall "touch ' + MARKER + '";\nReturn\n',
    "dead_branch": 'If (0)\nSystemCall "touch ' + MARKER + '";\nEndIf\n',
    "send_to_server": 'SendToServer View[0] "x";\n',
    "merge_program": 'Merge "tool.py";\n',
    "merge_gz": 'Merge "part.msh.gz";\n',
    "include_missing": 'Include "nowhere.geo";\n',
    "include_dir": 'Include "adir";\n',
    "include_fifo": 'Include "pipe.geo";\n',
}
for key, commands in REFUSED_GEO.items():
    setup = [("write", "part.geo", commands + BOX), ("write", "tool.py", "print(1)\n"),
             ("write", "part.msh.gz", "x"), ("mkdir", "adir")]
    if key == "include_fifo":
        setup.append(("fifo", "pipe.geo"))
    case(f"geo_refuse_{key}", "geo", ["mesh", "part.geo", "-q"], 1,
         ["refusing"], setup, absent=["pwned*"], timeout=20)

# Every command that opens geometry audits it.
for cmd_key, cmd in {"modes": ["modes", "part.geo", "-q", "-o", "m.h5"],
                     "reduce": ["reduce", "part.geo", "-q", "-o", "b.h5"],
                     "compare": ["compare", "part.geo", "-q"]}.items():
    case(f"geo_refuse_systemcall_{cmd_key}", "geo", cmd, 1, ["refusing", "SystemCall"],
         [("write", "part.geo", REFUSED_GEO["systemcall"] + BOX)],
         absent=["pwned*", "m.h5", "b.h5"], timeout=20)
    case(f"geo_refuse_onelabrun_{cmd_key}", "geo", cmd, 1, ["refusing", "OnelabRun"],
         [("write", "part.geo", REFUSED_GEO["onelabrun_call"] + BOX)],
         absent=["pwned*", "m.h5", "b.h5"], timeout=20)

# Hidden behind other files gmsh reads.
case("geo_include_nested", "geo", ["mesh", "top.geo", "-q"], 1, ["refusing", "c.geo:2"],
     [("write", "c.geo", "// c\nSystemCall \"touch " + MARKER + "\";\n"),
      ("write", "b.geo", 'Include "c.geo";\n'), ("write", "sub/a.geo", 'Include "../b.geo";\n'),
      ("write", "top.geo", 'Include "sub/a.geo";\n' + BOX)], absent=["pwned*"])
case("geo_include_cycle", "geo", ["mesh", "a.geo", "-q"], 1, ["includes a file that includes it"],
     [("write", "a.geo", 'Include "b.geo";\n' + BOX), ("write", "b.geo", 'Include "a.geo";\n')])
case("geo_include_self", "geo", ["mesh", "a.geo", "-q"], 1, ["includes a file that includes it"],
     [("write", "a.geo", 'Include "a.geo";\n' + BOX)])
case("geo_merge_script_txt", "geo", ["mesh", "a.geo", "-q"], 1, ["part.txt:1", "Exit"],
     [("write", "a.geo", 'Merge "part.txt";\n' + BOX), ("write", "part.txt", "Exit;\n")])
case("geo_opt_companion", "geo", ["mesh", "a.geo", "-q"], 1, ["a.geo.opt:1", "SystemCall"],
     [("write", "a.geo", BOX), ("write", "a.geo.opt", 'SystemCall "touch ' + MARKER + '";\n')],
     absent=["pwned*"])
case("geo_opt_of_opt", "geo", ["mesh", "a.geo", "-q"], 1, ["a.geo.opt.opt:1"],
     [("write", "a.geo", BOX), ("write", "a.geo.opt", "// options\n"),
      ("write", "a.geo.opt.opt", "Exit;\n")])
case("geo_msh_holding_script", "geo", ["mesh", "part.msh", "-q"], 1, ["refusing", "SystemCall"],
     [("write", "part.msh", 'SystemCall "touch ' + MARKER + '";\n' + BOX)], absent=["pwned*"])
case("geo_unknown_extension_script", "geo", ["mesh", "part.txt", "-q"], 1, ["refusing"],
     [("write", "part.txt", "Exit;\n" + BOX)])
case("geo_mixed_case_step_is_script", "geo", ["mesh", "part.Step", "-q"], 1, ["refusing"],
     [("write", "part.Step", "Exit;\n" + BOX)])
case("geo_msh_opt_companion", "geo", ["mesh", "{work}/bar.msh", "-q"], 1, ["bar.msh.opt"],
     [("copy", "{fix}/bar.msh", "bar.msh"), ("write", "bar.msh.opt", "Exit;\n")])
case("geo_nul_byte", "geo", ["mesh", "part.geo", "-q"], 1, ["NUL byte"],
     [("writeb", "part.geo", b64(b"// comment \0 hidden\n" + BOX.encode()))])
case("geo_long_string", "geo", ["mesh", "part.geo", "-q"], 1, ["gmsh keeps 1023"],
     [("write", "part.geo", 'Printf("' + "a" * 1100 + '");\n' + BOX)])
case("geo_cr_in_line_comment", "geo", ["mesh", "part.geo", "-q"], 0, [],
     [("write", "part.geo", "// a comment\r with a carriage return\n" + BOX)])
case("geo_binary_garbage", "geo", ["mesh", "part.geo", "-q"], 1, ["NUL byte"],
     [("writeb", "part.geo", b64(bytes(range(256)) * 8))])
case("geo_empty", "geo", ["mesh", "part.geo", "-q"], 1, ["no volume elements"],
     [("write", "part.geo", "")])
case("geo_syntax_error", "geo", ["mesh", "part.geo", "-q"], 1, ["gmsh failed to open"],
     [("write", "part.geo", "Box(1) = {0, 0, ;\n")])
case("geo_unterminated_comment", "geo", ["mesh", "part.geo", "-q"], 1, [],
     [("write", "part.geo", BOX + "/* never closed\nSystemCall \"x\";\n")])
case("geo_only_2d", "geo", ["mesh", "part.geo", "-q"], 1, ["no volume elements"],
     [("write", "part.geo", 'SetFactory("OpenCASCADE");\nRectangle(1) = {0, 0, 0, 1, 1};\n')])
# Allowed: comments, strings and harmless options are no commands.
case("geo_allowed_comments_strings", "geo", ["mesh", "part.geo", "-q"], 0, [],
     [("write", "part.geo", '// SystemCall "touch x";\n/* Exit; */\nPrintf("Save %g", 1 > 0);\n'
       'label = "SystemCall";\nGeneral.Terminal = 0;\nGeneral.Verbosity = 1;\n' + BOX)],
     absent=["pwned*", "x"])
# DefineConstant parameters (the scanner overflowed the stack on a malformed one).
MANY = "".join(f"  p{i} = {{{i}, Name \"P/p{i}\"}},\n" for i in range(20000))
case("geo_defineconstant_unclosed_long", "geo", ["mesh", "part.geo", "-q", "--set", "p5=1"], 1,
     [], [("write", "part.geo", "DefineConstant[\n" + MANY + BOX)], timeout=60)
case("geo_defineconstant_expression_default", "geo",
     ["mesh", "part.geo", "-q", "--set", "e=0.3"], 0, [],
     [("write", "part.geo", 'DefineConstant[ e = {2 * 0.25, Name "P/e"} ];\n' + BOX)])
case("geo_defineconstant_garbage_value", "geo", ["mesh", "part.geo", "-q", "--set", "a=1"], 1,
     ["no parameter 'a'"], [("write", "part.geo", "DefineConstant[ = e, {, ] ;\n" + BOX)])
for key, setting in {"unknown": "nope=1", "nan": "h=nan", "inf": "h=inf", "neg_inf": "h=-inf",
                     "empty_value": "h=", "no_name": "=1", "no_equals": "h", "text": "h=abc",
                     "trailing": "h=1x", "huge": "h=1e400"}.items():
    case(f"geo_set_{key}", "geo", ["mesh", "{fix}/bar.geo", "-q", "--set", setting], 1,
         ["--set" if key not in ("unknown",) else "no parameter"], timeout=20)
# Scripts that never finish while gmsh reads them (gmsh cannot be stopped): emb refuses them
# after EMB_GEO_SECONDS (here 3 s; 120 s by default), naming the file.
ENDLESS_GEO = {
    "loop_1e12": "For i In {1:1e12}\nEndFor\n",
    "nested_loops": "For i In {1:1e6}\nFor j In {1:1e6}\nEndFor\nEndFor\n",
    "macro_calls_itself": "Macro M\n  Call M;\nReturn\nCall M;\n",
    "point_flood": "For i In {1:5e7}\n  Point(1000 + i) = {i, 0, 0};\nEndFor\n",
}
FAST_DEADLINE = {"EMB_GEO_SECONDS": "3"}
for key, script in ENDLESS_GEO.items():
    case(f"geo_endless_{key}", "geo", ["mesh", "part.geo", "-q"], 1,
         ["refusing", "part.geo", "still reading"], [("write", "part.geo", script + BOX)],
         timeout=40, env=FAST_DEADLINE)
case("geo_endless_reduce", "geo", ["reduce", "part.geo", "-q", "-o", "b.h5"], 1,
     ["refusing", "still reading"],
     [("write", "part.geo", ENDLESS_GEO["loop_1e12"] + BOX)], absent=["b.h5"], timeout=40,
     env=FAST_DEADLINE)
case("geo_endless_beam_part", "geo", ["run", "s.yaml", "-q", "-o", "r.h5"], 1,
     ["refusing", "part.geo", "still reading"],
     [("write", "part.geo", ENDLESS_GEO["macro_calls_itself"] + BOX),
      ("write", "s.yaml", "bodies:\n  - {name: crank, model: beam, geometry: part.geo}\n"
                          "analysis: {type: assemble}\n")], absent=["r.h5"], timeout=40,
     env=FAST_DEADLINE)
for key, value in {"text": "soon", "zero": "0", "negative": "-5", "nan": "nan"}.items():
    case(f"geo_deadline_env_{key}", "geo", ["mesh", "{fix}/bar.geo", "-q"], 1,
         ["EMB_GEO_SECONDS"], env={"EMB_GEO_SECONDS": value})
case("geo_set_on_mesh_file", "geo", ["mesh", "{fix}/bar.msh", "-q", "--set", "h=1"], 1,
     ["parameters can only be set"])
case("geo_beam_parts_for_mesh", "geo", ["mesh", "{src}/meshes/tube.geo", "-q", "--set",
                                        "beam_parts=1"], 1, ["beam generator"])

# --- mesh files -------------------------------------------------------------------------

MSH2_HEAD = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
TET_NODES = "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n"


def msh2(nodes, elements):
    n = len(elements)
    return (MSH2_HEAD + nodes + f"$Elements\n{n}\n" + "".join(e + "\n" for e in elements)
            + "$EndElements\n")


MESHES = {
    "empty": ("", 1, []),
    "header_only": (MSH2_HEAD, 1, ["no volume elements"]),
    "nodes_only": (MSH2_HEAD + TET_NODES, 1, ["no volume elements"]),
    "surface_only": (msh2(TET_NODES, ["1 2 2 1 1 1 2 3"]), 1, ["no volume elements"]),
    "inverted_tet": (msh2(TET_NODES, ["1 4 2 1 1 1 3 2 4"]), 1, ["inverted"]),
    "degenerate_tet": (msh2("$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 2 0 0\n4 3 0 0\n$EndNodes\n",
                            ["1 4 2 1 1 1 2 3 4"]), 1, ["Jacobian"]),
    "nan_coordinate": (msh2("$Nodes\n4\n1 0 0 0\n2 nan 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n",
                            ["1 4 2 1 1 1 2 3 4"]), 1, ["non-finite"]),
    "inf_coordinate": (msh2("$Nodes\n4\n1 0 0 0\n2 inf 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n",
                            ["1 4 2 1 1 1 2 3 4"]), 1, []),
    "missing_node": (msh2(TET_NODES, ["1 4 2 1 1 1 2 3 99"]), 1, []),
    "pyramid": (msh2("$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 .5 .5 1\n$EndNodes\n",
                     ["1 7 2 1 1 1 2 3 4 5"]), 1, ["unsupported element type"]),
    "truncated_elements": (MSH2_HEAD + TET_NODES + "$Elements\n5\n1 4 2 1 1 1 2 3 4\n", 1, []),
    "negative_count": (MSH2_HEAD + "$Nodes\n-4\n$EndNodes\n", 1, []),
    "huge_count": (MSH2_HEAD + "$Nodes\n999999999999\n1 0 0 0\n$EndNodes\n", 1, []),
    "bad_version": ("$MeshFormat\n99.0 0 8\n$EndMeshFormat\n" + TET_NODES, 1, []),
    "text_garbage": ("$MeshFormat\nhello world\n", 1, []),
    "duplicate_node_moved": (msh2("$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n2 5 5 5\n"
                                  "$EndNodes\n", ["1 4 2 1 1 1 2 3 4"]), 1, ["node 2", "twice"]),
    "duplicate_element": (msh2(TET_NODES, ["1 4 2 1 1 1 2 3 4", "1 4 2 1 1 1 2 4 3"]), 1,
                          ["element", "twice"]),
    # Both elements valid: gmsh keeps the second silently (two different parts of the file).
    "duplicate_element_both_valid": (msh2("$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n"
                                          "5 1 1 1\n$EndNodes\n",
                                          ["1 4 2 1 1 1 2 3 4", "1 4 2 1 1 2 3 4 5"]), 1,
                                     ["element", "twice"]),
}
for key, (text, code, frags) in MESHES.items():
    case(f"mesh_{key}", "mesh", ["mesh", "part.msh", "-q"], code, frags,
         [("write", "part.msh", text)], timeout=30)
# A valid tetrahedron whose node numbers are sparse up to 10^12 (memory followed the tag).
case("mesh_sparse_huge_tags_ok", "mesh", ["mesh", "part.msh", "-q"], 0, [],
     [("write", "part.msh", msh2("$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n1000000000000 0 0 1\n"
                                 "$EndNodes\n", ["1 4 2 1 1 1 2 3 1000000000000"]))], timeout=30)
case("mesh_modes_more_than_dofs", "mesh",
     ["modes", "part.msh", "-q", "--modes", "50", "--no-output"], 1, ["degrees of freedom"],
     [("write", "part.msh", msh2(TET_NODES, ["1 4 2 1 1 1 2 3 4"]))])
case("mesh_fixed_unknown_group", "mesh",
     ["modes", "{fix}/bar.msh", "-q", "--fixed", "nope", "--no-output"], 1, ["nope"])
for key, (ext, data) in {"unv": (".unv", b"garbage\n-1\n2411\n"),
                         "bdf": (".bdf", b"GRID garbage\n"), "nas": (".nas", b"\x00\x01\x02"),
                         "step": (".step", b"ISO-10303-21;\ngarbage\n"),
                         "brep": (".brep", b"DBRep_DrawableShape\n\x00garbage"),
                         "stl": (".stl", b"solid x\nendsolid x\n"),
                         "vtk": (".vtk", b"# vtk DataFile Version 2.0\nx\nASCII\n"),
                         "mesh_ext": (".mesh", b"MeshVersionFormatted 2\nDimension\n3\nEnd\n"),
                         "msh_binary_garbage": (".msh", b"$MeshFormat\n4.1 1 8\n\x01\x00\x00")
                         }.items():
    case(f"mesh_garbage_{key}", "mesh", ["mesh", "part" + ext, "-q"], 1, [],
         [("writeb", "part" + ext, b64(data))], timeout=30)
case("mesh_missing_file", "mesh", ["mesh", "nowhere.msh", "-q"], 1, ["does not exist"])
case("mesh_directory", "mesh", ["mesh", "adir.msh", "-q"], 1, ["not a regular file"],
     [("mkdir", "adir.msh")])
case("mesh_fifo", "mesh", ["mesh", "pipe.msh", "-q"], 1, ["not a regular file"],
     [("fifo", "pipe.msh")], timeout=10)
case("mesh_dev_zero", "mesh", ["mesh", "/dev/zero", "-q"], 1, ["not a regular file"], timeout=10)
case("mesh_symlink_loop", "mesh", ["mesh", "loop.msh", "-q"], 1, [],
     [("symlink", "loop.msh", "loop.msh")])
case("mesh_size_estimate_refused", "mesh", ["mesh", "{src}/meshes/crankshaft_i4.geo", "-q",
                                            "--size", "0.0001"], 1, ["elements", "--force"],
     timeout=30)
case("mesh_size_estimate_refused_modes", "mesh",
     ["modes", "{fix}/bar.geo", "-q", "--size", "1e-5", "-o", "out.h5"], 1, ["--force"],
     absent=["out.h5"], timeout=30)

# --- command-line values ----------------------------------------------------------------

BAD_NUMBERS = {"nan": "nan", "inf": "inf", "neg": "-1", "zero": "0", "huge": "1e400"}


def cli_values(prefix, base, option, values, code=1, frag=None, extra_setup=(), timeout=30):
    for key, value in values.items():
        case(f"cli_{prefix}_{option.strip('-').replace('-', '_')}_{key}", "cli",
             [*base, option, value], code if not isinstance(code, dict) else code[key],
             [frag or option], list(extra_setup), absent=["out.h5", "out.csv"], timeout=timeout)


MODES = ["modes", "{fix}/bar.geo", "-q", "-o", "out.h5"]
cli_values("modes", MODES, "--modes", {"zero": "0", "neg": "-3"})
cli_values("modes", MODES, "--modes", {"text": "abc", "float": "1.5"}, code=2, frag="--modes")
cli_values("modes", MODES, "--shift-hz", {"nan": "nan", "inf": "inf"})
cli_values("modes", MODES, "--tol", {**BAD_NUMBERS, "one": "1"})
cli_values("modes", MODES, "--ncv", {"neg": "-5"})
cli_values("modes", MODES, "--max-restarts", {"zero": "0", "neg": "-1"})
cli_values("modes", MODES, "--size", {"nan": "nan", "neg": "-0.1", "inf": "inf"})
cli_values("modes", MODES, "--order", {"three": "3", "zero": "0"}, code=2)
cli_values("modes", MODES, "--E", BAD_NUMBERS, frag="Young")
cli_values("modes", MODES, "--nu", {"nan": "nan", "half": "0.5", "neg_one": "-1"}, frag="Poisson")
cli_values("modes", MODES, "--rho", {"nan": "nan", "zero": "0", "neg": "-7850"}, frag="ensity")
cli_values("modes", MODES, "--backend", {"bad": "lapack"}, code=2)
cli_values("modes", MODES, "--method", {"bad": "qr"}, code=2)

REDUCE = ["reduce", "{fix}/bar.geo", "-q", "-i", "x0", "-o", "out.h5"]
cli_values("reduce", REDUCE, "--modes", {"neg": "-1"})
cli_values("reduce", REDUCE, "--fmax", {"nan": "nan", "zero": "0", "neg": "-5", "inf": "inf"})
cli_values("reduce", REDUCE, "--band", {"nan": "nan", "zero": "0"})
cli_values("reduce", REDUCE, "--band-factor", {"half": "0.5", "nan": "nan"})
cli_values("reduce", REDUCE, "--check-fmax", {"neg": "-1", "nan": "nan"})
cli_values("reduce", REDUCE, "--damping-ratio", {"neg": "-0.1", "nan": "nan", "two": "2"})
cli_values("reduce", REDUCE, "--rayleigh", {"one_value": "1", "nan": "nan,1", "neg": "-1,0"})
cli_values("reduce", REDUCE, "--tol", {"zero": "0", "nan": "nan"})
cli_values("reduce", REDUCE, "--shift-hz", {"nan": "nan"})
cli_values("reduce", ["reduce", "{fix}/bar.geo", "-q", "-o", "out.h5"], "-i",
           {"bad_coupling": "x0:rbe9", "unknown_group": "nowhere", "bad_point": "x0@1,2",
            "nan_point": "x0@nan,0,0", "empty": ""}, frag="interface")
case("cli_reduce_modes_and_fmax", "cli", [*REDUCE, "--modes", "4", "--fmax", "100"], 1,
     ["one of"], absent=["out.h5"])
case("cli_reduce_free_free_and_interface", "cli", [*REDUCE, "--free-free"], 1, ["--free-free"],
     absent=["out.h5"])
case("cli_reduce_unknown_stiffening_support", "cli",
     [*REDUCE, "--stiffening-supports", "nope", "--no-reference"], 1, ["nope"],
     absent=["out.h5"])

RUN = ["run", "{fix}/pendulum.yaml", "-q", "-o", "out.h5"]
cli_values("run", RUN, "--t-end", {"nan": "nan", "inf": "inf", "before_start": "-1"})
cli_values("run", RUN, "--dt", {**BAD_NUMBERS})
cli_values("run", RUN, "--rtol", {**BAD_NUMBERS, "one": "1"})
cli_values("run", RUN, "--atol", {"nan": "nan", "zero": "0", "neg": "-1e-8", "inf": "inf"})
cli_values("run", RUN, "--analysis", {"bad": "transient"}, frag="analysis")
cli_values("run", RUN, "--linear-solver", {"bad": "lu"}, frag="linear solver")
case("cli_run_many_samples_refused", "cli", [*RUN, "--t-end", "1e6", "--dt", "1e-3"], 1,
     ["samples", "--force"], absent=["out.h5"])
case("cli_run_huge_output_refused", "cli", [*RUN, "--t-end", "1e3", "--dt", "1e-4"], 1,
     ["--force"], absent=["out.h5"])
case("cli_run_tiny_dt_refused", "cli", [*RUN, "--dt", "1e-300"], 1, ["--force"],
     absent=["out.h5"])
# Forced, the output times are made as the run goes (not all up front: 10^12 of them would
# not fit in memory): the run starts at once and stops on SIGINT with its file marked.
case("cli_run_forced_huge_samples_runs", "cli",
     ["run", "{fix}/pendulum.yaml", "-q", "-o", "r.h5", "--t-end", "1e9", "--dt", "1e-3",
      "--force"], "signal", [], signal={"sig": "INT", "when": "exists:r.h5", "delay": 1.0},
     h5_attr=[("r.h5", "status", "interrupted")], timeout=30)
case("cli_run_forced_dt_below_resolution", "cli",
     ["run", "{fix}/pendulum.yaml", "-q", "-o", "r.h5", "--t-end", "1e15", "--dt", "1e-300",
      "--force"], 1, ["output_step", "output times"], absent=["r.h5"], timeout=30)
case("cli_run_forced_too_many_times", "cli",
     ["run", "{fix}/pendulum.yaml", "-q", "--no-output", "--t-end", "1e300", "--dt", "1e-3",
      "--force"], 1, ["2^53"], timeout=30)
case("cli_run_no_output_samples_refused", "cli",
     ["run", "{fix}/pendulum.yaml", "-q", "--no-output", "--t-end", "1e9"], 1, ["samples"])
DOF = ["dof", "{fix}/pendulum.yaml", "-q"]
cli_values("dof", DOF, "--rank-tol", {"zero": "0", "neg": "-1", "nan": "nan", "one": "1"})
SPECTRUM = ["spectrum", "{fix}/disc.h5", "-q", "--channel", "disc.omega.x"]
cli_values("spectrum", [*SPECTRUM, "--angle", "disc"], "--cycles", {"neg": "-1", "many": "99"},
           frag="cycle")
cli_values("spectrum", [*SPECTRUM, "--angle", "disc"], "--orders",
           {"neg": "-1", "nan": "nan", "third": "0.3", "too_high": "1000"}, frag="order")
cli_values("spectrum", [*SPECTRUM, "--angle", "disc"], "--samples-per-cycle",
           {"zero": "0", "four": "4"})
cli_values("spectrum", [*SPECTRUM, "--angle", "disc"], "--angle-start", {"nan": "nan"})
cli_values("spectrum", SPECTRUM, "--rpm", {"zero": "0", "neg": "-3000", "nan": "nan"})
cli_values("spectrum", [*SPECTRUM, "--angle", "disc"], "--axis", {"w": "w"}, frag="axis")
SWEEP = ["sweep", "{src}/tests/sweep/data/one_cylinder_direct.yaml", "-q", "-o", "out.h5"]
cli_values("sweep", SWEEP, "--rpm", {"zero": "0", "neg": "-3000", "nan": "nan", "text": "abc",
                                     "range_down": "3000:1000:100", "step_zero": "1:5:0",
                                     "repeated": "1000,1000", "too_many": "0:1e9:1",
                                     "empty_item": "1000,,2000", "huge": "1e308",
                                     "tiny": "1e-300"}, frag="--rpm")
cli_values("sweep", [*SWEEP, "--rpm", "3000"], "--orders",
           {"third": "0.3", "zero": "0", "too_high": "1000", "text": "x"}, frag="order")
cli_values("sweep", [*SWEEP, "--rpm", "3000"], "--shard",
           {"k_eq_n": "2/2", "no_slash": "1", "neg": "-1/2", "text": "a/b"}, frag="--shard")
cli_values("sweep", [*SWEEP, "--rpm", "3000"], "-j", {"zero": "0", "neg": "-2"}, frag="-j")
cli_values("sweep", [*SWEEP, "--rpm", "3000"], "--channels", {"unknown": "nope.T.z"},
           frag="nope.T.z")
case("cli_sweep_no_rpm_motion", "cli",
     ["sweep", "{fix}/pendulum.yaml", "-q", "--rpm", "1000", "-o", "out.h5"], 1,
     ["no motion with function {rpm"], absent=["out.h5", "out.h5.points"])
case("cli_sweep_no_rpm_option", "cli", SWEEP, 1, ["--rpm"], absent=["out.h5"])
case("cli_sweep_shard_auto_without_environment", "cli", [*SWEEP, "--rpm", "3000", "--shard",
     "auto"], 1, ["no shard in the environment"], absent=["out.h5"])
case("cli_sweep_merge_not_a_sweep_file", "cli",
     ["sweep", "--merge", "{fix}/pendulum.h5", "-o", "out.h5", "-q"], 1, ["not a sweep file"],
     absent=["out.h5"])
case("cli_sweep_merge_without_output", "cli", ["sweep", "--merge", "{fix}/pendulum.h5", "-q"], 1,
     ["-o"])
# Issue 36: a sweep or point file edited after emb wrote it (another speed, other amplitudes)
# is refused by its content digest, not merged or resumed; one of the older format is named.
for key, mutation, frags in (
        ("amplitude", ["scale", "/amplitude", "0", "123.0"], ["changed after emb wrote it"]),
        ("speed", ["scale", "/rpm", "0", "3100"], ["changed after emb wrote it"]),
        ("no_digest", ["del_attr", "/", "content_digest"], ["content_digest"]),
        ("old_version", ["set_attr", "/", "version", "1", "int"], ["version 1", "older emb"])):
    case(f"cli_sweep_merge_edited_{key}", "cli",
         ["sweep", "--merge", "s.h5", "-o", "out.h5", "-q"], 1, ["s.h5", *frags],
         [("h5", "{fix}/sweep.h5", "s.h5", *mutation)], absent=["out.h5"])
case("cli_runup_unknown_angle", "cli",
     ["runup", "{fix}/disc.h5", "--angle", "crank", "--channels", "disc.omega.x", "-o", "out.h5",
      "-q"], 1, ["crank"], absent=["out.h5"])
case("cli_runup_unknown_channel", "cli",
     ["runup", "{fix}/disc.h5", "--angle", "disc", "--channels", "disk.omega.x", "-o", "out.h5",
      "-q"], 1, ["disk"], absent=["out.h5"])
case("cli_spectrum_angle_and_rpm", "cli", [*SPECTRUM, "--angle", "disc", "--rpm", "3000"], 1,
     ["exactly one"])
case("cli_spectrum_neither", "cli", SPECTRUM, 1, ["exactly one"])
case("cli_spectrum_unknown_channel", "cli",
     ["spectrum", "{fix}/disc.h5", "-q", "--channel", "disk.omega.x", "--angle", "disc"], 1,
     ["disk"])
case("cli_spectrum_malformed_channel", "cli",
     ["spectrum", "{fix}/disc.h5", "-q", "--channel", "....", "--angle", "disc"], 1, [])
case("cli_spectrum_unknown_angle_body", "cli", [*SPECTRUM, "--angle", "crank"], 1, ["crank"])
case("cli_spectrum_too_short", "cli",
     ["spectrum", "{fix}/pendulum.h5", "-q", "--channel", "rod.p.x", "--rpm", "60"], 1,
     ["cycle"])
COMPARE = ["compare", "{fix}/bar.geo", "-q"]
cli_values("compare", COMPARE, "--element-length", {"zero": "0", "nan": "nan"})
cli_values("compare", COMPARE, "--web-width", {"neg": "-1", "nan": "nan"})
cli_values("compare", COMPARE, "--tmm-band", {"one": "1", "nan": "nan,5", "reversed": "5,1"})
cli_values("compare", COMPARE, "--stations", {"one": "1"})
cli_values("compare", COMPARE, "--scan-intervals", {"zero": "0"})
cli_values("compare", COMPARE, "--shell-threshold", {"zero": "0", "one": "1", "nan": "nan"})
cli_values("compare", COMPARE, "--cms", {"neg": "-1"})
cli_values("compare", COMPARE, "--modes", {"zero": "0"})
cli_values("compare", COMPARE, "--support", {"bad": "clamped"}, code=2)
cli_values("compare", COMPARE, "--webs", {"bad": "hollow"}, code=2)
case("cli_compare_report_dir_missing", "cli", [*COMPARE, "--report-dir", "nowhere"], 1,
     ["nowhere"])
case("cli_inspect_missing", "cli", ["inspect", "nowhere.h5", "-q"], 1, ["nowhere.h5"])
case("cli_inspect_wrong_hash", "cli",
     ["inspect", "{fix}/body.h5", "-q", "--expect-mesh-hash", "0123"], 1, ["stale"])
# An empty path (an unset shell variable) is no path: refused, not "no option".
for key, cmd in {"run_o": ["run", "{fix}/pendulum.yaml", "-q", "-o", ""],
                 "run_csv": ["run", "{fix}/pendulum.yaml", "-q", "--no-output", "--csv", ""],
                 "modes_o": ["modes", "{fix}/bar.geo", "-q", "-o", ""],
                 "reduce_o": ["reduce", "{fix}/bar.geo", "-q", "-i", "x0", "-o", ""],
                 "save_mesh": ["mesh", "{fix}/bar.geo", "-q", "--save-mesh", ""],
                 "spectrum_csv": ["spectrum", "{fix}/disc.h5", "-q", "--channel", "disc.omega.x",
                                  "--angle", "disc", "--csv", ""],
                 "report_dir": ["compare", "{fix}/bar.geo", "-q", "--report-dir", ""]}.items():
    case(f"cli_empty_path_{key}", "cli", cmd, 2, ["empty"], timeout=30)
case("cli_unknown_subcommand", "cli", ["nonsense"], 2, ["unknown subcommand"])
case("cli_no_subcommand", "cli", [], 2, [])
case("cli_unknown_option", "cli", ["modes", "{fix}/bar.geo", "--frobnicate"], 2, [])
case("cli_missing_argument", "cli", ["modes"], 2, [])
case("cli_option_without_value", "cli", ["modes", "{fix}/bar.geo", "--tol"], 2, [])

# --- scenes -----------------------------------------------------------------------------

# Fixtures, made once per corpus run by run_corpus.py with the emb under test.
BAR_GEO = """SetFactory("OpenCASCADE");
DefineConstant[ h = {0.05, Name "Parameters/h"}, L = {0.5, Name "Parameters/L"} ];
Box(1) = {0, 0, 0, L, 0.05, 0.05};
Physical Surface("x0") = {1};
Physical Surface("x1") = {2};
Physical Volume("bar") = {1};
Mesh.MeshSizeMax = h;
"""
PENDULUM = """name: pendulum
gravity: [0, -9.81, 0]
bodies:
  - {name: rod, mass: 1.0, inertia: [1.0e-4, 0.083, 0.083], position: [0.5, 0, 0]}
markers:
  - {name: pivot, body: ground, position: [0, 0, 0]}
  - {name: rod_top, body: rod, position: [-0.5, 0, 0]}
joints:
  - {name: hinge, type: revolute, i: rod_top, j: pivot}
analysis: {type: dynamic, t_end: 0.1, output_step: 0.01}
"""
# A disc spun at 3000 rpm by a motion: two 720-degree cycles in 0.08 s (for emb spectrum).
DISC = """name: disc
bodies:
  - {name: disc, mass: 2.0, inertia: [0.01, 0.005, 0.005]}
markers:
  - {name: hub, body: ground, orientation: {z_axis: [1, 0, 0]}}
  - {name: disc_hub, body: disc, orientation: {z_axis: [1, 0, 0]}}
joints:
  - {name: bearing, type: revolute, i: disc_hub, j: hub}
motions:
  - {name: drive, joint: bearing, function: {rpm: 3000}}
analysis: {type: kinematic, t_end: 0.08, output_step: 0.0001}
"""
FIXTURES = {
    "files": {"bar.geo": BAR_GEO, "pendulum.yaml": PENDULUM, "disc.yaml": DISC,
              "one_cylinder.yaml": open(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                     "..", "sweep", "data",
                                                     "one_cylinder_direct.yaml")).read()},
    "commands": [["mesh", "bar.geo", "--save-mesh", "bar.msh"],
                 ["reduce", "bar.geo", "-i", "x0", "-i", "x1:rbe3", "-n", "4", "--no-reference",
                  "--no-xdmf", "-o", "body.h5"],
                 ["run", "pendulum.yaml", "-o", "pendulum.h5"],
                 ["run", "disc.yaml", "-o", "disc.h5"],
                 ["sweep", "one_cylinder.yaml", "--rpm", "3000", "-o", "sweep.h5"],
                 ["reduce", "bar.geo", "-i", "x0", "-n", "4", "--no-reference", "--no-xdmf",
                  "--stress-groups", "x1", "-o", "stress_body.h5"]],
}


def scene(name, text, code=1, frags=(), extra=(), args=(), setup=(), absent=("out.h5",),
          category="scene", **kw):
    case(f"scene_{name}", category, ["run", "s.yaml", "-q", "-o", "out.h5", *args], code,
         frags, [("write", "s.yaml", text), *setup, *extra],
         absent=list(absent) if code != 0 else [], **kw)


def replaced(old, new, text=PENDULUM):
    assert old in text, old
    return text.replace(old, new, 1)


ANALYSIS_BAD = {
    "t_start": {"nan": ".nan", "inf": ".inf", "text": "soon"},
    "t_end": {"nan": ".nan", "inf": ".inf", "before_start": "-1"},
    "output_step": {"nan": ".nan", "zero": "0", "neg": "-0.01", "inf": ".inf"},
    "rtol": {"zero": "0", "neg": "-1e-6", "nan": ".nan", "one": "1"},
    "atol": {"zero": "0", "neg": "-1", "nan": ".nan"},
    "atol_floor_relative": {"neg": "-1", "nan": ".nan"},
    "initial_step_fraction": {"neg": "-1", "two": "2"},
    "multiplier_atol": {"neg": "-1", "nan": ".nan"},
    "multiplier_atol_relative": {"zero": "0", "nan": ".nan"},
    "multiplier_atol_rtol_factor": {"zero": "0", "neg": "-1", "nan": ".nan", "huge": "1e9"},
    "max_step": {"neg": "-1", "nan": ".nan"},
    "max_steps": {"neg": "-5", "zero": "0", "huge": "1e30", "fraction": "2.5"},
    "assembly_tolerance": {"zero": "0", "nan": ".nan"},
    "assembly_iterations": {"zero": "0", "neg": "-1", "huge": "1e12"},
    "static_tolerance": {"neg": "-1", "nan": ".nan"},
    "static_iterations": {"zero": "0", "huge": "1e20"},
    "remove_redundant": {"text": "maybe"},
    "modal_velocity_atol_by_frequency": {"number": "3"},
    "velocity_atol": {"neg": "-1", "nan": ".nan"},
    "stop_at_outputs": {"text": "maybe"},
    "newton_refreshes": {"neg": "-2", "huge": "11", "fraction": "1.5"},
    "linear_solver": {"bad": "lu"},
    "type": {"bad": "transient"},
}
for key, values in ANALYSIS_BAD.items():
    for vk, v in values.items():
        scene(f"analysis_{key}_{vk}", replaced("output_step: 0.01}", f"output_step: 0.01, {key}: {v}}}"),
              1, [key if key not in ("type", "linear_solver") else key.split("_")[0], "s.yaml:10"])
scene("analysis_huge_t_end", replaced("t_end: 0.1", "t_end: 1.0e9"), 1, ["samples", "--force"])
scene("analysis_tiny_output_step", replaced("output_step: 0.01", "output_step: 1.0e-12"), 1,
      ["--force"])
scene("analysis_not_a_map", replaced("analysis: {type: dynamic, t_end: 0.1, output_step: 0.01}",
                                     "analysis: [dynamic]"), 1, ["analysis"])

BODY_BAD = {
    "mass_neg": ("mass: 1.0", "mass: -1.0", ["mass"]),
    "mass_zero": ("mass: 1.0", "mass: 0", ["mass"]),
    "mass_nan": ("mass: 1.0", "mass: .nan", ["mass"]),
    "mass_text": ("mass: 1.0", "mass: heavy", ["mass"]),
    "inertia_neg": ("inertia: [1.0e-4, 0.083, 0.083]", "inertia: [-1.0e-4, 0.083, 0.083]", ["inertia"]),
    "inertia_triangle": ("inertia: [1.0e-4, 0.083, 0.083]", "inertia: [1.0, 0.1, 0.1]", ["inertia"]),
    "inertia_count": ("inertia: [1.0e-4, 0.083, 0.083]", "inertia: [1.0e-4, 0.083]", ["inertia"]),
    "inertia_nan": ("inertia: [1.0e-4, 0.083, 0.083]", "inertia: [.nan, 0.083, 0.083]", ["inertia"]),
    "position_nan": ("position: [0.5, 0, 0]", "position: [.nan, 0, 0]", ["position"]),
    "position_inf": ("position: [0.5, 0, 0]", "position: [.inf, 0, 0]", ["position"]),
    "position_count": ("position: [0.5, 0, 0]", "position: [0.5, 0]", ["position"]),
    "position_text": ("position: [0.5, 0, 0]", "position: here", ["position"]),
    "velocity_nan": ("position: [0.5, 0, 0]", "position: [0.5, 0, 0], velocity: [0, .nan, 0]", ["velocity"]),
    "omega_inf": ("position: [0.5, 0, 0]", "position: [0.5, 0, 0], angular_velocity: [0, 0, .inf]", ["angular_velocity"]),
    "quaternion_zero": ("position: [0.5, 0, 0]", "position: [0.5, 0, 0], orientation: {quaternion: [0, 0, 0, 0]}", ["quaternion"]),
    "quaternion_nan": ("position: [0.5, 0, 0]", "position: [0.5, 0, 0], orientation: {quaternion: [.nan, 0, 0, 1]}", ["quaternion"]),
    "euler_count": ("position: [0.5, 0, 0]", "position: [0.5, 0, 0], orientation: {euler313_deg: [1, 2]}", ["euler"]),
    "two_orientations": ("position: [0.5, 0, 0]", "position: [0.5, 0, 0], orientation: {quaternion: [1, 0, 0, 0], euler313_deg: [0, 0, 0]}", ["orientation"]),
    "z_axis_zero": ("position: [0.5, 0, 0]", "position: [0.5, 0, 0], orientation: {z_axis: [0, 0, 0]}", ["z_axis"]),
    "unknown_key": ("mass: 1.0", "mass: 1.0, colour: red", ["colour"]),
    "model_bad": ("mass: 1.0", "mass: 1.0, model: flexible", ["model"]),
    "cms_without_file": ("mass: 1.0", "mass: 1.0, model: cms", ["body_file"]),
    "duplicate_name": ("bodies:\n", "bodies:\n  - {name: rod, mass: 1.0, inertia: [1, 1, 1]}\n", ["rod"]),
    "ground_name": ("name: rod,", "name: ground,", ["ground"]),
}
for key, (old, new, frags) in BODY_BAD.items():
    scene(f"body_{key}", replaced(old, new), 1, frags)

MARKER_BAD = {
    "unknown_body": ("body: ground, position: [0, 0, 0]}", "body: nowhere, position: [0, 0, 0]}", ["nowhere"]),
    "position_nan": ("body: ground, position: [0, 0, 0]}", "body: ground, position: [0, .nan, 0]}", ["position"]),
    "frame_bad": ("body: ground, position: [0, 0, 0]}", "body: ground, frame: lab, position: [0, 0, 0]}", ["frame"]),
    "interface_on_rigid": ("body: ground, position: [0, 0, 0]}", "body: rod, interface: x0}", ["interface"]),
    "duplicate": ("  - {name: rod_top,", "  - {name: pivot, body: rod, position: [0, 0, 0]}\n  - {name: rod_top,", ["pivot"]),
}
for key, (old, new, frags) in MARKER_BAD.items():
    scene(f"marker_{key}", replaced(old, new), 1, frags)
JOINT_BAD = {
    "unknown_type": ("type: revolute", "type: hinge", ["hinge"]),
    "unknown_marker": ("i: rod_top", "i: rod_tip", ["rod_tip"]),
    "same_marker": ("j: pivot", "j: rod_top", []),
    "missing_type": ("type: revolute, ", "", ["type"]),
    "not_a_list": ("joints:\n  - {name: hinge, type: revolute, i: rod_top, j: pivot}", "joints: hinge", ["joints"]),
}
for key, (old, new, frags) in JOINT_BAD.items():
    scene(f"joint_{key}", replaced(old, new), 1, frags)

MOTION = "motions:\n  - {name: drive, joint: hinge, function: FUNC}\nanalysis:"
FUNCTION_BAD = {
    "two_kinds": ("{constant: 1, rpm: 60}", ["exactly one"]),
    "none": ("{}", ["exactly one"]),
    "rpm_nan": ("{rpm: .nan}", ["rpm"]),
    "constant_inf": ("{constant: .inf}", ["constant"]),
    "polynomial_empty": ("{polynomial: []}", ["polynomial"]),
    "polynomial_nan": ("{polynomial: [0, .nan]}", ["polynomial"]),
    "harmonic_negative_frequency": ("{harmonic: {amplitude: 1, frequency_hz: -1}}", ["frequency_hz"]),
    "harmonic_missing": ("{harmonic: {amplitude: 1}}", ["frequency_hz"]),
    "table_decreasing": ("{table: {x: [0, 2, 1], y: [0, 1, 2]}}", ["table"]),
    "table_lengths": ("{table: {x: [0, 1, 2], y: [0, 1]}}", ["table"]),
    "table_nan": ("{table: {x: [0, .nan, 2], y: [0, 1, 2]}}", ["table"]),
    "table_single_point": ("{table: {x: [0], y: [1]}}", ["table"]),
    "table_cubic_not_periodic": ("{table: {x: [0, 1, 2], y: [0, 1, 0], interpolation: cubic}}", ["cubic"]),
    "table_duplicate_x": ("{table: {x: [0, 1, 1, 2], y: [0, 1, 2, 3]}}", ["table"]),
    "unknown_kind": ("{sine: 1}", ["sine"]),
    "cylinder_step_tiny": ("{cylinder_pressure: {step_deg: 1.0e-9}}", ["step_deg"]),
    "cylinder_nan_bore": ("{cylinder_pressure: {bore: .nan}}", ["bore"]),
    "cylinder_both_targets": ("{cylinder_pressure: {heat_released: 1000, peak_pressure: 7.0e6}}", ["at most one"]),
    "cylinder_rod_short": ("{cylinder_pressure: {rod: 0.01}}", ["rod"]),
}
FUNCTION_BAD.update({
    "expression_syntax": ('{expression: "sin(t"}', ["expression"]),
    "expression_unknown_name": ('{expression: "omega*t"}', ["omega"]),
    "expression_assignment": ('{expression: "t = 3"}', ["assigns"]),
    "expression_two_results": ('{expression: "t, 2*t"}', ["one formula"]),
    "expression_empty": ('{expression: ""}', ["empty"]),
    "expression_not_text": ("{expression: [1, 2]}", ["expression"]),
    "expression_huge": ('{expression: "' + "1+" * 3000 + 't"}', ["at most"]),
    "expression_string_function": ('{expression: "strfun1(\\"x\\")"}', ["expression"]),
    "expression_constant_nan": ('{expression: "a*t", constants: {a: .nan}}', ["constant 'a'"]),
    "expression_constant_text": ('{expression: "a*t", constants: {a: fast}}', ["constant 'a'"]),
    "expression_constants_list": ('{expression: "t", constants: [1, 2]}', ["constants"]),
    "expression_constant_bad_name": ('{expression: "t", constants: {"2a": 1}}', ["name"]),
    "expression_constant_pi": ('{expression: "t", constants: {pi: 3}}', ["taken"]),
    "expression_constant_shadows_function": ('{expression: "t", constants: {sqrt: 3}}', ["constant 'sqrt'", "function sqrt()"]),
    "expression_scale_zero": ('{expression: "t", scale: 0}', ["scale"]),
    "expression_scale_nan": ('{expression: "t", scale: .nan}', ["scale"]),
    "constants_without_expression": ("{rpm: 60, constants: {a: 1}}", ["only with an expression"]),
    "scale_without_expression": ("{rpm: 60, scale: 0.1}", ["only with an expression"]),
    "expression_and_rpm": ('{expression: "t", rpm: 60}', ["exactly one"]),
})
for key, (func, frags) in FUNCTION_BAD.items():
    scene(f"function_{key}", replaced("analysis:", MOTION.replace("FUNC", func)), 1, frags)
scene("motion_unknown_joint", replaced("analysis:", MOTION.replace("FUNC", "{rpm: 60}").replace("hinge", "hinj")), 1, ["hinj"])
scene("motion_bad_coordinate", replaced("analysis:", "motions:\n  - {name: m, joint: hinge, coordinate: shear, function: {rpm: 60}}\nanalysis:"), 1, ["coordinate"])

FORCE = "forces:\n  - FORCE\nanalysis:"
FORCE_BAD = {
    "spring_negative_stiffness": ("{name: f, type: spring-damper, i: rod_top, j: pivot, stiffness: -100}", ["stiffness"]),
    "spring_nan_damping": ("{name: f, type: spring-damper, i: rod_top, j: pivot, damping: .nan}", ["damping"]),
    "spring_negative_length": ("{name: f, type: spring-damper, i: rod_top, j: pivot, free_length: -1}", ["free_length"]),
    "rotational_nan_angle": ("{name: f, type: rotational-spring-damper, i: rod_top, j: pivot, free_angle: .nan}", ["free_angle"]),
    "bushing_not_6x6": ("{name: f, type: bushing, i: rod_top, j: pivot, stiffness: [1, 2, 3]}", ["stiffness"]),
    "bushing_nan": ("{name: f, type: bushing, i: rod_top, j: pivot, stiffness: [.nan, 1, 1, 1, 1, 1]}", ["stiffness"]),
    "bushing_negative_factor": ("{name: f, type: bushing, i: rod_top, j: pivot, stiffness: [1, 1, 1, 1, 1, 1], damping_factor: -1}", ["damping_factor"]),
    "bearing_clearance_too_big": ("{name: f, type: journal-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 0.03, viscosity: 0.01}", ["clearance"]),
    "bearing_zero_viscosity": ("{name: f, type: journal-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 1.0e-5, viscosity: 0}", ["viscosity"]),
    "bearing_too_long": ("{name: f, type: journal-bearing, i: rod_top, j: pivot, radius: 0.02, length: 1.0, clearance: 1.0e-5, viscosity: 0.01}", ["L/D"]),
    "bearing_nan_radius": ("{name: f, type: journal-bearing, i: rod_top, j: pivot, radius: .nan, length: 0.02, clearance: 1.0e-5, viscosity: 0.01}", ["radius"]),
    # Issue 30: the finite-width film bearing.
    "film_zero_clearance": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 0, viscosity: 0.01}", ["clearance"]),
    "film_clearance_too_big": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 0.03, viscosity: 0.01}", ["bearing 'f'", "clearance"]),
    "film_negative_viscosity": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 2.0e-5, viscosity: -0.01}", ["viscosity"]),
    "film_coarse_grid": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 2.0e-5, viscosity: 0.01, grid_circumferential: 4}", ["grid_circumferential"]),
    "film_bad_cavitation": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 2.0e-5, viscosity: 0.01, cavitation: elrod}", ["cavitation", "elrod"]),
    "film_hole_outside": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 2.0e-5, viscosity: 0.01, oil_holes: [{angle: 1.0, axial_position: 0.012, diameter: 0.004, supply_pressure: 3.0e5}]}", ["bearing 'f'", "oil_holes[0]"]),
    "film_negative_supply": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 2.0e-5, viscosity: 0.01, oil_holes: [{angle: 1.0, diameter: 0.004, supply_pressure: -1}]}", ["supply_pressure"]),
    "film_groove_too_narrow": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 2.0e-5, viscosity: 0.01, grooves: [{width: 1.0e-5, axial_position: 0.001, supply_pressure: 3.0e5}]}", ["bearing 'f'", "grooves[0]"]),
    "film_zero_bulk_modulus": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 2.0e-5, viscosity: 0.01, bulk_modulus: 0}", ["bulk_modulus"]),
    "film_hole_unknown_key": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 2.0e-5, viscosity: 0.01, oil_holes: [{angle: 1.0, diameter: 0.004, supply_pressure: 3.0e5, diam: 1}]}", ["diam"]),
    "film_switch_width_too_wide": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 2.0e-5, viscosity: 0.01, switch_width: 0.7}", ["switch_width", "0.5"]),
    "film_contact_without_roughness": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 2.0e-5, viscosity: 0.01, asperity_contact: {composite_modulus: 2.2e11}}", ["asperity_contact", "roughness"]),
    "film_contact_bad_function": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 2.0e-5, viscosity: 0.01, asperity_contact: {roughness: 4.0e-7, composite_modulus: 2.2e11, function: greenwood}}", ["function", "greenwood"]),
    "film_journal_hole_outside": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 2.0e-5, viscosity: 0.01, journal_oil_holes: [{angle: 0.0, axial_position: 0.009, diameter: 0.004, supply_pressure: 3.0e5}]}", ["journal_oil_holes[0]", "outside"]),
    "film_journal_hole_negative_pressure": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 2.0e-5, viscosity: 0.01, journal_oil_holes: [{angle: 0.0, diameter: 0.004, supply_pressure: -1.0e5}]}", ["supply_pressure", ">= 0"]),
    "film_journal_feed_ratio_zero": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 2.0e-5, viscosity: 0.01, journal_feed_ratio: 0}", ["journal_feed_ratio"]),
    "film_viscosity_and_lubricant": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 2.0e-5, viscosity: 0.01, lubricant: {viscosity: 0.01}}", ["viscosity", "lubricant", "both"]),
    "film_lubricant_celsius": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 2.0e-5, lubricant: {temperature_law: walther, nu_40: 7.0e-5, nu_100: 1.1e-5, density: 850, temperature: 110}}", ["temperature", "[200, 600]"]),
    "film_lubricant_bad_law": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 2.0e-5, lubricant: {temperature_law: arrhenius, viscosity: 0.01}}", ["temperature_law", "arrhenius"]),
    "film_lubricant_vogel_below_c": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 2.0e-5, lubricant: {temperature_law: vogel, vogel_a: 6.0e-5, vogel_b: 900, vogel_c: 400, temperature: 380}}", ["'f'", "temperature", "380"]),
    "film_bore_tilt_beyond_clearance": ("{name: f, type: film-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02, clearance: 2.0e-5, viscosity: 0.01, bore_tilt: [0.003, 0.0]}", ["'f'", "bore_tilt"]),
    "load_zero_direction": ("{name: f, type: force, marker: rod_top, direction: [0, 0, 0], function: {constant: 1}}", ["direction"]),
    "load_bad_frame": ("{name: f, type: force, marker: rod_top, frame: body, direction: [1, 0, 0], function: {constant: 1}}", ["frame"]),
    "load_unknown_marker": ("{name: f, type: torque, marker: nowhere, direction: [1, 0, 0], function: {constant: 1}}", ["nowhere"]),
    "load_bad_argument_unit": ("{name: f, type: torque, marker: rod_top, direction: [0, 0, 1], function: {constant: 1}, argument: {joint: hinge, unit: grad}}", ["unit"]),
    "load_argument_unknown_joint": ("{name: f, type: torque, marker: rod_top, direction: [0, 0, 1], function: {constant: 1}, argument: {joint: nowhere}}", ["nowhere"]),
    "unknown_type": ("{name: f, type: magnet, i: rod_top, j: pivot}", ["magnet"]),
}
for key, (force, frags) in FORCE_BAD.items():
    scene(f"force_{key}", replaced("analysis:", FORCE.replace("FORCE", force)), 1, frags)
scene("coupler_unknown_joint", replaced("analysis:", "couplers:\n  - {name: c, joint1: hinge, joint2: nowhere, ratio: 2}\nanalysis:"), 1, ["nowhere"])
scene("coupler_nan_ratio", replaced("analysis:", "couplers:\n  - {name: c, joint1: hinge, joint2: hinge, ratio: .nan}\nanalysis:"), 1, ["ratio"])
# Issue 36: a ratio of 0 and a coordinate coupled with itself (a coupler, a lash).
scene("coupler_zero_ratio", replaced("analysis:", "couplers:\n  - {name: c, joint1: hinge, joint2: hinge, ratio: 0}\nanalysis:"), 1, ["coupler 'c'", "non-zero ratio"])
scene("coupler_same_coordinate", replaced("analysis:", "couplers:\n  - {name: c, joint1: hinge, joint2: hinge, ratio: 2}\nanalysis:"), 1, ["coupler 'c'", "same coordinate of joint 'hinge'"])
LASH_CONTACT = "contact: {law: hunt-crossley, stiffness: 1.0e5, exponent: 1.0, restitution: 0.5}"
scene("lash_zero_ratio", replaced("analysis:", "forces:\n  - {name: l, type: lash, joint1: hinge, joint2: hinge, ratio: 0, lash: 0.01, " + LASH_CONTACT + "}\nanalysis:"), 1, ["lash 'l'", "non-zero"])
scene("lash_same_coordinate", replaced("analysis:", "forces:\n  - {name: l, type: lash, joint1: hinge, joint2: hinge, ratio: 2, lash: 0.01, " + LASH_CONTACT + "}\nanalysis:"), 1, ["lash 'l'", "same coordinate"])
scene("sensor_unknown_marker", replaced("analysis:", "sensors:\n  - {name: s, i: rod_top, j: nowhere}\nanalysis:"), 1, ["nowhere"])
# Issue 36: channels are <owner>.<quantity>, so owners share one namespace.
scene("sensor_named_like_joint", replaced("analysis:", "sensors:\n  - {name: hinge, i: rod_top, j: pivot}\nanalysis:"), 1, ["sensor 'hinge'", "joint or coupler 'hinge'", "distinct names"])
scene("sensor_named_like_body", replaced("analysis:", "sensors:\n  - {name: rod, i: rod_top, j: pivot}\nanalysis:"), 1, ["sensor 'rod'", "body 'rod'"])
scene("sensor_named_energy", replaced("analysis:", "sensors:\n  - {name: energy, i: rod_top, j: pivot}\nanalysis:"), 1, ["sensor 'energy'", "the energy channels"])
scene("sensor_chord_one_end", replaced("analysis:", "sensors:\n  - {name: s, type: chord, point: rod_top, chord: [pivot]}\nanalysis:"), 1, ["sensor 's'", "chord", "two markers"])
scene("sensor_chord_point_on_chord", replaced("analysis:", "sensors:\n  - {name: s, type: chord, point: pivot, chord: [pivot, rod_top]}\nanalysis:"), 1, ["three different markers"])
scene("sensor_type_unknown", replaced("analysis:", "sensors:\n  - {name: s, type: cord, point: pivot, chord: [pivot, rod_top]}\nanalysis:"), 1, ["'cord'", "chord"])

TOP_BAD = {
    "duplicate_top_key": (PENDULUM + "gravity: [0, 0, -9.81]\n", ["gravity", "given twice"]),
    "duplicate_nested_key": (replaced("mass: 1.0,", "mass: 1.0, mass: 2.0,"), ["mass", "given twice"]),
    "duplicate_analysis_key": (replaced("t_end: 0.1,", "t_end: 0.1, t_end: 100,"), ["t_end", "given twice"]),
    "unknown_top_key": (PENDULUM + "solver: ida\n", ["solver"]),
    "typo_top_key": (replaced("joints:", "jionts:"), ["jionts", "joints"]),
    "empty": ("", ["scene"]),
    "not_a_map": ("- a\n- b\n", ["scene"]),
    "scalar": ("hello\n", ["scene"]),
    "syntax_error": ("bodies: [\n  {name: a", ["YAML syntax error"]),
    "tab_indent": ("bodies:\n\t- {name: a}\n", ["YAML"]),
    "no_bodies": ("name: x\n", ["bodies"]),
    "bodies_not_list": ("bodies: {name: a}\n", ["bodies"]),
    "gravity_nan": (replaced("gravity: [0, -9.81, 0]", "gravity: [0, .nan, 0]"), ["gravity"]),
    "gravity_count": (replaced("gravity: [0, -9.81, 0]", "gravity: [0, -9.81]"), ["gravity"]),
    "deep_nesting": ("bodies: " + "[" * 10000 + "]" * 10000 + "\n", []),
    "deep_block_nesting": ("".join(" " * i + "a:\n" for i in range(3000)), []),
    "alias_bomb": ("a: &a [x, x, x, x, x, x, x, x, x]\nb: &b [*a, *a, *a, *a, *a, *a, *a, *a, *a]\n"
                   "c: &c [*b, *b, *b, *b, *b, *b, *b, *b, *b]\nd: &d [*c, *c, *c, *c, *c, *c, *c, *c, *c]\n"
                   "e: &e [*d, *d, *d, *d, *d, *d, *d, *d, *d]\nf: &f [*e, *e, *e, *e, *e, *e, *e, *e, *e]\n"
                   "g: [*f, *f, *f, *f, *f, *f, *f, *f, *f]\n", []),
    "binary": ("\x01\x02\x03\xff", []),
    "redundant_constraints": (replaced("  - {name: hinge, type: revolute, i: rod_top, j: pivot}",
                                       "  - {name: hinge, type: revolute, i: rod_top, j: pivot}\n"
                                       "  - {name: hinge2, type: revolute, i: rod_top, j: pivot}"), ["redundant"]),
    "assembly_fails": (replaced("position: [0.5, 0, 0]", "position: [5, 3, 1]").replace(
        "analysis: {type: dynamic,", "analysis: {assembly_iterations: 1, assembly_tolerance: 1.0e-300, type: dynamic,"), ["assembl"]),
}
for key, (text, frags) in TOP_BAD.items():
    scene(f"top_{key}", text, 1, frags, timeout=30)

# Names that would make ambiguous channels ("<name>.<quantity>") or garbled lists.
for key, (old_text, new_text, frags) in {
        "body_with_dot": ("name: rod,", "name: rod.x,", ["rod.x", "'.'"]),
        "joint_with_dot": ("name: hinge,", "name: hinge.F,", ["hinge.F", "'.'"]),
        "body_with_space": ("name: rod,", "name: rod x,", ["rod x", "spaces"]),
        "body_with_newline": ("name: rod,", 'name: "ro\\nd",', ["spaces"]),
        "body_empty_name": ("name: rod,", 'name: "",', ["non-empty"]),
        "sensor_with_dot": ("analysis:", "sensors:\n  - {name: s.t, i: rod_top, j: pivot}\nanalysis:",
                            ["s.t"]),
        "force_with_dot": ("analysis:", "forces:\n  - {name: k.1, type: spring-damper, i: rod_top, "
                                        "j: pivot, stiffness: 10}\nanalysis:", ["k.1"]),
}.items():
    scene(f"name_{key}", replaced(old_text, new_text), 1, frags)

# Outputs named by the scene.
case("scene_output_absolute_outside", "scene", ["run", "s.yaml", "-q"], 1, ["outside"],
     [("write", "s.yaml", PENDULUM + "output: {file: /tmp/emb_corpus_escape.h5}\n")])
case("scene_output_dotdot_escape", "scene", ["run", "sub/s.yaml", "-q"], 1, ["outside"],
     [("write", "sub/s.yaml", PENDULUM + "output: {file: ../../escape.h5}\n")],
     absent=["escape.h5"])
case("scene_output_symlink_escape", "scene", ["run", "sub/s.yaml", "-q"], 1, ["outside"],
     [("mkdir", "outside"), ("mkdir", "sub/sub2"), ("symlink", "/tmp", "sub/link"),
      ("write", "sub/s.yaml", PENDULUM + "output: {file: link/emb_corpus_link.h5}\n")],
     absent=["outside/*"])
case("scene_output_dangling_symlink", "scene", ["run", "sub/s.yaml", "-q"], 1, ["outside"],
     [("mkdir", "sub"), ("symlink", "/tmp/emb_corpus_dangling.h5", "sub/out.h5"),
      ("write", "sub/s.yaml", PENDULUM + "output: {file: out.h5}\n")])
case("scene_output_csv_outside", "scene", ["run", "sub/s.yaml", "-q"], 1, ["outside"],
     [("write", "sub/s.yaml", PENDULUM + "output: {csv: /etc/emb_corpus.csv, channels: [rod.p.x]}\n")])
scene("output_unknown_channel", PENDULUM + "output: {file: x.h5, csv: x.csv, channels: [rod.p.w]}\n",
      1, ["rod.p.w"], absent=("x.h5", "x.csv", "out.h5"))
scene("output_force_without_load", replaced("analysis:", "forces:\n  - {name: spring, type: spring-damper, i: rod_top, j: pivot, stiffness: 10}\nanalysis:") + "output: {csv: x.csv, channels: [spring.F.x]}\n", 1, ["spring", "reports no load"], absent=("out.h5", "x.csv"))
scene("output_channels_not_list", PENDULUM + "output: {csv: x.csv, channels: rod.p.x}\n", 1,
      ["channels"], absent=("x.csv",))
case("scene_output_is_directory", "scene", ["run", "s.yaml", "-q"], 1, ["directory"],
     [("write", "s.yaml", PENDULUM + "output: {file: adir}\n"), ("mkdir", "adir")])
case("scene_output_is_scene", "scene", ["run", "s.yaml", "-q"], 1, ["is the input"],
     [("write", "s.yaml", PENDULUM + "output: {file: s.yaml}\n")], unchanged=["s.yaml"])
case("scene_output_h5_equals_csv", "scene", ["run", "s.yaml", "-q"], 1, ["same file"],
     [("write", "s.yaml", PENDULUM + "output: {file: r.h5, csv: r.h5, channels: [rod.p.x]}\n")],
     absent=["r.h5"])
case("scene_output_dir_missing", "scene", ["run", "s.yaml", "-q"], 1, ["does not exist"],
     [("write", "s.yaml", PENDULUM + "output: {file: nodir/r.h5}\n")])
case("scene_missing", "scene", ["run", "nowhere.yaml", "-q"], 1, ["does not exist"])
case("scene_directory", "scene", ["run", "adir", "-q"], 1, ["not a regular file"],
     [("mkdir", "adir")])
case("scene_fifo", "scene", ["run", "pipe.yaml", "-q"], 1, ["not a regular file"],
     [("fifo", "pipe.yaml")], timeout=10)
case("scene_dof_bad", "scene", ["dof", "s.yaml", "-q"], 1, ["mass"],
     [("write", "s.yaml", replaced("mass: 1.0", "mass: -1"))])

# Parts from body files and geometry.
CMS = """bodies:
  - {name: bar, model: MODEL, body_file: FILE, EXTRA}
analysis: {type: assemble}
"""


def cms(name, file="{fix}/body.h5", model="cms", extra="modes: 2", frags=(), setup=(), code=1,
        category="scene"):
    text = CMS.replace("MODEL", model).replace("FILE", file).replace("EXTRA", extra)
    scene(name, text, code, frags, setup=setup, category=category, timeout=30)


cms("cms_ok_baseline", code=0)

# Issue 36: stress outputs with lists that hold nothing or an entry twice, field times the run
# never reaches, node numbers that look like gmsh tags (stress nodes are 0-based indices).
STRESS = """bodies:
  - {name: bar, model: cms, body_file: {fix}/stress_body.h5, modes: 2}
stress_outputs:
  - {name: s, body: bar, EXTRA}
analysis: {type: dynamic, t_end: 0.01, output_step: 0.001}
"""
for key, extra, frags in (
        ("groups_empty", "groups: []", ["groups", "empty list"]),
        ("groups_twice", "groups: [x1, x1]", ["groups", "x1 is listed twice"]),
        ("nodes_empty", "nodes: []", ["nodes", "empty list"]),
        ("nodes_twice", "nodes: [0, 0]", ["nodes", "listed twice"]),
        ("nodes_negative", "nodes: [-4]", ["0-based mesh node indices", "not gmsh's node tags"]),
        ("field_times_empty", "field_times: []", ["field_times", "empty list"]),
        ("field_times_twice", "field_times: [0.005, 0.005]", ["field_times", "listed twice"]),
        ("field_times_after_end", "field_times: [0.02]", ["field_times", "after the run's end"]),
        ("field_times_before_start", "field_times: [-1]", ["field_times", "before the run's start"])):
    scene(f"stress_output_{key}", STRESS.replace("EXTRA", extra), 1, frags, timeout=30)
cms("cms_modes_negative", extra="modes: -1", frags=["modes"])
cms("cms_modes_huge", extra="modes: 1.0e9", frags=["modes"])
cms("cms_modes_too_many", extra="modes: 50", frags=["modes"])
cms("cms_fmax_zero", extra="fmax_hz: 0", frags=["fmax_hz"])
cms("cms_fmax_nan", extra="fmax_hz: .nan", frags=["fmax_hz"])
cms("cms_dynamic_band_zero", extra="dynamic_band_hz: 0", frags=["dynamic_band_hz"])
cms("cms_dynamic_band_nan", extra="dynamic_band_hz: .nan", frags=["dynamic_band_hz"])
cms("cms_fmax_below_all", extra="fmax_hz: 1.0e-3", frags=["at or below"])
cms("cms_modal_coordinates_count", extra="modes: 2, modal_coordinates: [1, 2, 3]", frags=["modal_coordinates"])
cms("cms_modal_coordinates_nan", extra="modes: 2, modal_coordinates: [.nan, 0]", frags=["modal_coordinates"])
cms("cms_modal_velocities_count", extra="modes: 2, modal_velocities: [1]", frags=["modal_velocities", "expected 2"])
cms("cms_modal_velocities_inf", extra="modes: 2, modal_velocities: [0, .inf]", frags=["modal_velocities"])
cms("cms_modal_velocities_empty", extra="modes: 2, modal_velocities: []", frags=["modal_velocities", "expected 2", "got 0", "leave the key out"])
cms("cms_modal_coordinates_empty", extra="modes: 2, modal_coordinates: []", frags=["modal_coordinates", "expected 2", "got 0"])
cms("cms_expect_hash_wrong", extra="expect_mesh_hash: abc", frags=["stale"])
cms("cms_stiffening_text", extra="geometric_stiffening: maybe", frags=["geometric_stiffening"])
cms("cms_mass_given", extra="mass: 1", frags=["mass"])
cms("cms_body_file_missing", file="nowhere.h5", frags=["nowhere.h5"])
cms("cms_body_file_directory", file="adir", frags=["adir"], setup=[("mkdir", "adir")])
cms("cms_body_file_fifo", file="pipe.h5", frags=["pipe.h5"], setup=[("fifo", "pipe.h5")])
cms("cms_body_file_dev_zero", file="/dev/zero", frags=["/dev/zero"])
cms("cms_body_file_text", file="t.h5", frags=["not an HDF5 file"], setup=[("write", "t.h5", "hello\n")])
cms("cms_body_file_is_results", file="{fix}/pendulum.h5", frags=["format"])
cms("cms_rigid_from_file_ok", model="rigid", extra="modes: 2", code=0)
BEAM = """bodies:
  - {name: crank, model: beam, geometry: GEO, EXTRA}
analysis: {type: assemble}
"""
for key, (geo, extra, frags, setup) in {
        "geometry_missing": ("nowhere.geo", "webs: rigid", ["nowhere.geo"], []),
        "geometry_refused": ("evil.geo", "webs: rigid", ["refusing"],
                             [("write", "evil.geo", 'SystemCall "touch ' + MARKER + '";\n' + BOX)]),
        "element_length_zero": ("{src}/meshes/crankshaft_1cyl.geo", "element_length: 0", ["element_length"], []),
        "element_length_tiny": ("{src}/meshes/crankshaft_1cyl.geo", "element_length: 1.0e-9", ["element_length"], []),
        "webs_bad": ("{src}/meshes/crankshaft_1cyl.geo", "webs: hollow", ["webs"], []),
        "parameter_nan": ("{src}/meshes/crankshaft_1cyl.geo", "parameters: {stroke: .nan}", ["stroke"], []),
        "parameter_unknown": ("{src}/meshes/crankshaft_1cyl.geo", "parameters: {nope: 1}", ["nope"], []),
        "parameter_text": ("{src}/meshes/crankshaft_1cyl.geo", "parameters: {stroke: long}", ["stroke"], []),
        "material_negative_E": ("{src}/meshes/crankshaft_1cyl.geo", "material: {E: -1}", ["Young"], []),
        "stiffness_damping_negative": ("{src}/meshes/crankshaft_1cyl.geo", "stiffness_damping: -1", ["stiffness_damping"], []),
        "no_beam_groups": ("box.geo", "webs: rigid", ["beam_segment"], [("write", "box.geo", BOX)]),
}.items():
    scene(f"beam_{key}", BEAM.replace("GEO", geo).replace("EXTRA", extra), 1, frags,
          setup=setup, absent=("out.h5", "pwned*"), timeout=60)

# --- body files (HDF5), read by emb inspect and by scenes ---------------------------------

BODY_MUTATIONS = {
    "external_link": (["ext_link", "/reduced/borrowed", "{fix}/pendulum.h5", "/time"], ["external link", "/reduced/borrowed"]),
    "external_dataset": (["ext_dataset", "/modes/outside", "/etc/hostname"], ["external files", "/modes/outside"]),
    "virtual_dataset": (["vds", "/invariants/mapped", "{fix}/pendulum.h5", "/time"], ["virtual dataset"]),

    "drop_K": (["delete", "/reduced/K"], ["/reduced/K"]),
    "drop_X": (["delete", "/modes/X"], ["/modes/X"]),
    "drop_Sbar": (["delete", "/invariants/Sbar"], ["/invariants/Sbar"]),
    "drop_interface_names": (["delete", "/interfaces/names"], []),
    "drop_interface_nodes": (["delete", "/interfaces/x0/nodes"], ["x0"]),
    "drop_damping": (["delete", "/damping"], ["damping"]),
    "drop_format": (["del_attr", "/", "format"], ["format"]),
    "drop_digest": (["del_attr", "/", "content_digest"], ["content_digest"]),
    "drop_digest_version": (["del_attr", "/", "content_digest_version"], ["content digest"]),
    "format_wrong": (["set_attr", "/", "format", "emb.modes", "str"], ["format"]),
    "format_version_99": (["set_attr", "/", "format_version", "99", "int"], ["version"]),
    "digest_version_99": (["set_attr", "/", "content_digest_version", "99", "int"], ["digest version"]),
    "format_version_text": (["set_attr", "/", "format_version", "one", "str"], ["format_version"]),
    "tampered_K": (["scale", "/reduced/K", "7", "123.0"], ["content digest"]),
    "nan_in_M": (["scale", "/reduced/M", "0", "nan"], ["content digest"]),
    "tampered_damping_ratio": (["set_attr", "/damping", "ratio", "0.5", "float"], ["content digest"]),
    "tampered_density": (["set_attr", "/material", "density", "1.0", "float"], ["content digest"]),
    "tampered_mesh_hash": (["set_attr", "/provenance", "mesh_hash", "0000", "str"], ["content digest"]),
    "tampered_num_boundary": (["set_attr", "/reduced", "num_boundary", "1000", "int"], []),
    "tampered_coupling": (["replace", "/interfaces/couplings", [2], "str"], []),
    "damping_model_bad": (["set_attr", "/damping", "model", "viscous", "str"], ["damping model"]),
    "array_attribute": (["set_attr", "/material", "density", "1000", "array"], ["expected a single value"]),
    "array_mass": (["set_attr", "/invariants", "mass", "64", "array"], ["expected a single value"]),
    "K_1d": (["replace", "/reduced/K", [100], "f8"], ["/reduced/K"]),
    "K_not_square": (["replace", "/reduced/K", [12, 11], "f8"], ["/reduced/K"]),
    "X_wrong_rows": (["replace", "/modes/X", [3, 4], "f8"], ["/modes/X"]),
    "Sbar_short": (["replace", "/invariants/Sbar", [1, 1], "f8"], ["/invariants/Sbar"]),
    "points_2_columns": (["replace", "/interfaces/points", [2, 2], "f8"], ["/interfaces/points"]),
    "interface_shapes_short": (["replace", "/modes/interface_shapes", [1, 4], "f8"], ["/modes/interface_shapes"]),
    "weights_short": (["replace", "/interfaces/x0/weights", [1], "f8"], ["weights"]),
    "St_3d": (["replace", "/invariants/St", [3, 4, 1], "f8"], ["/invariants/St"]),
    "K_ints": (["replace", "/reduced/K", [12, 12], "i4"], []),
    "K_strings": (["replace", "/reduced/K", [4], "str"], ["/reduced/K"]),
    "names_fixed_strings": (["replace", "/interfaces/names", [2], "str"], []),
    "names_vlen_strings": (["replace", "/interfaces/names", [2], "vlen_str"], ["variable-length string", "/interfaces/names"]),
    "format_vlen_string": (["set_attr", "/", "format", "emb.body", "vlen_str"], ["variable-length string", "format"]),
    "huge_K": (["huge", "/reduced/K"], ["/reduced/K"]),
    "huge_X": (["huge", "/modes/X"], ["/modes/X"]),
    "stiffening_wrong_count": (["replace", "/geometric_stiffness/centrifugal", [5, 4, 4], "f8"], ["centrifugal"]),
    "stiffening_products": (["set_attr", "/geometric_stiffness", "centrifugal_products", "x", "str"], []),
}
for key, (mutation, frags) in BODY_MUTATIONS.items():
    setup = [("h5", "{fix}/body.h5", "b.h5", *mutation)]
    case(f"body_inspect_{key}", "body", ["inspect", "b.h5", "-q"], 1, frags, setup, timeout=30)
for key in ("external_link", "tampered_damping_ratio", "huge_K", "Sbar_short", "array_attribute",
            "virtual_dataset"):
    mutation, frags = BODY_MUTATIONS[key]
    cms(f"body_scene_{key}", file="b.h5", frags=frags,
        setup=[("h5", "{fix}/body.h5", "b.h5", *mutation)], category="body")
# Issue 36: a stress group's node tags removed or changed after the body file was written.
for key, mutation in (("node_tags_deleted", ["delete", "/stress/x1/node_tags"]),
                      ("node_tags_changed", ["scale", "/stress/x1/node_tags", "0", "7"])):
    case(f"body_inspect_stress_{key}", "body", ["inspect", "b.h5", "-q"], 1,
         ["content digest", "modified after it was written"],
         [("h5", "{fix}/stress_body.h5", "b.h5", *mutation)], timeout=30)
case("body_truncated_half", "body", ["inspect", "b.h5", "-q"], 1, [],
     [("truncate", "{fix}/body.h5", "b.h5", "0.5")])
case("body_truncated_tail", "body", ["inspect", "b.h5", "-q"], 1, [],
     [("truncate", "{fix}/body.h5", "b.h5", "0.98")])
case("body_empty_file", "body", ["inspect", "b.h5", "-q"], 1, ["not an HDF5 file"],
     [("write", "b.h5", "")])
case("body_text_file", "body", ["inspect", "b.h5", "-q"], 1, ["not an HDF5 file"],
     [("write", "b.h5", "emb.body\n")])
case("body_is_directory", "body", ["inspect", "adir", "-q"], 1, [], [("mkdir", "adir")])
case("body_is_fifo", "body", ["inspect", "pipe.h5", "-q"], 1, [], [("fifo", "pipe.h5")],
     timeout=10)
case("body_is_modes_file", "body", ["inspect", "m.h5", "-q"], 1, ["format"],
     [("copy", "{fix}/pendulum.h5", "m.h5")])

# --- results files (emb spectrum) --------------------------------------------------------

SPEC = ["spectrum", "r.h5", "-q", "--channel", "disc.omega.x", "--angle", "disc"]
RESULTS_MUTATIONS = {
    "external_link": (["ext_link", "/model/borrowed", "{fix}/body.h5", "/reduced/K"], 1, ["external link"]),
    "virtual_dataset": (["vds", "/state/mapped", "{fix}/pendulum.h5", "/time"], 1, ["virtual dataset"]),
    "drop_time": (["delete", "/time"], 1, ["/time"]),
    "drop_q": (["delete", "/state/q"], 1, ["/state/q"]),
    "drop_bodies": (["delete", "/model/bodies"], 1, ["/model/bodies"]),
    "drop_format": (["del_attr", "/", "format"], 1, ["format"]),
    "format_wrong": (["set_attr", "/", "format", "emb.body", "str"], 1, ["format"]),
    "q_short_rows": (["replace", "/state/q", [3, 7], "f8"], 1, ["samples"]),
    "q_narrow": (["replace", "/state/q", [801, 3], "f8"], 1, ["/state/q"]),
    "q_1d": (["replace", "/state/q", [801], "f8"], 1, ["/state/q"]),
    "v_narrow": (["replace", "/state/v", [801, 2], "f8"], 1, ["/state/v"]),
    "time_nan": (["scale", "/time", "5", "nan"], 1, ["/time"]),
    "time_backwards": (["scale", "/time", "5", "-1"], 1, ["/time"]),
    "q_nan": (["fill", "/state/q", "nan"], 1, []),
    "huge_q": (["huge", "/state/q"], 1, ["/state/q"]),
    "bodies_ints": (["replace", "/model/bodies", [1], "i4"], 1, ["/model/bodies"]),
    "layout_stride_huge": (["set_attr", "/state/q", "values_per_body", "1000000", "int"], 1, ["values_per_body"]),
    "layout_stride_negative": (["set_attr", "/state/q", "values_per_body", "-7", "int"], 1, ["values_per_body"]),
    "layout_quaternion_outside": (["set_attr", "/state/q", "quaternion_column", "5", "int"], 1, ["layout"]),
    "layout_stride_too_wide": (["set_attr", "/state/q", "values_per_body", "60", "int"], 1, ["/state/q"]),
    "status_running": (["set_attr", "/", "status", "running", "str"], 0, ["unfinished", "running"]),
    "status_interrupted": (["set_attr", "/", "status", "interrupted", "str"], 0, ["unfinished", "interrupted"]),
    "status_missing": (["del_attr", "/", "status"], 0, ["unfinished"]),
    "status_array": (["set_attr", "/", "status", "3", "array"], 0, ["unfinished"]),
}
for key, (mutation, code, frags) in RESULTS_MUTATIONS.items():
    case(f"results_spectrum_{key}", "results", SPEC, code, frags,
         [("h5", "{fix}/disc.h5", "r.h5", *mutation)], timeout=30)
case("results_truncated", "results", SPEC, 1, [], [("truncate", "{fix}/disc.h5", "r.h5", "0.6")])
case("results_empty", "results", SPEC, 1, ["not an HDF5 file"], [("write", "r.h5", "")])
case("results_is_body_file", "results",
     ["spectrum", "{fix}/body.h5", "-q", "--channel", "x.p.x", "--rpm", "60"], 1, ["format"])
case("results_missing", "results", ["spectrum", "nowhere.h5", "-q", "--channel", "a.p.x",
                                    "--rpm", "60"], 1, ["nowhere.h5"])
case("results_csv_is_input", "results", [*SPEC[:-2], "--angle", "disc", "--csv", "r.h5"], 1,
     ["is the input"], [("copy", "{fix}/disc.h5", "r.h5")], unchanged=["r.h5"])

# --- numerical failures inside a run: a status, a message, exit 3, a file marked so -------

BEARING = """name: bearing
bodies:
  - {name: rod, mass: 1.0, inertia: [1.0e-4, 0.083, 0.083], position: [0.5, Y0, 0]}
markers:
  - {name: pivot, body: ground, position: [0, 0, 0]}
  - {name: rod_top, body: rod, position: [-0.5, 0, 0]}
joints:
  - {name: guide, type: planar, i: rod_top, j: pivot}
forces:
  - {name: brg, type: journal-bearing, i: rod_top, j: pivot, radius: 0.02, length: 0.02,
     clearance: 1.0e-5, viscosity: 1.0e-4}
  - {name: push, type: force, marker: rod_top, direction: [0, -1, 0], function: {constant: LOAD}}
analysis: {type: dynamic, t_end: 0.01, output_step: 0.001INTEGRATOR}
"""
for key, y0, load, integrator, status in (
        ("start", "-2.0e-5", "0", "", "failed"),  # eccentricity 2 at t = 0
        ("ida", "0", "1.0e12", "", "integrator-failure"),  # pushed through the film
        ("generalized_alpha", "0", "1.0e12", ", integrator: generalized-alpha",
         "integrator-failure")):
    case(f"numerical_bearing_touches_{key}", "numerical", ["run", "s.yaml", "-q", "-o", "r.h5"],
         3, ["journal bearing 'brg'", "eccentricity ratio"],
         [("write", "s.yaml", BEARING.replace("Y0", y0).replace("LOAD", load)
           .replace("INTEGRATOR", integrator))],
         h5_attr=[("r.h5", "status", status)], timeout=30, stderr_absent=["and h ="])
case("numerical_too_much_work", "numerical", ["run", "s.yaml", "-q", "-o", "r.h5"], 3,
     ["too-much-work", "max_steps"], [("write", "s.yaml", replaced("output_step: 0.01}",
                                                                  "output_step: 0.01, "
                                                                  "max_steps: 2}"))],
     h5_attr=[("r.h5", "status", "integrator-failure")], timeout=30)

# --- usability features of issue 14: planar models, joint channels, expressions ---------

FOUR_BAR = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools",
                             "scenes", "four_bar.yaml")).read().replace(
    "  remove_redundant: true\n", "")
for key, (planar, code, frags) in {
        "true": ("planar: true", 0, []),
        "normal_z": ("planar: {normal: [0, 0, 2]}", 0, []),
        "wrong_plane": ("planar: {normal: [1, 0, 0]}", 1, ["act in the plane", "revolute 'B'"]),
        "tilted_plane": ("planar: {normal: [0, 0.1, 1]}", 1, ["act in the plane"]),
        "false": ("planar: false", 1, ["redundant", "remove_redundant"]),
        "text": ("planar: maybe", 1, ["planar", "s.yaml:"]),
        "zero_normal": ("planar: {normal: [0, 0, 0]}", 1, ["normal"]),
        "nan_normal": ("planar: {normal: [.nan, 0, 1]}", 1, ["normal"]),
        "inf_normal": ("planar: {normal: [0, 0, .inf]}", 1, ["normal"]),
        "short_normal": ("planar: {normal: [0, 1]}", 1, ["normal"]),
        "unknown_key": ("planar: {nrmal: [0, 0, 1]}", 1, ["nrmal"]),
        "list": ("planar: [0, 0, 1]", 1, ["planar"]),
        "duplicate": ("planar: true\nplanar: false", 1, ["planar", "given twice"]),
}.items():
    case(f"scene_planar_{key}", "scene", ["run", "s.yaml", "-q", "-o", "out.h5", "--t-end", "0.02"],
         code, frags, [("write", "s.yaml", FOUR_BAR + planar + "\n")],
         absent=["out.h5"] if code else [], stderr_absent=["warning"] if code == 0 else [],
         exists=["out.h5"] if code == 0 else [])
# A repeated hinge: its redundant at-point x and y act in any plane through the hinge axis.
scene("planar_repeated_hinge", replaced(
    "  - {name: hinge, type: revolute, i: rod_top, j: pivot}",
    "  - {name: hinge, type: revolute, i: rod_top, j: pivot}\n"
    "  - {name: hinge2, type: revolute, i: rod_top, j: pivot}") + "planar: true\n", 1,
      ["act in the plane", "revolute 'hinge2': at-point x"])

# Joint coordinates as channels.
scene("output_travel_of_revolute", PENDULUM + "output: {csv: x.csv, channels: [hinge.travel]}\n",
      1, ["hinge.travel", "hinge.angle"], absent=("out.h5", "x.csv"))
scene("output_angle_ok", PENDULUM + "output: {csv: x.csv, channels: [hinge.angle, hinge.angle_rate]}\n",
      0, [])
JSPEC = ["spectrum", "r.h5", "-q", "--channel", "bearing.angle_rate", "--angle", "bearing"]
case("results_joint_channel_ok", "results", JSPEC, 0, [], [("copy", "{fix}/disc.h5", "r.h5")])
for key, (mutation, frags) in {
        "joints_dropped": (["delete", "/joints"], ["/joints"]),
        "joints_names_dropped": (["delete", "/model/joints"], ["bearing"]),
        "joints_narrow": (["replace", "/joints", [801, 1], "f8"], ["/joints"]),
        "joints_1d": (["replace", "/joints", [801], "f8"], ["/joints"]),
        "joints_short": (["replace", "/joints", [3, 4], "f8"], ["samples"]),
        "joints_nan": (["fill", "/joints", "nan"], ["no such coordinate"]),
        "joints_names_ints": (["replace", "/model/joints", [1], "i4"], ["/model/joints"]),
        "joints_huge": (["huge", "/joints"], ["/joints"]),
}.items():
    case(f"results_{key}", "results", JSPEC, 1, frags,
         [("h5", "{fix}/disc.h5", "r.h5", *mutation)], timeout=30)
case("results_angle_unknown_joint", "results",
     ["spectrum", "{fix}/disc.h5", "-q", "--channel", "disc.omega.x", "--angle", "bearng"], 1,
     ["bearng", "bearing"])
case("results_joint_channel_unknown_coordinate", "results",
     ["spectrum", "{fix}/disc.h5", "-q", "--channel", "bearing.twist", "--angle", "bearing"], 1,
     ["bearing.twist"])

# Expressions that are valid text but no usable motion (no derivative where the run needs
# one): the input's fault, exit 1, found at once (not after the integrator's step budget),
# the results file marked failed when the run had started.
for key, expression, frags, attrs in (
        ("kink", "abs(t - 0.05)", ["expression", "kink"], [("r.h5", "status", "failed")]),
        ("nan_midrun", "sqrt(0.05 - t)", ["expression"], [("r.h5", "status", "failed")]),
        # Issue 36: not finite at a time of the run: refused naming the motion, the time and
        # the value (it was reported as a rank-deficient Jacobian or IDA's step budget).
        ("nan_after", "6.28*t + 0*ln(0.05 - t)", ["motion 'm' at t = ", "is NaN at"],
         [("r.h5", "status", "failed")]),
        ("inf_at_start", "1/t", ["motion 'm' at t = 0 s", "'1/t' is +inf"], []),
        ("too_fast_for_scale", "0.1*sin(2*pi*1000*t)", ["expression", "scale"], [])):
    case(f"numerical_expression_{key}", "numerical", ["run", "s.yaml", "-q", "-o", "r.h5"], 1,
         frags, [("write", "s.yaml", replaced(
             "analysis:", 'motions:\n  - {name: m, joint: hinge, function: {expression: "'
             + expression + '"}}\nanalysis:'))], h5_attr=attrs, timeout=20)

case("numerical_expression_load_nan", "numerical", ["run", "s.yaml", "-q", "-o", "r.h5"], 1,
     ["applied load 'f' at t = 0 s", "'sqrt(t - 0.03)' is NaN"],
     [("write", "s.yaml", replaced("analysis:", "forces:\n  - {name: f, type: torque, marker: "
                                   "rod_top, direction: [0, 0, 1], function: {expression: "
                                   "\"sqrt(t - 0.03)\"}}\nanalysis:"))],
     h5_attr=[("r.h5", "status", "failed")], timeout=20)

# --- I/O faults ---------------------------------------------------------------------------

for cmd_key, cmd, out in (
        ("modes", ["modes", "{fix}/bar.geo", "-q", "-o", "full/out.h5"], "full/out.h5"),
        ("reduce", ["reduce", "{fix}/bar.geo", "-q", "-i", "x0:rbe2", "-n", "4", "--no-reference",
                    "-o", "full/out.h5"], "full/out.h5"),
        ("run", ["run", "{fix}/disc.yaml", "-q", "-o", "full/out.h5"], "full/out.h5"),
        ("run_csv", ["run", "{fix}/disc.yaml", "-q", "--no-output", "--csv", "full/out.csv"],
         "full/out.csv"),
        ("spectrum_csv", ["spectrum", "{fix}/disc.h5", "-q", "--channel", "disc.omega.x",
                          "--angle", "disc", "--csv", "full/out.csv"], "full/out.csv"),
        ("save_mesh", ["mesh", "{fix}/bar.geo", "-q", "--save-mesh", "full/out.msh"],
         "full/out.msh")):
    # The disk fills while writing: the previous file stays, no temporary is left.
    old = "full/" + os.path.basename(out)
    case(f"io_disk_full_{cmd_key}", "io", cmd, 1, [],
         [("full_dir", "full", "64"), ("write", old, "previous result\n"),
          ("fill_disk", "full/filler")],
         unchanged=[old] if cmd_key not in ("run", "run_csv") else [], timeout=60)
case("io_disk_full_run_status", "io", ["run", "{fix}/disc.yaml", "-q", "-o", "full/out.h5"], 1,
     [], [("full_dir", "full", "40")], timeout=60)
for key, out in {"dev_full": "/dev/full", "dev_null": "/dev/null"}.items():
    case(f"io_modes_output_{key}", "io", ["modes", "{fix}/bar.geo", "-q", "-o", out], 1,
         ["not a regular file"])
    case(f"io_run_csv_{key}", "io", ["run", "{fix}/pendulum.yaml", "-q", "--no-output", "--csv",
                                     out], 1, ["not a regular file"])
case("io_spectrum_csv_dev_full", "io", ["spectrum", "{fix}/disc.h5", "-q", "--channel",
                                        "disc.omega.x", "--angle", "disc", "--csv", "/dev/full"],
     1, ["not a regular file"])
for key, cmd in {"modes": ["modes", "{fix}/bar.geo", "-q", "-o", "ro/out.h5"],
                 "reduce": ["reduce", "{fix}/bar.geo", "-q", "-i", "x0", "-o", "ro/out.h5"],
                 "run": ["run", "{fix}/pendulum.yaml", "-q", "-o", "ro/out.h5"],
                 "spectrum": ["spectrum", "{fix}/disc.h5", "-q", "--channel", "disc.omega.x",
                              "--angle", "disc", "--csv", "ro/out.csv"],
                 "save_mesh": ["mesh", "{fix}/bar.geo", "-q", "--save-mesh", "ro/out.msh"],
                 "compare": ["compare", "{fix}/bar.geo", "-q", "--report-dir", "ro"]}.items():
    case(f"io_readonly_dir_{key}", "io", cmd, 1, ["cannot create files"],
         [("readonly_dir", "ro")], timeout=20)
case("io_scene_output_readonly", "io", ["run", "s.yaml", "-q"], 1, ["cannot create files"],
     [("readonly_dir", "ro"), ("write", "s.yaml", PENDULUM + "output: {file: ro/r.h5}\n")])
case("io_output_is_directory", "io", ["modes", "{fix}/bar.geo", "-q", "-o", "adir"], 1,
     ["directory"], [("mkdir", "adir")])
case("io_output_dir_missing", "io", ["modes", "{fix}/bar.geo", "-q", "-o", "no/dir/out.h5"], 1,
     ["does not exist"])
case("io_output_is_input_mesh", "io", ["modes", "bar.msh", "-q", "-o", "bar.msh"], 1,
     ["is the input"], [("copy", "{fix}/bar.msh", "bar.msh")], unchanged=["bar.msh"])
case("io_save_mesh_is_output", "io", ["modes", "{fix}/bar.geo", "-q", "-o", "x.h5",
                                      "--save-mesh", "x.h5"], 1, ["same file"], absent=["x.h5"])
case("io_xdmf_is_input", "io", ["modes", "x.xdmf", "-q", "-o", "x.h5"], 1, [],
     [("copy", "{fix}/bar.msh", "x.xdmf")], unchanged=["x.xdmf"])
# A run validates all its outputs before it replaces the previous result.
case("io_previous_result_kept_bad_csv_dir", "io",
     ["run", "{fix}/pendulum.yaml", "-q", "-o", "out.h5", "--csv", "nowhere/x.csv"], 1,
     ["nowhere"], [("write", "out.h5", "previous result\n")], unchanged=["out.h5"])
case("io_previous_result_kept_unknown_channel", "io", ["run", "s.yaml", "-q", "-o", "out.h5"], 1,
     ["rod.p.w"], [("write", "out.h5", "previous result\n"),
                   ("write", "s.yaml", PENDULUM + "output: {csv: x.csv, channels: [rod.p.w]}\n")],
     unchanged=["out.h5"], absent=["x.csv"])
case("io_previous_result_kept_csv_readonly", "io",
     ["run", "{fix}/pendulum.yaml", "-q", "-o", "out.h5", "--csv", "ro/x.csv"], 1,
     ["cannot create files"], [("write", "out.h5", "previous result\n"), ("readonly_dir", "ro")],
     unchanged=["out.h5"])
# Concurrent writers: another process holds the output's lock (the runner binds its name,
# libemb/io/output_lock.h) and is named by its pid. A lock leaves no file, so none can be
# stale (a SIGKILLed holder: tests/io/output_lock_test.cpp).
for key, cmd, out in (("run", ["run", "{fix}/pendulum.yaml", "-q", "-o", "out.h5"], "out.h5"),
                      ("modes", ["modes", "{fix}/bar.geo", "-q", "-o", "out.h5"], "out.h5"),
                      ("run_csv", ["run", "{fix}/pendulum.yaml", "-q", "--no-output", "--csv",
                                   "out.csv"], "out.csv")):
    case(f"io_concurrent_writer_{key}", "io", cmd, 1, ["another emb process", "(pid "],
         [("write", "out.h5", "previous"), ("hold_lock", out)], unchanged=["out.h5"])

# --- signals mid-run -----------------------------------------------------------------------

LONG_RUN = ["run", "{fix}/disc.yaml", "-q", "-o", "r.h5", "--t-end", "50", "--dt", "1e-4",
            "--force"]
for sig in ("INT", "TERM"):
    case(f"signal_run_{sig.lower()}", "signal", LONG_RUN, "signal", [f"interrupted by SIG{sig}"],
         signal={"sig": sig, "when": "exists:r.h5", "delay": 1.0},
         h5_attr=[("r.h5", "status", "interrupted")], timeout=60)
    case(f"signal_run_{sig.lower()}_twice", "signal", LONG_RUN, "signal", [],
         signal={"sig": sig, "when": "exists:r.h5", "delay": 1.0, "again": 0.001}, timeout=60)
    case(f"signal_modes_{sig.lower()}", "signal",
         ["modes", "{src}/meshes/tube.geo", "-q", "--modes", "30", "-o", "m.h5"], "signal", [],
         signal={"sig": sig, "when": "2.0"}, absent=["m.h5", "m.xdmf"], timeout=60)
    case(f"signal_reduce_{sig.lower()}", "signal",
         ["reduce", "{src}/meshes/tube.geo", "-q", "-o", "b.h5"], "signal", [],
         signal={"sig": sig, "when": "3.0"}, absent=["b.h5", "b.xdmf"], timeout=60)
case("signal_run_kill", "signal", LONG_RUN, "signal", [],
     signal={"sig": "KILL", "when": "exists:r.h5", "delay": 1.0},
     h5_attr=[("r.h5", "status", "running")], timeout=60)
case("signal_modes_kill", "signal",
     ["modes", "{src}/meshes/tube.geo", "-q", "--modes", "30", "-o", "m.h5"], "signal", [],
     signal={"sig": "KILL", "when": "2.0"}, absent=["m.h5"], timeout=60)
# A SIGKILL leaves the hidden temporary; the next run of the same output removes it.
for key, cmd in (("modes", ["modes", "{src}/meshes/tube.geo", "-q", "--modes", "30", "-o", "m.h5"]),
                 ("reduce", ["reduce", "{src}/meshes/tube.geo", "-q", "-o", "m.h5"])):
    case(f"signal_{key}_kill_then_rerun", "signal", cmd, "signal", [],
         signal={"sig": "KILL", "when": "3.0"}, timeout=60,
         then={"cmd": ["modes", "{fix}/bar.geo", "-q", "-n", "2", "-o", "m.h5"], "exit": 0})
# An unwritable output is found before the work (the crankshaft takes minutes to reduce).
for key, cmd in (("reduce", ["reduce", "{src}/meshes/crankshaft_i4.geo", "-q", "-o", "ro/b.h5"]),
                 ("modes", ["modes", "{src}/meshes/crankshaft_i4.geo", "-q", "-o", "ro/m.h5"]),
                 ("run_csv", ["run", "{fix}/disc.yaml", "-q", "--t-end", "100", "--force",
                              "--csv", "ro/r.csv", "-o", "r.h5"])):
    case(f"io_readonly_found_before_work_{key}", "io", cmd, 1, ["cannot create files"],
         [("readonly_dir", "ro")], absent=["r.h5"], timeout=15)
# After a SIGKILL the reader says the file is unfinished.
case("signal_spectrum_after_kill", "signal", SPEC, 0, ["unfinished", "running"],
     [("h5", "{fix}/disc.h5", "r.h5", "set_attr", "/", "status", "running", "str")])



def manifest():
    counts = {}
    for c in CASES:
        counts[c["category"]] = counts.get(c["category"], 0) + 1
    return {"generated_by": "tests/corpus/make_manifest.py", "counts": counts,
            "fixtures": FIXTURES, "cases": CASES}


def main():
    m = manifest()
    args = sys.argv[1:]
    if args[:1] == ["--write"] and len(args) == 2:
        with open(args[1], "w") as f:
            f.write(json.dumps(m, indent=1) + "\n")
    elif args[:1] == ["--check"] and len(args) == 2:
        if len(CASES) < int(args[1]):
            sys.exit(f"corpus: {len(CASES)} cases, expected at least {args[1]}")
    elif args:
        sys.exit(__doc__)
    print(f"{len(CASES)} cases: " + ", ".join(f"{k} {v}" for k, v in sorted(m["counts"].items())))


if __name__ == "__main__":
    main()
