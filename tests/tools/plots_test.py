"""The plotting tools on real `emb` output: the deformed-shape animation
(tools/plots/animate_body.py) and the engine plots (tools/plots/engine_plots.py).

    /usr/bin/python3 tests/tools/plots_test.py EMB_EXECUTABLE SOURCE_DIR

Animation: a coarse tube is reduced with its mesh shapes, floats free with initial modal coordinates
(it vibrates), and the script's XDMF/HDF5 output is checked: one frame per output time at
the run's times, every referenced dataset present with the XDMF's dimensions, frame 0's
displacement equal to the scene's initial modal coordinates times the body file's mesh
shapes (independent of the run), geometry = nodes + scale x displacement, later frames
following the run's modal coordinates; and bad input (an unknown body, a body file
without mesh shapes) exits non-zero with the thing named and no output written.
Engine plots: the tube spinning about its axis for one 720-degree cycle gives the trace and
order-spectrum PNGs (written, valid PNG), and an unknown channel is an error naming it.
Campbell plot (tools/plots/campbell_plot.py): the diagram of the Jeffcott disc scene gives a PNG.
Clonk plots (tools/plots/clonk_plots.py): a lash run with output points on the vibrating tube
gives its five PNGs and metrics that count the results file's contacts.
Bearing plots (tools/plots/bearing_plots.py): a rotor in a film bearing gives the orbit and
film PNGs, the orbit agreeing with the element's eccentricity_ratio channel.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import h5py
import numpy as np

EMB, SOURCE = sys.argv[1], sys.argv[2]
SCRIPT = os.path.join(SOURCE, "tools", "plots", "animate_body.py")
ENGINE_PLOTS = os.path.join(SOURCE, "tools", "plots", "engine_plots.py")
SWEEP_PLOTS = os.path.join(SOURCE, "tools", "plots", "sweep_plots.py")
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAILED:", what)


def is_png(path):
    """A PNG file of more than 1 kB (a plot, not an empty canvas)."""
    if not os.path.exists(path):
        return False
    with open(path, "rb") as f:
        return f.read(8) == PNG_MAGIC and os.path.getsize(path) > 1000


def run(args, cwd):
    return subprocess.run(args, cwd=cwd, capture_output=True, text=True)


def check_campbell_plot(work):
    """campbell_plot.py on `emb campbell -o` of the Jeffcott disc: a PNG; a file that is not a
    diagram is refused, naming the missing key."""
    scene = os.path.join(SOURCE, "tools", "scenes", "jeffcott_disc.yaml")
    r = run([EMB, "campbell", "-q", scene, "--rpm", "500:6000:500", "--body", "disc",
             "--fmax", "300", "-o", "campbell.json"], work)
    check(r.returncode == 0, "emb campbell ran (%s)" % r.stderr.strip())
    script = os.path.join(SOURCE, "tools", "plots", "campbell_plot.py")
    r = run(["/usr/bin/python3", script, "campbell.json", "--out", "campbell.png"], work)
    check(r.returncode == 0, "campbell_plot.py ran (%s)" % r.stderr.strip())
    png = os.path.join(work, "campbell.png")
    check(os.path.exists(png) and open(png, "rb").read(8) == PNG_MAGIC, "campbell.png is a PNG")
    with open(os.path.join(work, "not_campbell.json"), "w") as f:
        json.dump({"rpm": [1000]}, f)
    r = run(["/usr/bin/python3", script, "not_campbell.json", "--out", "bad.png"], work)
    check(r.returncode == 1 and "modes" in r.stderr, "a non-diagram is refused (%s)" % r.stderr)


def check_engine_plots(work):
    with open(os.path.join(work, "spin.yaml"), "w") as f:
        f.write("bodies:\n  - {name: tube, model: cms, body_file: tube.h5, "
                "angular_velocity: [314.159265, 0, 0]}\n")
        f.write("analysis: {type: dynamic, t_end: 0.045, output_step: 1.0e-4}\n")
    r = run([EMB, "run", "spin.yaml", "-q", "-o", "spin.h5"], work)
    if r.returncode != 0:
        sys.exit("emb run failed: " + r.stderr)
    plots = ["/usr/bin/python3", ENGINE_PLOTS, "spin.h5", "--angle", "tube", "--axis", "x",
             "--out", "plots", "--emb", EMB]
    r = run(plots + ["--traces", "tube.omega.x,energy.total", "--spectrum", "tube.omega.x"], work)
    check(r.returncode == 0, "engine_plots.py exit code 0: " + r.stderr)
    for png in ("spin_traces.png", "spin_spectrum_tube_omega_x.png"):
        check(is_png(os.path.join(work, "plots", png)), "engine_plots.py wrote a PNG " + png)
    r = run(plots + ["--traces", "tube.spin.x"], work)
    check(r.returncode != 0 and "tube.spin.x" in r.stderr,
          "unknown channel: non-zero exit naming it (%s)" % r.stderr.strip()[-200:])


def check_sweep_plots(work):
    """sweep_plots.py on a small sweep of tests/sweep/data/one_cylinder_direct.yaml, with the
    critical speeds as `emb campbell --json` gives them (a list under some key) and as a bare
    list; a malformed critical-speed file or an unknown channel is a non-zero exit naming it."""
    scene = os.path.join(SOURCE, "tests", "sweep", "data", "one_cylinder_direct.yaml")
    r = run([EMB, "sweep", scene, "--rpm", "2000,3000", "--orders", "0.5:3:0.5", "-q", "-o",
             "sw.h5"], work)
    if r.returncode != 0:
        sys.exit("emb sweep failed: " + r.stderr)
    with open(os.path.join(work, "campbell.json"), "w") as f:
        json.dump({"summary": {}, "crossings": [
            {"order": 1.0, "rpm": 2500, "mode_hz": 41.7, "class": "torsion"},
            {"order": 2.0, "rpm": 2600, "mode_hz": 86.7, "class": "bending"}]}, f)
    with open(os.path.join(work, "bad.json"), "w") as f:
        json.dump([{"order": "x", "rpm": 1}], f)
    plots = ["/usr/bin/python3", SWEEP_PLOTS, "sw.h5", "--out", "sweep_plots"]
    r = run(plots + ["--critical", "campbell.json", "--critical-class", "torsion"], work)
    check(r.returncode == 0, "sweep_plots.py exit code 0: " + r.stderr)
    for png in ("sw_waterfall_crank_speed_T_z.png", "sw_order_cuts_crank_speed_T_z.png"):
        check(is_png(os.path.join(work, "sweep_plots", png)), "sweep_plots.py wrote a PNG " + png)
    # Crossings of modes the torsion channel sees: by torsion share, whatever their class.
    with open(os.path.join(work, "shares.json"), "w") as f:
        json.dump({"crossings": [
            {"order": 1.0, "rpm": 2500, "mode_hz": 41.7, "class": "torsion", "torsion": 0.9},
            {"order": 2.0, "rpm": 2600, "mode_hz": 86.7, "class": "bending", "torsion": 0.48},
            {"order": 2.0, "rpm": 2900, "mode_hz": 96.7, "class": "bending", "torsion": 0.02}]}, f)
    sys.path.insert(0, os.path.dirname(SWEEP_PLOTS))
    import sweep_plots
    kept = sweep_plots.read_critical(os.path.join(work, "shares.json"), None, 0.25)
    check([c[1] for c in kept] == [2500.0, 2600.0],
          "--critical-min-torsion keeps the coupled mode, drops the pure bending one (%r)" % kept)
    r = run(plots + ["--critical", "shares.json", "--critical-min-torsion", "0.25"], work)
    check(r.returncode == 0, "sweep_plots.py --critical-min-torsion exit code 0: " + r.stderr)
    r = run(plots + ["--critical", "campbell.json", "--critical-min-torsion", "0.25"], work)
    check(r.returncode != 0 and "torsion" in r.stderr,
          "crossings without torsion shares: non-zero exit (%s)" % r.stderr.strip()[-200:])
    r = run(plots + ["--critical", "bad.json"], work)
    check(r.returncode != 0 and "bad.json" in r.stderr, "bad critical speeds: non-zero exit "
          "naming the file (%s)" % r.stderr.strip()[-200:])
    r = run(plots + ["--channel", "nope.T.z"], work)
    check(r.returncode != 0 and "nope.T.z" in r.stderr, "unknown channel: non-zero exit")


def check_sensor_and_force_channels(work):
    """engine_plots.py reads every kind of channel emb does: sensor components and force
    elements' loads equal the CSV emb run writes for them (issue 14)."""
    with open(os.path.join(work, "pend.yaml"), "w") as f:
        f.write("""gravity: [0, -9.81, 0]
bodies:
  - {name: rod, mass: 1.0, inertia: [1.0e-4, 0.083, 0.083], position: [0.5, 0, 0]}
markers:
  - {name: pivot, body: ground, position: [0, 0, 0]}
  - {name: anchor, body: ground, position: [1.0, 0.3, 0]}
  - {name: rod_top, body: rod, position: [-0.5, 0, 0]}
  - {name: rod_tip, body: rod, position: [0.5, 0, 0]}
joints:
  - {name: hinge, type: revolute, i: rod_top, j: pivot}
forces:
  - {name: spring, type: spring-damper, i: rod_tip, j: anchor, stiffness: 50, damping: 0.5}
  - {name: mount, type: bushing, i: rod_tip, j: anchor,
     stiffness: [10, 10, 10, 1, 1, 1], damping_factor: 0.01}
sensors:
  - {name: tip, i: rod_tip, j: pivot}
  - {name: bend, type: chord, point: anchor, chord: [rod_top, rod_tip]}
analysis: {type: dynamic, t_end: 0.2, output_step: 0.01}
output: {csv: pend.csv, channels: [tip.dx, tip.rz, mount.F.x, mount.T.z, hinge.F.y, mount.F.norm,
                                   bend.dy, bend.norm, bend.s]}
""")
    r = run([EMB, "run", "pend.yaml", "-q", "-o", "pend.h5"], work)
    if r.returncode != 0:
        sys.exit("emb run failed: " + r.stderr)
    sys.path.insert(0, os.path.dirname(ENGINE_PLOTS))
    import engine_plots  # noqa: E402
    with open(os.path.join(work, "pend.csv")) as f:
        header = f.readline().strip().split(",")
    table = np.loadtxt(os.path.join(work, "pend.csv"), delimiter=",", skiprows=1)
    with h5py.File(os.path.join(work, "pend.h5"), "r") as f:
        for name in ("tip.dx", "tip.rz", "mount.F.x", "mount.T.z", "hinge.F.y", "mount.F.norm",
                     "bend.dy", "bend.norm", "bend.s"):
            check(name in header, "CSV column of %s (%s)" % (name, header))
            if name not in header:
                continue
            got = engine_plots.channel(f, name)
            want = table[:, header.index(name)]
            # The CSV prints 10 significant digits.
            check(np.allclose(got, want, rtol=1e-8, atol=1e-10 * np.abs(want).max()),
                  "engine_plots channel %s equals emb's CSV" % name)
            check(np.abs(want).max() > 0, "channel %s is not trivially zero" % name)
    # emb spectrum reads the same channels from the results file: at 600 rpm the 0.2 s run is
    # one 720-degree cycle, whose order-0 term is the channel's mean over it (the trapezoidal
    # mean of the CSV samples agrees to its 20-sample resolution, 2 %).
    for name in ("mount.F.norm", "bend.norm"):
        sp = run([EMB, "spectrum", "pend.h5", "--channel", name, "--rpm", "600", "--json"], work)
        check(sp.returncode == 0, "emb spectrum reads %s: %s" % (name, sp.stderr))
        if sp.returncode == 0 and name in header:
            mean = json.loads(sp.stdout)["summary"]["mean"]
            col = table[:, header.index(name)]
            want = np.trapz(col, dx=1.0) / (len(col) - 1)
            check(abs(mean - want) <= 0.02 * abs(want), "%s: spectrum mean %g, CSV mean %g"
                  % (name, mean, want))
    r = run(["/usr/bin/python3", ENGINE_PLOTS, "pend.h5", "--time", "--traces", "spring.F.x",
             "--out", "plots", "--emb", EMB], work)
    check(r.returncode != 0 and "spring" in r.stderr,
          "a force element without loads: non-zero exit naming it (%s)" % r.stderr.strip()[-200:])


