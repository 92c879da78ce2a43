"""Deformed-shape animation of a flexible body from a multibody results file.

    /usr/bin/python3 tools/plots/animate_body.py RESULTS.h5 BODY_FILE.h5 --body crank \
        [--scale 200] [--every 2] -o crank_anim.xdmf

Reads the modal coordinates of `--body` (/state/eta, /model/flexible_bodies,
/model/num_modes: the part kept the file's lowest modes, a prefix of /modes/mesh_shapes)
and the body file's mesh (/mesh/nodes, /viz/<cell type>) and mode shapes
(/modes/mesh_shapes, written unless `emb reduce --no-mesh-shapes`), and writes an XDMF
temporal collection (ParaView, gmsh) with the geometry x + scale * Phi eta per output time,
in the body frame (the rigid motion removed, so the magnified deformation is what moves),
plus the displacement field itself. The heavy data go to OUTPUT.h5 next to the .xdmf.
"""
import argparse
import os
import sys

import h5py
import numpy as np
from results_status import warn_if_unfinished  # tools/plots/results_status.py

TOPOLOGY = {"Tet4": ("Tetrahedron", 4), "Tet10": ("Tet_10", 10),
            "Hex8": ("Hexahedron", 8), "Hex20": ("Hex_20", 20),
            "Wedge6": ("Wedge", 6), "Wedge15": ("Wedge_15", 15)}


def names(ds):
    return [n.decode() if isinstance(n, bytes) else str(n) for n in ds[()]]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("results")
    p.add_argument("body_file")
    p.add_argument("--body", required=True, help="name of the flexible part in the scene")
    p.add_argument("--scale", type=float, default=100.0, help="magnification of the deformation")
    p.add_argument("--every", type=int, default=1, help="keep every k-th output time")
    p.add_argument("-o", "--output", required=True, help="XDMF file to write")
    a = p.parse_args()
    with h5py.File(a.results, "r") as r:
        warn_if_unfinished(r, a.results)
        if "model/flexible_bodies" not in r:
            sys.exit(f"{a.results}: no flexible bodies in this run")
        flex = names(r["model/flexible_bodies"])
        if a.body not in flex:
            sys.exit(f"{a.results}: '{a.body}' is not a flexible body of this run; it has {flex}")
        counts = [int(c) for c in r["model/num_modes"][()]]
        k = flex.index(a.body)
        start = sum(counts[:k])
        eta = r["state/eta"][:, start:start + counts[k]][::a.every]
        time = r["time"][()][::a.every]
    with h5py.File(a.body_file, "r") as b:
        if "modes/mesh_shapes" not in b:
            sys.exit(f"{a.body_file}: no mode shapes at the nodes (reduced with --no-mesh-shapes)")
        shapes = b["modes/mesh_shapes"][: eta.shape[1]]  # (ne, n, 3)
        nodes = b["mesh/nodes"][()]
        viz = {t: b["viz/" + t][()] for t in b["viz"].keys() if t in TOPOLOGY}
    if shapes.shape[0] < eta.shape[1]:
        sys.exit(f"{a.body_file} has {shapes.shape[0]} mode shapes, the run kept {eta.shape[1]}")
    h5_path = os.path.splitext(a.output)[0] + ".h5"
    h5_name = os.path.basename(h5_path)
    tmp = h5_path + ".tmp"
    with h5py.File(tmp, "w") as out:
        for t, cells in viz.items():
            out["cells/" + t] = cells
        for i in range(len(time)):
            u = np.tensordot(eta[i], shapes, axes=1)  # (n, 3)
            out[f"steps/{i}/geometry"] = nodes + a.scale * u
            out[f"steps/{i}/displacement"] = u
    os.replace(tmp, h5_path)
    n = nodes.shape[0]
    lines = ['<?xml version="1.0" ?>', '<Xdmf Version="3.0">', " <Domain>",
             '  <Grid Name="%s" GridType="Collection" CollectionType="Temporal">' % a.body]
    for i, ti in enumerate(time):
        for t, cells in viz.items():
            name, per = TOPOLOGY[t]
            lines += ['   <Grid Name="%s_%d" GridType="Uniform">' % (t, i),
                      '    <Time Value="%.9g"/>' % ti,
                      '    <Topology TopologyType="%s" NumberOfElements="%d">' % (name, cells.shape[0]),
                      '     <DataItem Dimensions="%d %d" NumberType="Int" Format="HDF">%s:/cells/%s</DataItem>' % (cells.shape[0], per, h5_name, t),
                      "    </Topology>",
                      '    <Geometry GeometryType="XYZ">',
                      '     <DataItem Dimensions="%d 3" NumberType="Float" Precision="8" Format="HDF">%s:/steps/%d/geometry</DataItem>' % (n, h5_name, i),
                      "    </Geometry>",
                      '    <Attribute Name="displacement" AttributeType="Vector" Center="Node">',
                      '     <DataItem Dimensions="%d 3" NumberType="Float" Precision="8" Format="HDF">%s:/steps/%d/displacement</DataItem>' % (n, h5_name, i),
                      "    </Attribute>",
                      "   </Grid>"]
    lines += ["  </Grid>", " </Domain>", "</Xdmf>"]
    with open(a.output + ".tmp", "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(a.output + ".tmp", a.output)
    print(f"{a.output}: {len(time)} frames, {n} nodes, scale {a.scale}")


if __name__ == "__main__":
    main()
