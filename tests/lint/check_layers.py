#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks the include structure of AngleCore's C++ against model/layers.txt.

Fails (exit 1) on: an include of a folder listed below the including file's folder (upward), an
include cycle between files, a model header included without its folder ("errors.hpp" instead of
"core/errors.hpp"), and an include that resolves to no file of the repository.
usage: check_layers.py [ROOT]
"""

import os
import re
import sys

ROOT = os.path.abspath(
    sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
)
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)
# Include roots of the build (CMake target_include_directories), searched after the file's own
# folder.
ROOTS = ["model/ip", "model/lab", "model", "tests", "tb", "model/cli"]
# Headers generated into the build tree (Verilated classes, generated tables): not checked.
GENERATED = re.compile(r"^V[A-Za-z0-9_]*\.h$|_generated\.hpp$")


def layers():
    order = []
    with open(os.path.join(ROOT, "model/layers.txt")) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line:
                order.append(line)
    return order


def component(path, order):
    """The longest layer folder that holds path (relative), and its rank."""
    best = None
    for rank, folder in enumerate(order):
        inside = path == folder or path.startswith(folder + "/")
        if inside and (best is None or len(folder) > len(best[1])):
            best = (rank, folder)
    return best


def sources():
    for top in ("model", "tb", "tests", "python"):
        for dp, dn, fn in os.walk(os.path.join(ROOT, top)):
            dn[:] = [d for d in dn if not d.startswith(".")]
            for f in sorted(fn):
                if f.endswith((".cpp", ".hpp", ".h")):
                    yield os.path.relpath(os.path.join(dp, f), ROOT)


def resolve(src, name):
    for base in [os.path.dirname(src), *ROOTS]:
        cand = os.path.normpath(os.path.join(base, name))
        if os.path.isfile(os.path.join(ROOT, cand)):
            return cand
    return None


def main():
    order = layers()
    errors = []
    graph = {}
    for src in sources():
        here = component(src, order)
        if here is None:
            errors.append(f"{src}: in no layer of model/layers.txt")
            continue
        text = open(os.path.join(ROOT, src), encoding="utf-8", errors="replace").read()
        graph[src] = []
        for m in INCLUDE.finditer(text):
            name = m.group(1)
            line = text.count("\n", 0, m.start()) + 1
            if GENERATED.search(os.path.basename(name)):
                continue
            dst = resolve(src, name)
            if dst is None:
                errors.append(
                    f'{src}:{line}: #include "{name}" resolves to no file of the repository'
                )
                continue
            graph[src].append((dst, line))
            there = component(dst, order)
            if dst.startswith(("model/ip/", "model/lab/")) and "/" not in name:
                qualified = "/".join(dst.split("/")[2:])
                errors.append(f'{src}:{line}: #include "{name}": name the folder ("{qualified}")')
            if there is None:
                errors.append(f"{src}:{line}: {dst} is in no layer")
            elif there[0] > here[0]:
                errors.append(
                    f"{src}:{line}: upward include: {here[1]} may not include {there[1]} "
                    f'("{name}"; model/layers.txt lists {there[1]} above {here[1]})'
                )
    # Cycles between files (depth-first search, colours).
    state = {}
    stack = []

    def visit(node):
        state[node] = 1
        stack.append(node)
        for nxt, _line in graph.get(node, []):
            if state.get(nxt) == 1:
                cyc = [*stack[stack.index(nxt) :], nxt]
                errors.append("include cycle: " + " -> ".join(cyc))
            elif state.get(nxt) is None:
                visit(nxt)
        stack.pop()
        state[node] = 2

    for node in sorted(graph):
        if state.get(node) is None:
            visit(node)
    for e in errors:
        print(e)
    n = sum(len(v) for v in graph.values())
    print(
        f"check_layers: {len(graph)} files, {n} includes, {len(order)} layers, "
        f"{len(errors)} problems"
    )
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
