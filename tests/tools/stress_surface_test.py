"""The whole-surface stress field read without emb (h5py) and its XDMF parsed (issue 17).

    /usr/bin/python3 tests/tools/stress_surface_test.py EMB_EXECUTABLE WORK_DIR

A Tet10 bar (gmsh) reduced with `--stress-surface` and run clamped with a tip force: the body
file's /stress/surface (nodes on the bar's boundary, coordinates = the mesh's, face indices in
range, modal stresses (6 s, ne)); the run's .stress.h5 (von Mises, sigma_1 and signed von Mises
recomputed with numpy from the six components); the .stress.xdmf parsed as XML, every HDF
DataItem pointing at a dataset of exactly its Dimensions, topology Tri_6 with NumberOfElements
= the faces, times = the field's times; a body file without surface stresses refused (exit 1,
naming the file and --stress-surface, no field file written).
"""
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

EMB, WORK = sys.argv[1], sys.argv[2]
L, B, H = 0.5, 0.05, 0.05  # bar [m]
ON_PLANE = 1e-9            # [m] gmsh places boundary nodes on the box planes
ROUND_OFF = 1e-9           # relative: the same formulas in C++ and numpy
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAILED:", what)


def run(args):
    return subprocess.run([EMB] + args, cwd=WORK, capture_output=True, text=True)


def scene(name, body, stress_outputs):
    with open(os.path.join(WORK, name), "w") as f:
        f.write(f"""bodies:
  - {{name: bar, model: cms, body_file: {body}}}
markers:
  - {{name: root, body: bar, interface: x0}}
  - {{name: tip, body: bar, interface: x1}}
  - {{name: base, body: ground, frame: world, position: [0, 0.025, 0.025]}}
joints:
  - {{name: clamp, type: fixed, i: root, j: base}}
forces:
  - {{name: load, type: force, marker: tip, direction: [0, 0, 1], function: {{constant: 200}}}}
stress_outputs:
{stress_outputs}analysis: {{type: dynamic, t_end: 0.002, output_step: 5.0e-4}}
""")


def check_xdmf(path, h5_path):
    root = ET.parse(path).getroot()
    h5 = h5py.File(h5_path, "r")
    items = root.iter("DataItem")
    n_hdf = 0
    for item in items:
        if item.get("Format") != "HDF":
            continue
        n_hdf += 1
        file, dataset = item.text.strip().split(":", 1)
        check(file == os.path.basename(h5_path), f"XDMF DataItem file {file}")
        dims = tuple(int(x) for x in item.get("Dimensions").split())
        check(dataset in h5 and h5[dataset].shape == dims,
              f"XDMF DataItem {dataset} {dims} vs HDF5 {h5[dataset].shape if dataset in h5 else None}")
    check(n_hdf > 0, "XDMF has HDF DataItems")
    grids = [g for g in root.iter("Grid") if g.get("GridType") == "Uniform"]
    surface = [g for g in root.iter("Grid") if g.get("Name") == "s.surface"]
    check(len(surface) == 1, "one temporal collection for the surface")
    steps = surface[0].findall("Grid")
    times = h5["/s/surface/times"][:]
    check(len(steps) == len(times), "one grid per surface field time")
    for step, t in zip(steps, times):
        check(abs(float(step.find("Time").get("Value")) - t) <= 1e-12 * max(1.0, abs(t)),
              "XDMF time = field time")
        topo = step.find("Topology")
        check(topo.get("TopologyType") == "Tri_6", "surface topology Tri_6")
        check(int(topo.get("NumberOfElements")) == h5["/s/surface/faces/Tri6"].shape[0],
              "NumberOfElements = faces")
        names = {a.get("Name"): a.get("AttributeType") for a in step.findall("Attribute")}
        check(names == {"von_mises": "Scalar", "max_principal": "Scalar",
                        "signed_von_mises": "Scalar", "stress": "Tensor6"}, f"attributes {names}")
    check(len(grids) >= len(times), "uniform grids")
    h5.close()