# A small stand-in for the inline-4 engine with the channel names of the README's example:
# a crank driven at 3000 rpm (motion crank_speed), a flywheel on a torsional coupling
# (sensor nose_torsion across it) and a bushing main_bearing3 carrying its weight.
MINI_ENGINE = """name: mini_engine
gravity: [0, -9.81, 0]
bodies:
  - {name: crank, mass: 10.0, inertia: [0.02, 0.05, 0.05], angular_velocity: [314.159265, 0, 0]}
  - {name: flywheel, mass: 8.0, inertia: [0.1, 0.06, 0.06], position: [0.3, 0, 0],
     angular_velocity: [314.159265, 0, 0]}
markers:
  - {name: block_main, body: ground, orientation: {z_axis: [1, 0, 0]}}
  - {name: crank_main, body: crank, orientation: {z_axis: [1, 0, 0]}}
  - {name: crank_nose, body: crank, frame: world, position: [0.3, 0, 0], orientation: {z_axis: [1, 0, 0]}}
  - {name: flywheel_hub, body: flywheel, frame: world, position: [0.3, 0, 0], orientation: {z_axis: [1, 0, 0]}}
  - {name: block_mj3, body: ground, frame: world, position: [0.3, 0, 0], orientation: {z_axis: [1, 0, 0]}}
joints:
  - {name: main, type: revolute, i: crank_main, j: block_main}
motions:
  - {name: crank_speed, joint: main, function: {rpm: 3000}}
forces:
  - {name: coupling, type: bushing, i: flywheel_hub, j: crank_nose,
     stiffness: [1.0e8, 1.0e8, 1.0e8, 1.0e4, 1.0e5, 1.0e5], damping_factor: 1.0e-4}
  - {name: main_bearing3, type: bushing, i: flywheel_hub, j: block_mj3,
     stiffness: [1.0e7, 1.0e7, 1.0e7, 0, 0, 0], damping_factor: 1.0e-4}
sensors:
  - {name: nose_torsion, i: crank_nose, j: flywheel_hub}
analysis: {type: dynamic, t_end: 0.08, output_step: 2.0e-4}
"""


