#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""No multiplier, divider or power operator in any registered build's netlist but the hardware
multipliers of MULT = 1.

  no_multiplier.py [--root DIR] [--only NAME[,NAME...]] [--jobs N]

The RTL writes constant products with `*` (parameters, localparams, the constant functions of
rtl/acore_derived.vh): they are evaluated at elaboration. The datapath multiplies on adders and
shifters only. This check proves it on the netlist: for every line of rtl/configs.txt whose module
is acore_top, acore_serial_top, acore_apb, acore_cordic, acore_cordic_serial, acore_track, a drive
interface or the board top (acore_abz, acore_uvw, acore_spi_as5047, acore_pwm, acore_board), Yosys
reads rtl/files.f and elaborates the module with the line's parameters (hierarchy -chparam); the
design must then hold
no $mul, $macc, $div, $mod, $divfloor, $modfloor or $pow cell (checked before any optimization, so
a product cannot hide behind constant folding). Elaboration makes a cell of every operator, inside
processes and functions too, so `proc` (a third of the time) is not run. Negative controls first: a
module with one `*` between two inputs, and one with a product in a clocked process and one in a
function called from a combinational process, must each fail the same check, so the check cannot
pass on a design it did not see.

A line with MULT=1 (hardware multipliers, docs/datapath.md) may hold $mul cells, but only in
acore_hw_mul (rtl/acore_hw_mul.v, which the stages instantiate in their MULT = 1 generate branches
only), and must hold at least one (else its MULT = 1 branches were not built); no other cell of
the list anywhere. A MULT=0 line holding acore_hw_mul fails like any other multiplier. The lines
tagged long-sim are checked when --only names them (the default run checks the shell's MULT=1
lines, apb_mult and apb_fold8_mult, pipelined and folded).

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
# The one module whose $mul cells a MULT=1 line may hold (Yosys names its elaborations
# $paramod...\acore_hw_mul...).
HW_MUL = "acore_hw_mul"


sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import registry


def rtl_files(root):
    return [os.path.join(root, "rtl", f) for f in registry.rtl_files(root)]


def builds(root, long=False):
    """(name, module, [(PARAM, value)]) of every registry line for MODULES (the lines tagged
    long-sim only when long: the shell's MULT=1 lines stand for them in the default run)."""
    return [
        (l.name, l.module, list(l.params))
        for l in registry.load(root)
        if l.module in MODULES and (long or "long-sim" not in l.tags)
    ]