def main():
    os.makedirs(WORK, exist_ok=True)
    with open(os.path.join(WORK, "bar.geo"), "w") as f:
        f.write(f"""SetFactory("OpenCASCADE");
Box(1) = {{0, 0, 0, {L}, {B}, {H}}};
Physical Surface("x0") = {{1}};
Physical Surface("x1") = {{2}};
Physical Surface("z1") = {{6}};
Physical Volume("bar") = {{1}};
Mesh.MeshSizeMax = 0.025;
""")
    common = ["reduce", "bar.geo", "-q", "-n", "4", "--no-reference", "-i", "x0:rbe2", "-i",
              "x1:rbe2", "--stress-groups", "z1"]
    r = run(common + ["--stress-surface", "-o", "body.h5"])
    check(r.returncode == 0, "reduce --stress-surface: " + r.stderr)
    r = run(common + ["-o", "plain.h5"])
    check(r.returncode == 0, "reduce: " + r.stderr)
    with h5py.File(os.path.join(WORK, "body.h5"), "r") as f:
        g = f["/stress/surface"]
        nodes, xyz = g["nodes"][:], g["coordinates"][:]
        types = [t.decode() for t in g["face_types"][:]]
        check(types == ["Tri6"], f"face types {types}")
        faces = g["faces/Tri6"][:]
        check(faces.min() >= 0 and faces.max() < nodes.size, "face indices into nodes")
        check(np.array_equal(np.unique(faces), np.arange(nodes.size)), "every node in a face")
        check(np.array_equal(xyz, f["/mesh/nodes"][:][nodes]), "coordinates = mesh nodes")
        on = np.zeros(nodes.size, bool)
        for axis, size in enumerate((L, B, H)):
            on |= (np.abs(xyz[:, axis]) < ON_PLANE) | (np.abs(xyz[:, axis] - size) < ON_PLANE)
        check(on.all(), "every surface node on the bar's boundary")
        ne = f["/modes/frequencies_hz"].shape[0]
        check(g["modal"].shape == (6 * nodes.size, ne), "modal (6 s, ne)")
        check(g["modal"].dtype == np.float32, "modal stored as float32")
        check(f.attrs["content_digest_version"] == 4, "digest version 4")

    scene("surf.yaml", "body.h5",
          "  - {name: s, body: bar, field_times: [0.001], surface_field_times: [0.001, 0.002]}\n")
    r = run(["run", "-q", "surf.yaml", "-o", "surf.h5"])
    check(r.returncode == 0, "run: " + r.stderr)
    h5_path = os.path.join(WORK, "surf.stress.h5")
    with h5py.File(h5_path, "r") as f:
        sig = f["/s/surface/stress"][:]
        vm = f["/s/surface/von_mises"][:]
        p1 = f["/s/surface/max_principal"][:]
        svm = f["/s/surface/signed_von_mises"][:]
        xx, yy, zz, xy, yz, zx = np.moveaxis(sig, -1, 0)
        vm_np = np.sqrt(0.5 * ((xx - yy) ** 2 + (yy - zz) ** 2 + (zz - xx) ** 2)
                        + 3 * (xy ** 2 + yz ** 2 + zx ** 2))
        T = np.stack([np.stack([xx, xy, zx], -1), np.stack([xy, yy, yz], -1),
                      np.stack([zx, yz, zz], -1)], -2)
        eig = np.linalg.eigvalsh(T)
        scale = np.abs(vm_np).max()
        check(scale > 0, "a stressed surface")
        check(np.abs(vm - vm_np).max() <= ROUND_OFF * scale, "von Mises = numpy's")
        check(np.abs(p1 - eig[..., -1]).max() <= ROUND_OFF * scale, "sigma_1 = numpy's")
        sign = np.where(np.abs(eig[..., -1]) >= np.abs(eig[..., 0]), 1.0, -1.0)
        check(np.abs(svm - sign * vm_np).max() <= ROUND_OFF * scale, "signed von Mises")
        check("faces" in f["/s/z1"], "the group's field has faces")
    check_xdmf(os.path.join(WORK, "surf.stress.xdmf"), h5_path)

    scene("plain.yaml", "plain.h5", "  - {name: s, body: bar, surface_field_times: [0.001]}\n")
    r = run(["run", "-q", "plain.yaml", "-o", "plain_run.h5"])
    check(r.returncode == 1, "a body file without surface stresses: exit 1")
    check("plain.h5" in r.stderr and "--stress-surface" in r.stderr, "error names: " + r.stderr)
    check(not os.path.exists(os.path.join(WORK, "plain_run.stress.h5")), "no field file")
    if failures:
        print(f"{len(failures)} check(s) failed")
        sys.exit(1)
    print("stress surface: all checks passed")


if __name__ == "__main__":
    try:
        main()
    finally:
        shutil.rmtree(WORK, ignore_errors=True)