def check_readme_example(work):
    """The engine_plots.py command line the README gives for the inline-4 run plots, as
    written, on a small model with the same channel names (issue 14: it could not)."""
    import re
    with open(os.path.join(SOURCE, "README.md")) as f:
        readme = f.read()
    m = re.search(r"/usr/bin/python3 tools/plots/engine_plots\.py out/inline4\.h5 ([^`]*)`", readme)
    check(m is not None, "README.md gives an engine_plots.py example for out/inline4.h5")
    if m is None:
        return
    args = m.group(1).split()
    with open(os.path.join(work, "mini.yaml"), "w") as f:
        f.write(MINI_ENGINE)
    r = run([EMB, "run", "mini.yaml", "-q", "-o", "mini.h5"], work)
    if r.returncode != 0:
        sys.exit("emb run failed: " + r.stderr)
    args = [a.replace("out/plots", "readme_plots") for a in args]
    r = run(["/usr/bin/python3", ENGINE_PLOTS, "mini.h5", *args, "--emb", EMB], work)
    check(r.returncode == 0, "the README's engine_plots.py example plots: " + r.stderr)
    written = [w.split(" ", 1)[1] for w in r.stdout.splitlines() if w.startswith("wrote ")]
    check(len(written) == 2, "traces and spectrum written (%s)" % written)
    for path in written:
        with open(os.path.join(work, path), "rb") as f:
            check(f.read(8) == PNG_MAGIC, "%s is a PNG" % path)


