#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""scripts/gen_as5047.py against broken descriptions (CTest as5047_regs_errors).

  as5047_errors.py --root DIR --work DIR

In a copy of rtl/acore_as5047_map.txt under WORK: the copy as it is generates (exit 0); every
malformed description of the table below exits 2 naming the description's file, the line of the
fault and the field at fault, and writes nothing. Exit 0 when every case behaves so, 1 otherwise.
"""

import argparse
import os
import re
import shutil
import subprocess
import sys

DESC = "rtl/acore_as5047_map.txt"
# (the line to change (a regex on it), its replacement, the field the error must name, what it
# must say)
CASES = [
    (r"^reg    0x0003 PROG", "reg    0x0001 PROG       rw", "ADDR", "another register's address"),
    (r"^reg    0x0003 PROG", "reg    0x4000 PROG       rw", "ADDR", "not a 14-bit address"),
    (r"^reg    0x0003 PROG", "reg    0x0003 PROG       w", "ACCESS", "expected r or rw"),
    (r"^field  SETTINGS2 7:5", "field  SETTINGS2 7:4  ABIRES", "BITS", "overlaps SETTINGS2.HYS"),
    (r"^field  SETTINGS1 2 ", "field  SETTINGS1 0    DIR", "BITS", "FIXED bits"),
    (r"^field  SETTINGS1 5 ", "field  SETTINGS1 5    ABIBIN     2", "RESET", "does not fit 1 bits"),
    (r"^field  PROG      0 ", "field  PROGX     0    PROGEN     0", "REG", "no register defined"),
    (r"^field  DIAAGC    8 ", "field  DIAAGC    14   LF", "BITS", "not within 13:0"),
    (r"^table  ABIRES_BIN", "table  ABIRES_BIN 1024 x 256", "V1", "not a number"),
    (r"^table  ABIRES_DEC", "table  ABIRES_DEC 1 2 3 4 5 6 7 8 9", "table", "1 to 8 entries"),
    (r"^const  HYS_MAX", "const  HYS_MAX", "const", "expected: const NAME VALUE"),
    (r"^const  DATA_W", "konst  DATA_W 8", "kind", "unknown line kind"),
    (r"^reg    0x0000 NOP", "reg    0x0002 NOP        r", "ADDR", "NOP's, address 0"),
]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--root", required=True)
    ap.add_argument("--work", required=True)
    a = ap.parse_args()
    gen = os.path.join(a.root, "scripts", "gen_as5047.py")
    with open(os.path.join(a.root, DESC), encoding="utf-8") as f:
        lines = f.read().splitlines(keepends=True)
    failures = 0

    def run(text, name):
        work = os.path.join(a.work, name)
        shutil.rmtree(work, ignore_errors=True)
        os.makedirs(os.path.join(work, "rtl"))
        with open(os.path.join(work, DESC), "w", encoding="utf-8") as f:
            f.write(text)
        out = os.path.join(work, "out")
        p = subprocess.run(
            [sys.executable, gen, "--root", work, "--out", out],
            capture_output=True,
            text=True,
            check=False,
        )
        return p, os.path.exists(out)

    p, _ = run("".join(lines), "ok")
    if p.returncode != 0:
        print(f"FAIL: the description as it is: exit {p.returncode}\n{p.stderr}")
        failures += 1
    for i, (pattern, repl, field, says) in enumerate(CASES):
        hit = [n for n, l in enumerate(lines) if re.match(pattern, l)]
        if len(hit) != 1:
            print(f"FAIL: case {i}: {pattern!r} matches {len(hit)} lines of {DESC}")
            failures += 1
            continue
        broken = lines[:]
        broken[hit[0]] = repl + "\n"
        p, wrote = run("".join(broken), f"case{i}")
        want = f"{DESC}:{hit[0] + 1}: {field}: "
        if p.returncode != 2 or want not in p.stderr or says not in p.stderr or wrote:
            print(
                f"FAIL: case {i} ({repl!r}): exit {p.returncode}, wrote {wrote}, expected exit 2 "
                f"with {want!r} ... {says!r}; stderr: {p.stderr.strip()}"
            )
            failures += 1
        else:
            print(f"ok: case {i}: {p.stderr.strip()}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
