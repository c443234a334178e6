#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Where the cells are: a per-instance breakdown of one registry line's iCE40 synthesis (LUT4, DFF,
# carry, block RAM per instance of the hierarchy, with and without its sub-instances). The line's
# module (or, with --placed, its HX8K pin wrapper: the design scripts/synth.sh places) is read
# exactly as scripts/synth.sh reads it (rtl/files.f, the line's parameters by chparam), synthesized
# by `synth_ice40 -noflatten` so that every instance keeps its own cells, and the netlist counted.
# Without flattening Yosys cannot propagate constants across module boundaries, so the total is a
# little above the flattened report's (synth/reports/ice40_<name>.txt, printed beside it).
# usage: synth_breakdown.py [--root ROOT] [--placed] [--depth N] NAME [NAME...] > REPORT.md
import argparse
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import registry

# iCE40 cell classes of the columns (the technology cells of synth_ice40).
CLASSES = (
    ("LUT4", lambda t: t == "SB_LUT4"),
    ("DFF", lambda t: t.startswith("SB_DFF")),
    ("carry", lambda t: t == "SB_CARRY"),
    ("BRAM", lambda t: t.startswith("SB_RAM40")),
)


def base_name(module):
    """The source module of a Yosys module name ($paramod$<hash>\\acore_fold_cordic ->
    acore_fold_cordic)."""
    if module.startswith("$paramod"):
        return module.split("\\")[1]
    return module.lstrip("\\")


def synthesize(root, top, source, params, out_json):
    reads = []
    with open(os.path.join(root, "rtl", "files.f")) as f:
        for name in f.read().split():
            if name.endswith(".v"):
                reads.append(f"read_verilog -sv {os.path.join(root, 'rtl', name)}")
    if source:
        reads.append(f"read_verilog -sv -I{root}/synth -I{root}/rtl {source}")
    if params:
        reads.append("chparam " + " ".join(f"-set {k} {v}" for k, v in params) + f" {top}")
    script = "\n".join(
        [
            *reads,
            f"hierarchy -check -top {top}",
            f"synth_ice40 -noflatten -top {top}",
            f"write_json {out_json}",
        ]
    )
    with tempfile.NamedTemporaryFile("w", suffix=".ys", delete=False) as ys:
        ys.write(script + "\n")
    try:
        r = subprocess.run(["yosys", "-q", "-s", ys.name], capture_output=True, text=True)
    finally:
        os.unlink(ys.name)
    if r.returncode != 0:
        sys.exit(
            f"synth_breakdown.py: yosys failed on {top}:\n{r.stdout[-2000:]}{r.stderr[-2000:]}"
        )
    with open(out_json) as f:
        return json.load(f)["modules"]


def own_counts(mod):
    counts = [0] * len(CLASSES)
    subs = []
    for cname, cell in mod["cells"].items():
        t = cell["type"]
        for i, (_, match) in enumerate(CLASSES):
            if match(t):
                counts[i] += 1
                break
        else:
            if not t.startswith("SB_"):
                subs.append((cname, t))
    return counts, sorted(subs)


def walk(modules, module, inst, depth, rows, max_depth):
    own, subs = own_counts(modules[module])
    total = list(own)
    row = [inst, base_name(module), depth, own, total]
    rows.append(row)
    for cname, t in subs:
        if t not in modules:
            continue
        sub_total = walk(modules, t, cname.lstrip("\\"), depth + 1, rows, max_depth)
        total[:] = [a + b for a, b in zip(total, sub_total)]
    return total


def report(root, name, placed, max_depth):
    line = registry.get(root, name)
    top, source = line.module, registry.synth_source(root, line.module)
    design = name
    if placed:
        w, wsrc = registry.pin_wrapper(root, line.module, "hx8k")
        if w:
            top, source, design = w, wsrc, registry.placed_design(root, line, "hx8k")
    with tempfile.TemporaryDirectory() as tmp:
        modules = synthesize(root, top, source, list(line.params), os.path.join(tmp, "n.json"))
    rows = []
    total = walk(modules, top, top, 0, rows, max_depth)
    flat = registry.cells(registry.report(root, "ice40", design))
    out = [f"## {design}: {top} {line.param_text()}", ""]
    if flat:
        f = [sum(n for t, n in flat.items() if match(t)) for _, match in CLASSES]
        out.append(
            "Flattened (synth/reports/ice40_%s.txt): %s."
            % (design, ", ".join(f"{v} {k}" for (k, _), v in zip(CLASSES, f)))
        )
    out.append(
        "Unflattened total: %s." % ", ".join(f"{v} {k}" for (k, _), v in zip(CLASSES, total))
    )
    out.append("")
    cols = [c for c, _ in CLASSES]
    out.append(
        "| instance | module | "
        + " | ".join(cols)
        + " | "
        + " | ".join(f"own {c}" for c in cols)
        + " |"
    )
    out.append("|---|---|" + "---:|" * (2 * len(cols)))
    for inst, mod, depth, own, tot in rows:
        if depth > max_depth:
            continue
        out.append(
            f"| {'. ' * depth}{inst} | {mod} | "
            + " | ".join(str(v) for v in tot)
            + " | "
            + " | ".join(str(v) for v in own)
            + " |"
        )
    out.append("")
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument(
        "--root", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    )
    ap.add_argument("--placed", action="store_true", help="the HX8K pin wrapper of each line")
    ap.add_argument("--depth", type=int, default=99, help="deepest instance level listed")
    ap.add_argument("names", nargs="+")
    a = ap.parse_args()
    root = os.path.abspath(a.root)
    cmd = (
        "scripts/synth_breakdown.py "
        + ("--placed " if a.placed else "")
        + (f"--depth {a.depth} " if a.depth != 99 else "")
        + " ".join(a.names)
    )
    parts = [
        "# iCE40 cells per instance",
        "",
        f"Generated by `{cmd}` (Yosys `synth_ice40 -noflatten`, the netlist counted per instance).",
        "A row's first columns count the instance with its sub-instances, the `own` columns its",
        "own cells only (glue logic, registers and memories written in the module itself).",
        "",
    ]
    for n in a.names:
        try:
            parts.append(report(root, n, a.placed, a.depth))
        except registry.RegistryError as e:
            sys.exit(f"synth_breakdown.py: {e}")
    sys.stdout.write("\n".join(parts))


if __name__ == "__main__":
    main()