def check_steady_cycle(work):
    """A run to periodic steady state (analysis.steady_state) marks its steady cycle; the
    traces show only that cycle by default and every sample with --all-cycles, and the
    spectrum's cycle count is that of `emb spectrum`'s default, the steady cycle (issue 19).
    The mini engine's flywheel starts 5 % fast: its torsional transient on the coupling
    decays over a few cycles."""
    scene = MINI_ENGINE.replace("""position: [0.3, 0, 0],
     angular_velocity: [314.159265, 0, 0]}""", """position: [0.3, 0, 0],
     angular_velocity: [329.867, 0, 0]}""").replace(
        "analysis: {type: dynamic, t_end: 0.08, output_step: 2.0e-4}",
        "analysis: {type: dynamic, output_step: 2.0e-4, steady_state: {period: 0.04, "
        "channels: [main_bearing3.F.y], tolerance: 1.0e-2, max_cycles: 30}}")
    check("329.867" in scene and "steady_state" in scene, "the steady-state mini engine scene")
    with open(os.path.join(work, "steady.yaml"), "w") as f:
        f.write(scene)
    r = run([EMB, "run", "steady.yaml", "-q", "-o", "steady.h5"], work)
    if r.returncode != 0:
        sys.exit("emb run (steady state) failed: " + r.stderr)
    with h5py.File(os.path.join(work, "steady.h5"), "r") as f:
        check(int(f.attrs["steady_state_converged"]) == 1, "the mini engine reaches steady state")
        start, end = float(f.attrs["steady_state_cycle_start"]), float(f.attrs["steady_state_cycle_end"])
        cycles = int(f.attrs["steady_state_cycles"])
        t = f["time"][:]
    check(cycles >= 3 and abs(end - start - 0.04) < 1e-12 and abs(end - t[-1]) < 1e-12,
          "the steady cycle is the last 0.04 s of at least 3 cycles (%d, %g .. %g)"
          % (cycles, start, end))
    base = ["/usr/bin/python3", ENGINE_PLOTS, "steady.h5", "--angle", "main", "--traces",
            "main_bearing3.F.y", "--out", "plots", "--emb", EMB]
    r = run(base + ["--spectrum", "main_bearing3.F.y", "--orders", "4"], work)
    check(r.returncode == 0, "engine_plots.py on a steady-state run: " + r.stderr)
    # 0.04 s at 2e-4 s a sample: 201 samples with the cycle's end.
    want = "traces: 201 samples, t = %.6g .. %.6g s (the steady cycle)" % (start, end)
    check(want in r.stdout, "traces of the steady cycle only: %r in %r" % (want, r.stdout))
    r = run(base + ["--all-cycles"], work)
    check(r.returncode == 0 and "traces: %d samples" % len(t) in r.stdout,
          "--all-cycles: every sample (%s)" % r.stdout)
    spectrum = run([EMB, "spectrum", "steady.h5", "--channel", "main_bearing3.F.y", "--angle",
                    "main", "--json"], work)
    check(spectrum.returncode == 0, "emb spectrum of the steady run: " + spectrum.stderr)
    if spectrum.returncode == 0:
        import json
        summary = json.loads(spectrum.stdout)["summary"]
        check(summary["cycles"] == 1, "emb spectrum analyses the one steady cycle (%s)" % summary)


