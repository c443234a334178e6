#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks the correction modes against their one table, model/ip/core/correction_modes.hpp.

Reads the table's rows (ROW(ID, CONSTANT, "name", ...) of ACORE_CORRECTION_MODES) from the source
and fails (exit 1), naming file:line, when:
  - a mode is missing from a file generated from the table: its constant in rtl/acore_modes.vh
    (localparam integer ACORE_CORR_<NAME> = ID), its DEGREE rule in rtl/acore_mode_checks.vh, its
    row in docs/reports/correction_modes.md;
  - a mode is missing from the docs' mode list: docs/datapath.md "Correction modes" must show the
    generated table (a figure of docs/reports/correction_modes.md) and name every mode;
  - docs/architecture.md has no recipe "A correction mode" naming the table's file;
  - an RTL, synthesis or bench Verilog file compares CORRECTION (or a function's f_correction) with
    a literal number, or passes a literal mode to a mode function (acore_terms(1, ...)), instead of
    using the table's constants ACORE_CORR_* (rtl/acore_modes.vh, the generated file, is where the
    numbers live);
  - a model, CLI or binding C++ file other than the table's own compares a correction with a number,
    a mode constant or a name, or switches on it: every such decision reads the table's row.
usage: check_modes.py [ROOT]
"""

import os
import re
import sys

ROOT = os.path.abspath(
    sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
)
TABLE = "model/ip/core/correction_modes.hpp"
ROW = re.compile(r'^\s*ROW\((\d+),\s*(k\w+),\s*"(\w+)"', re.MULTILINE)
GENERATED_RTL = {"rtl/acore_modes.vh"}


def read(rel):
    with open(os.path.join(ROOT, rel), encoding="utf-8") as f:
        return f.read()


def line_of(text, pos):
    return text.count("\n", 0, pos) + 1


def files_under(top, exts):
    for dp, dn, fn in os.walk(os.path.join(ROOT, top)):
        dn[:] = [d for d in dn if not d.startswith(".") and d != "build"]
        for f in sorted(fn):
            if f.endswith(exts):
                yield os.path.relpath(os.path.join(dp, f), ROOT)


def strip_comments(text, style):
    """Comments blanked (same length, newlines kept): a comment may name a mode's number."""
    pat = r"//[^\n]*|/\*.*?\*/" if style == "c" else r"#[^\n]*"
    return re.sub(pat, lambda m: re.sub(r"[^\n]", " ", m.group(0)), text, flags=re.DOTALL)


def check_generated(modes, errors):
    vh = read("rtl/acore_modes.vh")
    checks = read("rtl/acore_mode_checks.vh")
    doc = read("docs/reports/correction_modes.md")
    for mid, _, name in modes:
        const = "ACORE_CORR_" + name.upper()
        if not re.search(r"^localparam integer %s = %d;$" % (const, mid), vh, re.MULTILINE):
            errors.append(
                f"rtl/acore_modes.vh: no 'localparam integer {const} = {mid};' for mode {name} "
                f"(run scripts/gen_tables.sh)"
            )
        if not re.search(rf"\bDEGREE_must_be_\d+_to_\d+_for_{re.escape(name)} \(\);", checks):
            errors.append(
                f"rtl/acore_mode_checks.vh: no DEGREE rule for mode {name} (run "
                "scripts/gen_tables.sh)"
            )
        if f"| `{name}` ({mid}) |" not in doc:
            errors.append(
                f"docs/reports/correction_modes.md: no row for mode {name} ({mid}) "
                f"(run scripts/gen_tables.sh)"
            )


