#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks that the licence is stated once and everywhere alike.

LICENSE at the repository root names its licence in its first line ("MIT License") and carries a
copyright line ("Copyright (c) YEAR HOLDER"); every source file git tracks (Verilog, C++, Python,
shell, CMake, the FuseSoC core, Verilator configuration) carries an SPDX-License-Identifier line
with that licence's identifier; pyproject.toml declares the same licence. Fails (exit 1) listing
each file that does not.
usage: check_license.py [ROOT]
"""

import os
import re
import subprocess
import sys

ROOT = os.path.abspath(
    sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
)
# The licences this check knows: LICENSE's first line -> SPDX identifier.
KNOWN = {"MIT License": "MIT"}
SOURCE = re.compile(
    r"\.(v|vh|sv|cpp|hpp|h|py|sh|cmake|core|vlt|ys\.in|sdc)$|(^|/)CMakeLists\.txt$|^\.ci/run$"
)
SPDX = re.compile(r"SPDX-License-Identifier:\s*([\w.+-]+)")


def main():
    problems = []
    try:
        lines = open(os.path.join(ROOT, "LICENSE"), encoding="utf-8").read().splitlines()
    except OSError:
        print("check_license: LICENSE: missing")
        return 1
    spdx = KNOWN.get(lines[0].strip() if lines else "")
    if spdx is None:
        problems.append(f"LICENSE:1: '{lines[0] if lines else ''}' is none of {', '.join(KNOWN)}")
    if not any(re.match(r"Copyright \(c\) \d{4}(-\d{4})? \S", line) for line in lines):
        problems.append("LICENSE: no copyright line 'Copyright (c) YEAR HOLDER'")
    files = subprocess.run(
        ["git", "-C", ROOT, "ls-files"], capture_output=True, text=True, check=True
    ).stdout.split()
    n = 0
    for f in files:
        if not SOURCE.search(f):
            continue
        n += 1
        try:
            head = "\n".join(open(os.path.join(ROOT, f), encoding="utf-8").read().splitlines()[:5])
        except (OSError, UnicodeDecodeError):
            problems.append(f"{f}: unreadable")
            continue
        m = SPDX.search(head)
        if not m:
            problems.append(f"{f}: no SPDX-License-Identifier line in its first five lines")
        elif spdx and m.group(1) != spdx:
            problems.append(f"{f}: SPDX-License-Identifier {m.group(1)}, LICENSE says {spdx}")
    py = open(os.path.join(ROOT, "pyproject.toml"), encoding="utf-8").read()
    if spdx and not re.search(r"^license\s*=.*\b" + re.escape(spdx) + r"\b", py, re.MULTILINE):
        problems.append(f"pyproject.toml: its license is not {spdx}")
    for p in problems:
        print("check_license:", p)
    print(f"check_license: LICENSE {spdx}, {n} source files, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