CLONK_PLOTS = os.path.join(SOURCE, "tools", "plots", "clonk_plots.py")


def check_clonk_plots(work, num_modes):
    """clonk_plots.py on a run with a lash (two discs that hit its stops) and output points on
    the vibrating coarse tube: the five PNGs, the contacts counted as the results file lists
    them, eleven 1/3-octave bands per clonk window, and an unknown channel named."""
    eta0 = ", ".join(repr(1e-4 * (k + 1)) for k in range(num_modes))
    with open(os.path.join(work, "clonk.yaml"), "w") as f:
        f.write("""bodies:
  - {name: a, mass: 1.0, inertia: [0.01, 0.01, 0.02], angular_velocity: [0, 0, 5]}
  - {name: b, mass: 1.0, inertia: [0.025, 0.025, 0.05], position: [0.2, 0, 0]}
  - {name: tube, model: cms, body_file: tube.h5, position: [0, 1, 0], modal_coordinates: [%s]}
markers:
  - {name: ga, body: ground, frame: world, position: [0, 0, 0]}
  - {name: gb, body: ground, frame: world, position: [0.2, 0, 0]}
  - {name: ha, body: a}
  - {name: hb, body: b}
joints:
  - {name: ja, type: revolute, i: ha, j: ga}
  - {name: jb, type: revolute, i: hb, j: gb}
forces:
  - {name: mesh, type: lash, joint1: ja, joint2: jb, ratio: 2.0, lash: 0.02,
     contact: {law: hunt-crossley, stiffness: 2.0e3, restitution: 0.7}}
output_points:
  - {name: mid, body: tube, position: [0.3, 0, 0.045], direction: radial,
     axis: {point: [0, 0, 0], direction: [1, 0, 0]}}
  - {name: noise, body: tube, group: outer, quantity: radiated_power}
analysis: {type: dynamic, t_end: 0.03, output_step: 1.0e-4, rtol: 1.0e-7}
""" % eta0)
    r = run([EMB, "run", "clonk.yaml", "-q", "-o", "clonk.h5"], work)
    if r.returncode != 0:
        sys.exit("emb run failed: " + r.stderr)
    plots = ["/usr/bin/python3", CLONK_PLOTS, "clonk.h5", "--out", "clonk_png", "--json",
             "--window", "0.005"]
    r = run(plots + ["--accel", "mid.a.n", "--power", "noise.power"], work)
    check(r.returncode == 0, "clonk_plots.py exit code 0: " + r.stderr)
    metrics = json.loads(r.stdout) if r.returncode == 0 else {"elements": {}, "windows": []}
    with h5py.File(os.path.join(work, "clonk.h5"), "r") as f:
        contacts = f["events/contacts"][()]
    check(len(contacts) >= 2 and metrics["elements"].get("mesh", {}).get("contacts") == len(contacts),
          "clonk_plots counts the results file's contacts (%d)" % len(contacts))
    check(len(metrics["windows"]) >= 1 and all(len(w["band_levels_db"]) == 11 for w in metrics["windows"]),
          "eleven 1/3-octave bands per clonk window")
    for png in ("impacts", "surface", "spectrogram", "bands", "noise"):
        path = os.path.join(work, "clonk_png", "clonk_%s.png" % png)
        ok = os.path.exists(path)
        if ok:
            with open(path, "rb") as fp:
                ok = fp.read(8) == PNG_MAGIC and os.path.getsize(path) > 1000
        check(ok, "clonk_plots.py wrote a PNG clonk_%s.png" % png)
    r = run(plots + ["--accel", "nowhere.a.n"], work)
    check(r.returncode != 0 and "nowhere.a.n" in r.stderr,
          "unknown output point channel: non-zero exit naming it (%s)" % r.stderr.strip()[-200:])


