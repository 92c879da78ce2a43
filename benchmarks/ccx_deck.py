#!/usr/bin/python3
"""CalculiX side of benchmarks/ccx_vs_emb.sh.

  deck MESH.inp DECK.inp MODES   a CalculiX *FREQUENCY deck (free-free, MODES modes, steel
                                 E = 210 GPa, nu = 0.3, rho = 7850 kg/m^3 as emb's defaults)
                                 from the Abaqus file gmsh writes of an emb mesh: its nodes
                                 and its C3D10 cells (gmsh writes them in Abaqus node order)
  result DECK.dat TIME.txt OUT.json   frequencies [Hz] from the .dat eigenvalue table, wall
                                 time and peak memory from `/usr/bin/time -v`, as JSON
"""
import json
import math
import re
import sys


def deck(src, dst, modes):
    nodes, cells, mode = [], [], None
    for line in open(src):
        if line.startswith("*"):
            u = line.upper().replace(" ", "")
            mode = "node" if u.startswith("*NODE") else (
                "c3d10" if u.startswith("*ELEMENT") and "TYPE=C3D10" in u else None)
            continue
        if mode == "node":
            nodes.append(line)
        elif mode == "c3d10":
            cells.append(line)
    if not nodes or not cells:
        sys.exit(f"ccx_deck.py: expected nodes and C3D10 cells in {src}")
    with open(dst, "w") as out:
        out.write("*NODE\n")
        out.writelines(nodes)
        out.write("*ELEMENT, TYPE=C3D10, ELSET=EALL\n")
        out.writelines(cells)
        out.write("*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850.\n")
        out.write("*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n")
        out.write(f"*STEP\n*FREQUENCY\n{modes}\n*END STEP\n")


def result(dat, timing, out):
    eigenvalues, inside = [], False
    for line in open(dat):
        if "E I G E N V A L U E   O U T P U T" in line:
            inside = True
            continue
        if inside and "P A R T I C I P A T I O N" in line:
            break
        parts = line.split()
        if inside and len(parts) == 5 and parts[0].isdigit():
            eigenvalues.append(float(parts[1]))
    seconds = peak_kb = None
    for line in open(timing):
        if "Elapsed (wall clock)" in line:
            t = line.rsplit(" ", 1)[1].strip().split(":")
            seconds = sum(float(x) * 60 ** i for i, x in enumerate(reversed(t)))
        m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", line)
        if m:
            peak_kb = int(m.group(1))
    hz = [math.copysign(math.sqrt(abs(l)), l) / (2 * math.pi) for l in eigenvalues]
    with open(out, "w") as f:
        json.dump({"seconds": seconds, "peak_memory_mb": peak_kb / 1000 if peak_kb else None,
                   "frequencies_hz": hz}, f, indent=1)


if __name__ == "__main__":
    if len(sys.argv) == 5 and sys.argv[1] == "deck":
        deck(sys.argv[2], sys.argv[3], int(sys.argv[4]))
    elif len(sys.argv) == 5 and sys.argv[1] == "result":
        result(sys.argv[2], sys.argv[3], sys.argv[4])
    else:
        sys.exit(__doc__)
