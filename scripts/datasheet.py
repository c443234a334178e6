#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The datasheet table synth/reports/datasheet.md: one line per FPGA device (or synthesis-only
family) and configuration of the estimator, so a user picks a line without reading the flow
(scripts/synth.sh's last step).

usage: datasheet.py [--root DIR] [--out FILE [--check]] [--anglecore BIN]   (default: stdout)
  --check: write nothing; exit 1 when FILE differs from what it would write (CTest
  datasheet_current: the checked-in table is the reports' and the model's now)

Read from the reports scripts/synth.sh wrote (synth/reports/) and the model (`BIN sweep`, default
ROOT/build/anglecore: it must be built); the devices, families, their cell classes and capacities
from synth/devices.toml, the configurations from the build registry rtl/configs.txt: every line of a
top module (acore_top, acore_serial_top, acore_apb, acore_board) placed on a device, then those with
an area-only family that has no device (xc7: no clock). Per line:
  logic      the place-and-route log's logic cells, used/available (the family's pnr_cell)
  LUT, FF    the family's lut and ff cell classes in the Yosys report of the placed netlist
  BRAM, DSP  the log's block RAMs and hard multipliers (pnr_bram, pnr_dsp); Yosys's count where the
             line is not placed
  Fmax       nextpnr's, at the devices table's seed and target clock ("does not fit" when the
             design is larger than the device or its package)
  samples/s  Fmax / clocks per sample (the module's CYCLES; FOLD for a folded top)
  latency    the module's LATENCY clocks at that Fmax, in microseconds
  accuracy   RMS / max error in degrees on the noise-free paper scenario of the bit-accurate model
             of the same datapath parameters, calibrated and validated as the design space's
             accuracy half (`anglecore sweep`, its default samples; MULT = 1's rounding included;
             the serial core, the folded tops, the shell and the board compute bit for bit what the
             pipelined top computes: the same model)
"""

import argparse
import difflib
import json
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import devices
import registry

TOPS = ("acore_top", "acore_serial_top", "acore_apb", "acore_board")
# Parameters that choose how the datapath is built, not what it computes.
BUILD_ONLY = {"FOLD", "SERIAL"}
SCENARIO = "paper-noiseless"


class Accuracy:
    """RMS / max error (degrees, SCENARIO, the bit-accurate model) of each line's datapath, from
    one `anglecore sweep` of the lines' distinct datapath parameters: the model as it is now,
    calibrated as the sweep calibrates (the design space's accuracy half), MULT = 1 included."""

    def __init__(self, root, anglecore, lines):
        self.defaults = registry.rtl_parameters(root, "acore_top")
        if not os.access(anglecore, os.X_OK):
            raise registry.RegistryError(
                f"{anglecore}: no anglecore binary (build it with scripts/build.sh, or pass "
                "--anglecore): the accuracy column is the model's"
            )
        keys = sorted({self.canonical(l.params) for l in lines})
        with tempfile.TemporaryDirectory() as d:
            grid = os.path.join(d, "grid.json")
            with open(grid, "w") as f:
                json.dump([{k: [int(v)] for k, v in key} for key in keys], f)
            p = subprocess.run(
                [anglecore, "sweep", "--grid", grid, "--out", d, "--jobs", "2"],
                capture_output=True,
                text=True,
            )
            if p.returncode != 0:
                raise registry.RegistryError(f"{anglecore} sweep: {p.stderr.strip()[-2000:]}")
            self.keys = {}
            for line in open(os.path.join(d, "accuracy-0-of-1.jsonl")):
                r = json.loads(line)
                fixed = r.get("accuracy", {}).get(SCENARIO, {}).get("fixed")
                if fixed:
                    params = tuple(tuple(q.split("=", 1)) for q in r["params"].split())
                    self.keys[self.canonical(params)] = (fixed["rms"], fixed["max_abs"])

    def canonical(self, params):
        """The datapath parameters that differ from acore_top's defaults, sorted."""
        return tuple(
            sorted(
                (k, str(v))
                for k, v in params
                if k not in BUILD_ONLY and str(self.defaults.get(k)) != str(v)
            )
        )

    def of(self, line):
        return self.keys.get(self.canonical(line.params))


def fmt_fmax(fmax, why):
    return f"{fmax:.1f}" if fmax else (why or "-")


def build(root, anglecore):
    t = registry.table(root)
    lines = [l for l in registry.load(root) if l.module in TOPS]
    acc = Accuracy(root, anglecore, lines)
    timing = {}

    def clocks(line):
        if line.name not in timing:
            k = registry.rtl_constants(root, line.module, line.params)
            timing[line.name] = (k.get("LATENCY"), k.get("CYCLES", 1))
        return timing[line.name]

    head = [
        "device and line",
        "design",
        "logic (used/avail.)",
        "LUT",
        "FF",
        "BRAM",
        "DSP",
        "Fmax (MHz)",
        "samples/s",
        "latency (µs)",
        f"accuracy RMS / max (°, {SCENARIO})",
    ]
    rows = []
    for dev in t.devices.values():
        fam = dev.family
        for line in lines:
            if dev.name not in line.flows:
                continue
            design = registry.placed_design(root, line, dev.name)
            log = registry.report(root, dev.name, design)
            stat = registry.cells(registry.report(root, fam.name, design))
            fmax, lc, why = registry.pnr_result(log, dev)
            io = registry.pnr_count(log, "USER_IO")
            bram = registry.pnr_count(log, fam.pnr_bram)
            dsp = registry.pnr_count(log, fam.pnr_dsp) if dev.capacity["dsp"] else None
            # The resources over the device's (the logic cells when the log names none over).
            over = [
                f"{n[0]}/{n[1]} {label}"
                for n, label in ((lc, fam.pnr_cell_label), (bram, "BRAM"), (dsp, "DSP"))
                if n and n[0] > n[1]
            ]
            if io:
                why = f"does not fit ({io[0]} I/O of {io[1]} pins)"
            elif why == "does not fit" and (over or lc):
                over = over or [f"{lc[0]}/{lc[1]} {fam.pnr_cell_label}"]
                why = f"does not fit ({', '.join(over)})"
            if why == "failed":
                # The program stopped (its counts are not the design's): its message and Yosys's.
                err = re.findall(r"^ERROR: (.*)$", open(log).read(), re.MULTILINE)
                why = f"failed: {err[-1].strip()}" if err else why
                bram = dsp = lc = None
            rows.append(row(dev.short, fam, line, stat, lc, bram, dsp, fmax, why, clocks, acc))
    placed_families = {d.family.name for d in t.devices.values()}
    for fam in t.families.values():
        if fam.name in placed_families or fam.name == "generic":
            continue
        for line in lines:
            if fam.name not in line.flows:
                continue
            stat = registry.cells(registry.report(root, fam.name, line.name))
            rows.append(
                row(
                    fam.title,
                    fam,
                    line,
                    stat,
                    None,
                    None,
                    None,
                    None,
                    "-",
                    clocks,
                    acc,
                )
            )
    out = [
        "# AngleCore datasheet\n",
        "Generated by `scripts/datasheet.py --out synth/reports/datasheet.md` (the last step of "
        f"`scripts/synth.sh`) from its reports ({t.flow['yosys']}; "
        + "; ".join(f"{f.title}: {f.measured_with}" for f in t.families.values() if f.placed)
        + f"; seed {t.seed}, target {t.freq} MHz) and the model (`anglecore sweep`). "
        "One line per device and configuration of the "
        "estimator, placed and routed whole in its pin wrapper; logic = the place-and-route "
        "log's logic cells; LUT, FF: Yosys's cells of the placed netlist; BRAM, DSP: the log's "
        "(Yosys's where not placed: the xc7 lines are Yosys's area alone, no clock); "
        "samples/s = Fmax / clocks per sample; latency = LATENCY clocks at Fmax; accuracy: the "
        "noise-free paper scenario, the bit-accurate model of the same datapath parameters "
        "calibrated as the design space's accuracy half "
        "(FOLD, the serial core, the register shell and the board compute the same bits). "
        "Devices: "
        + "; ".join(
            f"{d.short} = {d.title} ({d.part}, {d.package}"
            + (f", speed {d.speed})" if d.speed else ")")
            for d in t.devices.values()
        )
        + ". The flow and its caveats: docs/synthesis.md.\n",
        "| " + " | ".join(head) + " |",
        "|" + "---|" * len(head),
    ]
    out += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(out) + "\n"


def row(device, fam, line, stat, lc, bram, dsp, fmax, why, clocks, acc):
    lat, cps = clocks(line)
    a = acc.of(line)

    def yosys(cls):
        n = fam.count(stat, [cls])
        return "-" if n is None else str(n)

    return [
        f"{device} {line.name}",
        f"{line.module} {line.param_text() or '(defaults)'}".strip(),
        f"{lc[0]}/{lc[1]}" if lc else "-",
        yosys("lut"),
        yosys("ff"),
        str(bram[0]) if bram else yosys("bram"),
        str(dsp[0]) if dsp else yosys("dsp"),
        fmt_fmax(fmax, why),
        f"{fmax * 1e6 / cps:.3g}" if fmax and cps else "-",
        f"{lat / fmax:.2f}" if fmax and isinstance(lat, int) else "-",
        f"{a[0]:.3f} / {a[1]:.2f}" if a else "-",
    ]


def main(argv):
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--root", default=os.path.dirname(HERE))
    ap.add_argument("--out")
    ap.add_argument("--check", action="store_true", help="compare with --out, write nothing")
    ap.add_argument(
        "--anglecore",
        help="the anglecore binary whose `sweep` gives the accuracy column "
        "(default: ROOT/build/anglecore)",
    )
    try:
        a = ap.parse_args(argv)
    except SystemExit as e:
        return 0 if e.code == 0 else 2
    if a.check and not a.out:
        print("datasheet.py: --check needs --out FILE", file=sys.stderr)
        return 2
    try:
        root = os.path.abspath(a.root)
        text = build(root, a.anglecore or os.path.join(root, "build", "anglecore"))
    except (registry.RegistryError, devices.DevicesError) as e:
        print(f"datasheet.py: {e}", file=sys.stderr)
        return 2
    if a.check:
        old = open(a.out).read().splitlines() if os.path.exists(a.out) else []
        diff = list(difflib.unified_diff(old, text.splitlines(), a.out, "now", lineterm="", n=0))
        if diff:
            print(f"datasheet.py: {a.out} is not current (scripts/synth.sh's last step writes it):")
            print("\n".join(diff[:40]))
            return 1
        print(f"datasheet.py: {a.out} is current")
    elif a.out:
        registry.write_if_changed(a.out, text)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