def check_bearing_plots(work):
    """bearing_plots.py on a rotor in a film bearing (Swift-Stieber, coarse grid): the orbit and
    film PNGs; the orbit's largest e/c from eccentricity_x, _y and the scene's clearance equals
    the element's own eccentricity_ratio channel; an element that is not a film bearing is
    refused, naming it and the film bearings there are."""
    scene = os.path.join(work, "rotor.yaml")
    with open(scene, "w") as f:
        f.write("bodies:\n  - {name: rotor, mass: 100.0, inertia: [6.0, 6.0, 10.0], "
                "position: [0, -5.0e-6, 0], angular_velocity: [0, 0, 314.159]}\n"
                "markers:\n  - {name: bore, body: ground}\n  - {name: journal, body: rotor}\n"
                "joints:\n  - {name: plane, type: planar, i: journal, j: bore}\n"
                "forces:\n  - {name: main, type: film-bearing, i: journal, j: bore, radius: 0.03,"
                " length: 0.02, clearance: 3.0e-5, viscosity: 0.0086, grid_circumferential: 16,"
                " grid_axial: 4, cavitation: reynolds}\n"
                "gravity: [0, -9.81, 0]\n"
                "analysis: {type: dynamic, t_end: 0.02, output_step: 5.0e-4}\n")
    r = run([EMB, "run", scene, "-q", "-o", "rotor.h5"], work)
    if r.returncode != 0:
        sys.exit("emb run (film rotor) failed: " + r.stderr)
    script = os.path.join(SOURCE, "tools", "plots", "bearing_plots.py")
    r = run(["/usr/bin/python3", script, "rotor.h5", "--bearing", "main", "--out", "bp",
             "--json"], work)
    check(r.returncode == 0, "bearing_plots.py exit code 0: " + r.stderr)
    if r.returncode == 0:
        summary = json.loads(r.stdout)
        for png in summary["written"]:
            check(is_png(os.path.join(work, png)), "bearing plot %s is a PNG" % png)
        with h5py.File(os.path.join(work, "rotor.h5"), "r") as f:
            channels = [c.decode() for c in f["model/force_output_channels"][:]]
            ratio = f["forces/outputs"][:, channels.index("main.eccentricity_ratio")]
        check(abs(summary["max_eccentricity_ratio"] - ratio.max()) <= 1e-12,
              "orbit's largest e/c %.15g equals the eccentricity_ratio channel's %.15g"
              % (summary["max_eccentricity_ratio"], ratio.max()))
        check(summary["samples"] == len(ratio), "orbit over every sample")
    r = run(["/usr/bin/python3", script, "rotor.h5", "--bearing", "plane", "--out", "bp2"], work)
    check(r.returncode != 0 and "'plane'" in r.stderr and "main" in r.stderr
          and not os.path.exists(os.path.join(work, "bp2")),
          "an element that is not a film bearing is refused, naming it: " + r.stderr)


