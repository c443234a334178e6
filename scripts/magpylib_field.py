#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The field of a diametrically magnetized cylinder from magpylib (an independent implementation:
its analytic solution for the cylinder), for tests/lab/physics/physics_field_vs_magpylib.cpp.

usage: magpylib_field.py IN.json OUT.json
IN:  {"cases": [{"radius_m": R, "height_m": h, "br_T": Br, "points": [[x, y, z], ...]}, ...]}
     (the magnet frame of model/lab/physics/physics_magnet.hpp: axis z, centre at the origin,
     M along +x)
OUT: {"magpylib": VERSION, "cases": [{"B_T": [[Bx, By, Bz], ...]}, ...]}
Run it with the interpreter of the virtual environment scripts/setup.sh makes (.venv/bin/python).
"""

import json
import sys

import magpylib
import numpy as np


def main() -> int:
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    with open(sys.argv[1], encoding="utf-8") as f:
        spec = json.load(f)
    out = {"magpylib": magpylib.__version__, "cases": []}
    for case in spec["cases"]:
        magnet = magpylib.magnet.Cylinder(
            polarization=(case["br_T"], 0.0, 0.0),
            dimension=(2.0 * case["radius_m"], case["height_m"]),
        )
        b = np.atleast_2d(magnet.getB(np.asarray(case["points"], dtype=float)))
        out["cases"].append({"B_T": b.tolist()})
    with open(sys.argv[2], "w", encoding="utf-8") as f:
        json.dump(out, f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