def check(files, top, params, workdir):
    """(ok, message): Yosys elaborates top and lists its cells of CELLS: none may exist, but with
    MULT=1 among the params $mul cells inside acore_hw_mul, of which there must be one at least."""
    chp = "".join(f" -chparam {k} {v}" for k, v in params)
    sel = " ".join(f"t:{c}" for c in CELLS)
    log = os.path.join(workdir, f"{top}_{abs(hash(chp))}.log")
    mlog = log + ".mul"
    script = (
        f"read_verilog -sv -defer {' '.join(files)}; hierarchy -check -top {top}{chp}; "
        f"tee -o {log} select -list {sel}; tee -o {mlog} select -list t:$mul"
    )
    p = subprocess.run(
        ["yosys", "-q", "-p", script], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True
    )
    if p.returncode != 0 or not os.path.exists(log) or not os.path.exists(mlog):
        return False, p.stdout.strip()[-3000:]
    # One "module/cell" a line.
    found = [l.strip() for l in open(log) if "/" in l]
    if not any(k == "MULT" and str(v) == "1" for k, v in params):
        return (not found), "\n".join(found)[-3000:]
    muls = {l.strip() for l in open(mlog) if "/" in l}
    bad = [c for c in found if c not in muls or HW_MUL not in c.split("/")[0]]
    if bad:
        return False, f"MULT=1: cells outside {HW_MUL}:\n" + "\n".join(bad)[-3000:]
    if not muls:
        return False, "MULT=1 but no $mul cell: the hardware multipliers were not built"
    return True, f"MULT=1: {len(muls)} $mul cells, all in {HW_MUL}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument(
        "--root", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    )
    ap.add_argument("--only", default="", help="comma-separated registry names (default: all)")
    ap.add_argument("--jobs", type=int, default=1)
    args = ap.parse_args()
    try:
        checked = builds(args.root, long=bool(args.only))
    except registry.RegistryError as e:
        print(f"no_multiplier.py: {e}", file=sys.stderr)
        return 2
    if args.only:
        wanted = args.only.split(",")
        unknown = [w for w in wanted if w not in {b[0] for b in checked}]
        if unknown:
            print(
                f"no_multiplier.py: not in rtl/configs.txt for {', '.join(MODULES)}: "
                f"{', '.join(unknown)}",
                file=sys.stderr,
            )
            return 2
        checked = [b for b in checked if b[0] in wanted]
    files = rtl_files(args.root)
    fails = 0
    with tempfile.TemporaryDirectory(prefix="acore_nomul_") as tmp:
        # Negative controls: each design holds a product the check must find (name, Verilog, top,
        # parameters, what it shows).
        controls = (
            (
                "mul_control",
                (
                    "module mul_control(input wire [7:0] a, input wire [7:0] b, "
                    "output wire [15:0] p);\n  assign p = a * b;\nendmodule\n"
                ),
                [],
                "a product of two inputs is found ($mul)",
            ),
            # Products inside processes (no `proc` pass runs): clocked, and through a function.
            (
                "mul_control_proc",
                (
                    "module mul_control_proc(input wire clk, input wire [7:0] a,"
                    " input wire [7:0] b, output reg [15:0] q);\n"
                    "  always @(posedge clk) q <= a * b;\nendmodule\n"
                ),
                [],
                "a product in a clocked process is found",
            ),
            (
                "mul_control_func",
                (
                    "module mul_control_func(input wire [7:0] a, input wire [7:0] b,"
                    " output reg [15:0] r);\n"
                    "  function [15:0] f(input [7:0] x, input [7:0] y); f = x * y; endfunction\n"
                    "  always @* begin r = 16'd0; if (a[0]) r = f(a, b); end\nendmodule\n"
                ),
                [],
                "a product in a function called from a combinational process is found",
            ),
            # With MULT=1 too, when it is not in acore_hw_mul.
            (
                "mul_control1",
                (
                    "module mul_control1 #(parameter integer MULT = 0) (input wire [7:0] a, "
                    "input wire [7:0] b, output wire [15:0] p);\n  assign p = a * b;\nendmodule\n"
                ),
                [("MULT", "1")],
                "with MULT=1, a product outside acore_hw_mul is found",
            ),
        )
        for top, text, params, what in controls:
            ctl = os.path.join(tmp, top + ".v")
            with open(ctl, "w") as f:
                f.write(text)
            ok, _ = check([ctl], top, params, tmp)
            if ok:
                print(f"FAIL control: not so: {what}")
                return 1
            print(f"ok   control: {what}")

        def one(b):
            name, module, params = b
            t0 = time.time()
            ok, msg = check(files, module, params, tmp)
            return name, module, params, ok, msg, time.time() - t0

        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as ex:
            for name, module, params, ok, msg, dt in ex.map(one, checked):
                desc = f"{name} ({module}{''.join(f' {k}={v}' for k, v in params)})"
                if ok:
                    what = msg or f"no {'/'.join(CELLS)} cell"
                    print(f"ok   {desc}: {what} ({dt:.1f} s)")
                else:
                    fails += 1
                    print(f"FAIL {desc}:\n{msg}")
    print(
        f"{len(checked) - fails} of {len(checked)} registered builds pass: no multiplier cell "
        f"(with MULT=1: only in {HW_MUL})"
    )
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