def main():
    work = tempfile.mkdtemp(prefix="emb_animate_")
    check_readme_example(work)
    check_bearing_plots(work)
    check_sensor_and_force_channels(work)
    geo = os.path.join(SOURCE, "meshes", "tube.geo")
    coarse = ["--set", "n_wall=1", "--set", "n_circ=8", "--set", "h=0.1", "--set", "L=0.6",
              "-n", "4", "--no-reference", "--no-xdmf", "-q"]
    for out, extra in (("tube.h5", []), ("bare.h5", ["--no-mesh-shapes"])):
        r = run([EMB, "reduce", geo, *coarse, *extra, "-o", out], work)
        if r.returncode != 0:
            sys.exit("emb reduce failed: " + r.stderr)
    with h5py.File(os.path.join(work, "tube.h5"), "r") as b:
        num_modes = b["modes/mesh_shapes"].shape[0]
    eta0 = [1e-4 * (k + 1) for k in range(num_modes)]
    with open(os.path.join(work, "scene.yaml"), "w") as f:
        f.write("bodies:\n  - {name: tube, model: cms, body_file: tube.h5, modal_coordinates: "
                "[%s]}\n" % ", ".join(repr(e) for e in eta0))
        f.write("analysis: {type: dynamic, t_end: 1.0e-3, output_step: 2.0e-4}\n")
    r = run([EMB, "run", "scene.yaml", "-q", "-o", "run.h5"], work)
    if r.returncode != 0:
        sys.exit("emb run failed: " + r.stderr)

    scale = 50.0
    r = run(["/usr/bin/python3", SCRIPT, "run.h5", "tube.h5", "--body", "tube", "--scale",
             str(scale), "-o", "anim.xdmf"], work)
    check(r.returncode == 0, "animate_body.py exit code 0: " + r.stderr)

    with h5py.File(os.path.join(work, "run.h5"), "r") as res:
        time = res["time"][()]
        eta = res["state/eta"][()]
    with h5py.File(os.path.join(work, "tube.h5"), "r") as b:
        shapes = b["modes/mesh_shapes"][()]
        nodes = b["mesh/nodes"][()]
    tree = ET.parse(os.path.join(work, "anim.xdmf"))
    frames = tree.getroot().findall("./Domain/Grid/Grid")
    check(len(frames) == len(time), "one frame per output time (%d, %d)" % (len(frames), len(time)))
    with h5py.File(os.path.join(work, "anim.h5"), "r") as anim:
        for i, g in enumerate(frames):
            t = float(g.find("Time").get("Value"))
            check(abs(t - time[i]) <= 1e-9 * max(1.0, abs(time[i])), "frame %d time" % i)
            for item in g.iter("DataItem"):
                path = item.text.split(":", 1)[1]
                dims = tuple(int(d) for d in item.get("Dimensions").split())
                check(path in anim and anim[path].shape == dims,
                      "frame %d: %s with dimensions %s" % (i, path, dims))
        # Rounding of the stored data: 8-byte floats, values ~1e-3 m.
        tol = 1e-12
        u0 = anim["steps/0/displacement"][()]
        expected = np.tensordot(np.array(eta0), shapes, axes=1)
        check(np.abs(u0 - expected).max() <= tol, "frame 0 = initial modal coordinates x shapes")
        check(np.abs(expected).max() > 1e-6, "the initial deformation is not trivially zero")
        for i in range(len(time)):
            u = anim["steps/%d/displacement" % i][()]
            check(np.abs(u - np.tensordot(eta[i], shapes, axes=1)).max() <= tol,
                  "frame %d follows the run's modal coordinates" % i)
            check(np.abs(anim["steps/%d/geometry" % i][()] - (nodes + scale * u)).max() <= tol,
                  "frame %d geometry = nodes + scale x displacement" % i)
        check(np.abs(anim["steps/%d/displacement" % (len(time) - 1)][()] - u0).max() > 1e-8,
              "the body vibrates (the last frame differs from the first)")

    for args, name, what in ((["run.h5", "tube.h5", "--body", "shaft"], "shaft", "unknown body"),
                             (["run.h5", "bare.h5", "--body", "tube"], "bare.h5", "no mesh shapes")):
        out = "bad_%s.xdmf" % name.replace(".", "_")
        r = run(["/usr/bin/python3", SCRIPT, *args, "-o", out], work)
        check(r.returncode != 0 and name in r.stderr, "%s: non-zero exit naming '%s' (%s)"
              % (what, name, r.stderr.strip()))
        check(not os.path.exists(os.path.join(work, out)), "%s: no output written" % what)

    check_engine_plots(work)
    check_sweep_plots(work)
    check_steady_cycle(work)
    check_clonk_plots(work, num_modes)
    check_campbell_plot(work)
    if failures:
        sys.exit("%d check(s) failed; files kept in %s" % (len(failures), work))
    shutil.rmtree(work)
    print("all checks passed")


if __name__ == "__main__":
    main()
