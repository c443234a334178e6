#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""scripts/gen_apb_regs.py against broken inputs (CTest apb_regs_errors).

  regs_errors.py --root DIR --work DIR

In a copy of the repository's register descriptions and generated files under WORK:
  - the copy as it is passes `--check` (exit 0);
  - a generated file edited by hand fails `--check` (exit 1) naming that file, and so does a
    missing one;
  - every malformed description of the table below exits 2 naming the description's file, the
    line of the fault and the field or word at fault, and writes nothing.
Exit 0 when every case behaves so, 1 otherwise.
"""

import argparse
import glob
import os
import re
import shutil
import subprocess
import sys

BOARD = "rtl/acore_board_regs.txt"
SHELL = "rtl/acore_apb_regs.txt"
NRANGE = r"^range  1 \d+$"  # ABZ_N.N's range (the first `range 1 ...` line of the board's)
# (description, the line to change (a regex on it), its replacement ('' deletes it; a leading '+'
# adds a line after it), what the error must say[, the line it must name when the fault shows at
# another line: the later of two overlapping fields, the field of an attribute, the register of
# its fields, the `irq` line])
CASES = [
    (BOARD, NRANGE, "range  1 9000", "range 1..9000 of field N"),
    (
        BOARD,
        NRANGE,
        "range  3000 2000",
        "range 3000..2000 of field N: not within its 13 bits, or empty",
    ),
    (BOARD, NRANGE, "range  2000 3000", "its reset 1024 is outside its range"),
    (BOARD, r"^field  12:0   N ", "field  12:0   n  RW   1024  x", "field name 'n'"),
    (BOARD, r"^field  4:0    POLE_PAIRS", "field  4:0    POLE_PAIRS    RX   1  x", "access 'RX'"),
    (
        BOARD,
        r"^field  31:16  TURNS",
        "field  31:15  TURNS  RO  -  x",
        "ANGLE (15:0) overlaps TURNS",
        r"^field  15:0   ANGLE",
    ),
    (BOARD, r"^reg    0x06C  UVW_PP", "reg    0x06E  UVW_PP  RW  x", "offset 0x06E of UVW_PP"),
    (
        BOARD,
        r"^reg    0x06C  UVW_PP",
        "reg    0x060  UVW_PP  RW  x",
        "UVW_PP at 0x060 overlaps ABZ_N",
    ),
    (BOARD, r"^field  12:0   N ", "field  12:0   N  RW  9000  x", "reset 9000 of field N"),
    (BOARD, r"^field  31:0   VELOCITY", "+range  1 2", "only an RW field has a range"),
    (BOARD, r"^field  31:0   VELOCITY", "+lock   always", "'lock' of field VELOCITY"),
    (BOARD, r"^frac   4$", "frac   9", "frac 9 of field LEAD"),
    (BOARD, r"^frac   4$", "fraction 4", "unknown line kind 'fraction'"),
    (BOARD, r"^block  acore_board$", "", "the first line must be 'block OWNER'"),
    (
        BOARD,
        r"^field  15:0   SPACING",
        "field  15:0   SPACING  RW  -  x",
        "an RW field has a RESET",
    ),
    (
        BOARD,
        r"^range  TRK_BW_MIN TRK_BW_MAX word$",
        "range  TRK_BW_MIN TRK_BW_MAX words",
        "expected 'range LO HI [word]'",
    ),
    (
        BOARD,
        r"^field  15:0   SPACING",
        "+range  TRK_BW_MIN TRK_BW_MAX",
        "field SPACING: a range set by parameters needs a field of at most 8 bits",
        r"^field  15:0   SPACING",
    ),
    (
        SHELL,
        r"^field  13:8   IRQ_EN",
        "field  12:8   IRQ_EN  RW  0  x",
        "CTRL.IRQ_EN must be a field with one bit",
        r"^irq ",
    ),
    (
        SHELL,
        r"^clears STATUS$",
        "clears CTRL",
        "clears CTRL, which has no W1C field",
        r"^field  1      CLEAR",
    ),
    (SHELL, r"^size   WORDS$", "", "window COEF has no 'size' line", r"^window 0x400"),
    (
        SHELL,
        r"^field  5:0    PENDING",
        "field  5:0    PENDING  RW  0  x",
        "register IRQ is RO but its fields",
        r"^reg    0x028  IRQ",
    ),
    (
        SHELL,
        r"^mem    COEF$",
        "+hw     the firmware",
        "field CRC_EXPECTED: mem and hw: one writer of its word",
        r"^field  31:0   CRC_EXPECTED",
    ),
    (
        SHELL,
        r"^mem    COEF$",
        "mem    STATUS",
        "field CRC_EXPECTED: mem STATUS is not a window",
        r"^field  31:0   CRC_EXPECTED",
    ),
]


def gen(work, *args):
    p = subprocess.run(
        [sys.executable, os.path.join(work, "scripts", "gen_apb_regs.py"), "--root", work, *args],
        capture_output=True,
        text=True,
    )
    return p.returncode, p.stdout, p.stderr


def copy_tree(root, work):
    """The generator, the descriptions and the files they give, under work."""
    if os.path.exists(work):
        shutil.rmtree(work)
    os.makedirs(os.path.join(work, "scripts"))
    shutil.copy(os.path.join(root, "scripts", "gen_apb_regs.py"), os.path.join(work, "scripts"))
    rc = subprocess.run(
        [
            sys.executable,
            os.path.join(root, "scripts", "gen_apb_regs.py"),
            "--root",
            root,
            "--out",
            os.path.join(work, "fresh"),
        ],
        stdout=subprocess.PIPE,
    ).returncode
    outputs = [
        os.path.relpath(p, os.path.join(work, "fresh"))
        for p in glob.glob(os.path.join(work, "fresh", "**", "*"), recursive=True)
        if os.path.isfile(p)
    ]
    shutil.rmtree(os.path.join(work, "fresh"))
    for rel in outputs + [
        os.path.relpath(p, root) for p in glob.glob(os.path.join(root, "rtl", "*_regs.txt"))
    ]:
        os.makedirs(os.path.dirname(os.path.join(work, rel)), exist_ok=True)
        shutil.copy(os.path.join(root, rel), os.path.join(work, rel))
    return rc, outputs


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--root", required=True)
    ap.add_argument("--work", required=True)
    args = ap.parse_args()
    work = os.path.abspath(args.work)
    fails = []
    rc, outputs = copy_tree(os.path.abspath(args.root), work)
    if rc != 0 or not outputs:
        print(f"FAIL the generator did not run on the repository (exit {rc})")
        return 1
    rc, out, err = gen(work, "--check", os.path.join(work, "check"))
    print(f"{'ok  ' if rc == 0 else 'FAIL'} the copy passes --check (exit {rc})")
    fails += [] if rc == 0 else ["clean copy"]
    # A generated file edited by hand, then removed: --check fails naming it.
    for rel in outputs:
        path = os.path.join(work, rel)
        keep = open(path).read()
        for what, change in (
            ("edited", lambda: open(path, "a").write("\n")),
            ("removed", lambda: os.remove(path)),
        ):
            change()
            rc, out, err = gen(work, "--check", os.path.join(work, "check"))
            good = rc == 1 and f"FAIL {rel} differs" in out
            print(f"{'ok  ' if good else 'FAIL'} {rel} {what} by hand: --check exit {rc}")
            fails += [] if good else [f"{rel} {what}"]
            with open(path, "w") as f:
                f.write(keep)
    # Malformed descriptions: exit 2, the file and the line named, nothing written.
    for desc, pattern, repl, what, *named_at in CASES:
        path = os.path.join(work, desc)
        keep = open(path).read()
        lines = keep.split("\n")
        at = next((i for i, l in enumerate(lines) if re.search(pattern, l)), None)
        if at is None:
            print(f"FAIL {desc}: no line matches {pattern!r} (the table is stale)")
            fails.append(pattern)
            continue
        if repl.startswith("+"):
            lines.insert(at + 1, repl[1:])
            line = at + 2
        elif repl == "":
            del lines[at]
            line = at + 1
        else:
            lines[at] = repl
            line = at + 1
        if named_at:
            line = next(i for i, l in enumerate(lines, 1) if re.search(named_at[0], l))
        with open(path, "w") as f:
            f.write("\n".join(lines))
        stamp = {rel: os.path.getmtime(os.path.join(work, rel)) for rel in outputs}
        rc, out, err = gen(work)
        named = re.search(rf"{re.escape(desc)}:(\d+): ", err)
        good = (
            rc == 2
            and what in err
            and named is not None
            and int(named.group(1)) == line
            and all(os.path.getmtime(os.path.join(work, rel)) == t for rel, t in stamp.items())
        )
        print(
            f"{'ok  ' if good else 'FAIL'} {desc}:{line} {repl or '(deleted)'!r}: "
            f"exit {rc}: {err.strip()}"
        )
        fails += [] if good else [f"{desc}:{line}"]
        with open(path, "w") as f:
            f.write(keep)
    print(f"regs_errors: {len(fails)} failure(s)")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