def check_docs(modes, errors):
    text = read("docs/datapath.md")
    m = re.search(r"^## Correction modes\n(.*?)(?=^## )", text, re.MULTILINE | re.DOTALL)
    if not m:
        errors.append("docs/datapath.md: no section '## Correction modes'")
    else:
        sec = m.group(1)
        where = f"docs/datapath.md:{line_of(text, m.start())}"
        if "<!-- figure: table docs/reports/correction_modes.md" not in sec:
            errors.append(
                f"{where}: 'Correction modes' does not show the generated table "
                f"(a figure of docs/reports/correction_modes.md)"
            )
        for _, _, name in modes:
            if f"`{name}`" not in sec:
                errors.append(f"{where}: 'Correction modes' does not name mode `{name}`")
    arch = read("docs/architecture.md")
    r = re.search(r"^\*\*A correction mode\.\*\*(.*?)(?=^\*\*|\Z)", arch, re.MULTILINE | re.DOTALL)
    if not r:
        errors.append("docs/architecture.md: no recipe '**A correction mode.**'")
    elif TABLE not in r.group(1):
        errors.append(
            f"docs/architecture.md:{line_of(arch, r.start())}: the recipe 'A correction mode' "
            f"does not name {TABLE}"
        )


# Verilog: CORRECTION / f_correction against a number, either side; a literal mode to a mode
# function.
V_COMPARE = re.compile(
    r"\b(?:CORRECTION|f_correction)\s*(?:==|!=|<=|>=|<|>)\s*-?\d"
    r"|-?\d\s*(?:==|!=|<=|>=|<|>)\s*(?:CORRECTION|f_correction)\b"
)
V_LITERAL_ARG = re.compile(
    r"\b(?:acore_terms|acore_correction_latency|acore_mode_\w+|acore_folded)\s*\(\s*-?\d"
)


def check_verilog(errors):
    for top, exts in (("rtl", (".v", ".vh")), ("synth", (".v", ".vh")), ("tb", (".v", ".sv"))):
        for rel in files_under(top, exts):
            if rel in GENERATED_RTL:
                continue
            text = strip_comments(read(rel), "c")
            for pat, what in (
                (V_COMPARE, "compares the correction mode with a number"),
                (V_LITERAL_ARG, "passes a literal correction mode"),
            ):
                for m in pat.finditer(text):
                    errors.append(
                        f"{rel}:{line_of(text, m.start())}: '{m.group(0).strip()}' {what}: "
                        f"use the table's constants ACORE_CORR_* (rtl/acore_modes.vh)"
                    )


# C++: a correction compared with anything but through the table, or switched on.
CPP_PATTERNS = [
    re.compile(r"\bcorrection\s*(?:==|!=)\s*(?:-?\d|k[A-Z]\w*|\")"),
    re.compile(r"(?:-?\d|\bk[A-Z]\w*|\")\s*(?:==|!=)\s*\w*(?:\.|->)?correction\b"),
    re.compile(r"\bswitch\s*\([^)]*\bcorrection\s*\)"),
    re.compile(r"\bcase\s+(?:kPoly|kPoly2d|kNone)\b"),
]


def check_cpp(errors):
    own = {TABLE, TABLE.replace(".hpp", ".cpp")}
    for top in ("model", "python/src"):
        for rel in files_under(top, (".cpp", ".hpp", ".h")):
            if rel in own:
                continue
            text = strip_comments(read(rel), "c")
            for pat in CPP_PATTERNS:
                for m in pat.finditer(text):
                    errors.append(
                        f"{rel}:{line_of(text, m.start())}: '{m.group(0).strip()}' decides on the "
                        f"correction mode outside its table: read its row ({TABLE})"
                    )


def main():
    modes = [(int(i), c, n) for i, c, n in ROW.findall(read(TABLE))]
    errors = []
    if not modes:
        errors.append(f"{TABLE}: no ROW(...) of ACORE_CORRECTION_MODES found")
    ids = [m[0] for m in modes]
    if ids != list(range(len(ids))):
        errors.append(f"{TABLE}: the rows' IDs {ids} are not 0, 1, 2, ... in order")
    check_generated(modes, errors)
    check_docs(modes, errors)
    check_verilog(errors)
    check_cpp(errors)
    for e in errors:
        print(e)
    print(
        f"check_modes: {len(modes)} correction modes ({', '.join(n for _, _, n in modes)}); "
        f"{len(errors)} problem(s)"
    )
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
