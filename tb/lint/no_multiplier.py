#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""No multiplier, divider or power operator in any registered build's netlist.

  no_multiplier.py [--root DIR] [--only NAME[,NAME...]] [--jobs N]

The RTL writes constant products with `*` (parameters, localparams, the constant functions of
rtl/acore_derived.vh): they are evaluated at elaboration. The datapath multiplies on adders and
shifters only. This check proves it on the netlist: for every line of rtl/configs.txt whose module
is acore_top, acore_serial_top, acore_apb, acore_cordic, acore_cordic_serial, acore_track, a drive
interface or the board top (acore_abz, acore_uvw, acore_spi_as5047, acore_pwm, acore_board), Yosys
reads rtl/files.f, elaborates the module with the line's parameters (hierarchy -chparam) and runs
`proc`; the design must then hold
no $mul, $macc, $div, $mod, $divfloor, $modfloor or $pow cell (checked before any optimization, so
a product cannot hide behind constant folding). A negative control first: a module with one `*`
between two inputs must fail the same check, so the check cannot pass on a design it did not see.

Exit 0 when every build passes, 1 when one holds such a cell (its cells are listed) or Yosys fails,
2 on bad usage or a malformed registry line (scripts/registry.py reads the registry).
"""

import argparse
import concurrent.futures
import os
import subprocess
import sys
import tempfile
import time

MODULES = (
    "acore_top",
    "acore_serial_top",
    "acore_apb",
    "acore_cordic",
    "acore_cordic_serial",
    "acore_track",
    "acore_abz",
    "acore_uvw",
    "acore_spi_as5047",
    "acore_pwm",
    "acore_board",
)
CELLS = ("$mul", "$macc", "$div", "$mod", "$divfloor", "$modfloor", "$pow")


sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import registry


def rtl_files(root):
    return [os.path.join(root, "rtl", f) for f in registry.rtl_files(root)]


def builds(root):
    """(name, module, [(PARAM, value)]) of every registry line for MODULES."""
    return [(l.name, l.module, list(l.params)) for l in registry.load(root) if l.module in MODULES]


def check(files, top, params, workdir):
    """(ok, message): Yosys elaborates top and asserts that no cell of CELLS exists."""
    chp = "".join(f" -chparam {k} {v}" for k, v in params)
    sel = " ".join(f"t:{c}" for c in CELLS)
    log = os.path.join(workdir, f"{top}_{abs(hash(chp))}.log")
    script = (
        f"read_verilog -sv {' '.join(files)}; hierarchy -check -top {top}{chp}; proc; "
        f"tee -o {log} select -list {sel}; select -assert-none {sel}"
    )
    p = subprocess.run(
        ["yosys", "-q", "-p", script], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True
    )
    if p.returncode == 0:
        return True, ""
    found = open(log).read().strip() if os.path.exists(log) else ""
    return False, (found or p.stdout.strip())[-3000:]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument(
        "--root", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    )
    ap.add_argument("--only", default="", help="comma-separated registry names (default: all)")
    ap.add_argument("--jobs", type=int, default=1)
    args = ap.parse_args()
    try:
        todo = builds(args.root)
    except registry.RegistryError as e:
        print(f"no_multiplier.py: {e}", file=sys.stderr)
        return 2
    if args.only:
        wanted = args.only.split(",")
        unknown = [w for w in wanted if w not in {b[0] for b in todo}]
        if unknown:
            print(
                f"no_multiplier.py: not in rtl/configs.txt for {', '.join(MODULES)}: "
                f"{', '.join(unknown)}",
                file=sys.stderr,
            )
            return 2
        todo = [b for b in todo if b[0] in wanted]
    files = rtl_files(args.root)
    fails = 0
    with tempfile.TemporaryDirectory(prefix="acore_nomul_") as tmp:
        # Negative control: a product of two inputs must be found.
        ctl = os.path.join(tmp, "mul_control.v")
        with open(ctl, "w") as f:
            f.write(
                "module mul_control(input wire [7:0] a, input wire [7:0] b, "
                "output wire [15:0] p);\n"
                "  assign p = a * b;\nendmodule\n"
            )
        ok, _ = check([ctl], "mul_control", [], tmp)
        if ok:
            print("FAIL control: a product of two inputs was not found")
            return 1
        print("ok   control: a product of two inputs is found ($mul)")

        def one(b):
            name, module, params = b
            t0 = time.time()
            ok, msg = check(files, module, params, tmp)
            return name, module, params, ok, msg, time.time() - t0

        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as ex:
            for name, module, params, ok, msg, dt in ex.map(one, todo):
                desc = f"{name} ({module}{''.join(f' {k}={v}' for k, v in params)})"
                if ok:
                    print(f"ok   {desc}: no {'/'.join(CELLS)} cell ({dt:.1f} s)")
                else:
                    fails += 1
                    print(f"FAIL {desc}:\n{msg}")
    print(f"{len(todo) - fails} of {len(todo)} registered builds have no multiplier cell")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
