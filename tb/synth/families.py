#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Each placed family's flow on one small design, in seconds (CTest synth_families, default run):
for the first device of every family of synth/devices.toml with a place-and-route program (iCE40
HX8K, ECP5 LFE5U-25F, Gowin GW1N-9), the registry line stage_uvw's module (acore_uvw, about 150
LUT4) is synthesized by the family's Yosys command, wrapped as scripts/stage_fmax.py wraps a stage,
and placed and routed by the device's program with the table's arguments (pins from the device's
free pins where the program needs every port placed). Checks, per device:
  - the design is placed and routed, with a clock rate (0 < Fmax < 1000 MHz) and at least as many
    logic cells as Yosys's LUTs of the family's lut class (a LUT is packed into a logic cell);
  - the log counts the logic cells, block RAMs and hard multipliers out of the datasheet's figures
    (the table's capacity: nextpnr's device database against the vendor's numbers);
  - where the device lists pins: the pin file places exactly the design's ports, the clock on the
    first pin, and a design with one port more than there are pins does not fit (PinsError).
The whole flow of the reports (default top, FOLD 8, serial, board on every device) is
scripts/synth.sh (docs/synthesis.md), minutes to hours.

usage: families.py ROOT WORKDIR [--devices NAME[,NAME...]] [--line NAME]
Exit 1 when a check fails, 2 on bad usage or a missing program.
"""

import argparse
import json
import os
import re
import sys

ROOT_SCRIPTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts")
sys.path.insert(0, os.path.abspath(ROOT_SCRIPTS))
import devices
import registry
import stage_fmax


def check_device(root, dev, line, work, fails):
    os.makedirs(work, exist_ok=True)
    why = dev.tool_missing(root)
    if why:
        print(f"families: {why}", file=sys.stderr)
        sys.exit(2)
    stage_fmax.DEVICE, stage_fmax.ROOT = dev, root
    full = os.path.join(work, "full.json")
    design = stage_fmax.elaborate(
        root, line.module, list(line.params), full, os.path.join(work, "elab.log")
    )
    res = stage_fmax.stage_result(work, full, line.module, design[line.module]["ports"])
    log = os.path.join(work, "nextpnr.log")
    where = f"{dev.name} ({dev.title}), {line.name}"
    if "error" in res:
        fails.append(f"{where}: {res['error']} (see {res['log']})")
        return res
    if not res["fits"] or not 0 < res["fmax_mhz"] < 1000:
        fails.append(f"{where}: not placed and routed with a clock rate (see {log})")
    if res["lcs"] is None or res["lut4"] is None or res["lcs"] < res["lut4"]:
        fails.append(
            f"{where}: {res['lcs']} {dev.family.pnr_cell} for {res['lut4']} LUTs of Yosys "
            f"(see {log})"
        )
    for key, name in (
        ("logic_cells", dev.family.pnr_cell),
        ("bram_blocks", dev.family.pnr_bram),
        ("dsp", dev.family.pnr_dsp),
    ):
        got = registry.pnr_count(log, name)
        want = dev.capacity[key]
        if (got[1] if got else 0) != want:
            fails.append(
                f"{where}: the log counts {name} out of {got[1] if got else 'none'}, "
                f"synth/devices.toml capacity {key} = {want}"
            )
    if dev.pins:
        pins_file = os.path.join(work, "wrap.pins")
        ports = registry.netlist_ports(os.path.join(work, "wrap.json"))
        placed = dev.constraint_ports(pins_file)
        if placed != ports:
            fails.append(
                f"{where}: {pins_file} places {sorted(placed)}, the ports are {sorted(ports)}"
            )
        first = next((l for l in open(pins_file) if re.search(dev.family.constraint_pin, l)), "")
        clock = dev.family.constraint_line.format(port="clk_i", pin=dev.pins[0])
        if first.strip() != clock:
            fails.append(f"{where}: first pin line '{first.strip()}', expected '{clock}'")
        many = {f"p_i[{i}]" for i in range(len(dev.pins) + 1)}
        try:
            dev.pin_constraints(many, os.path.join(work, "many.pins"))
            fails.append(f"{where}: {len(many)} ports placed on {len(dev.pins)} pins")
        except devices.PinsError:
            pass
    print(f"{where}: {json.dumps(res)}")
    return res


def main(argv):
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("root")
    ap.add_argument("workdir")
    ap.add_argument("--devices", default="")
    ap.add_argument("--line", default="stage_uvw")
    try:
        a = ap.parse_args(argv)
    except SystemExit as e:
        return 0 if e.code == 0 else 2
    root = os.path.abspath(a.root)
    try:
        t = registry.table(root)
        line = registry.get(root, a.line)
    except registry.RegistryError as e:
        print(f"families: {e}", file=sys.stderr)
        return 2
    if a.devices:
        names = a.devices.split(",")
        unknown = [n for n in names if n not in t.devices]
        if unknown:
            print(
                f"families: {', '.join(unknown)}: not devices of synth/devices.toml",
                file=sys.stderr,
            )
            return 2
        devs = [t.devices[n] for n in names]
    else:
        devs, seen = [], set()
        for d in t.devices.values():
            if d.family.name not in seen:
                seen.add(d.family.name)
                devs.append(d)
    failed = 0
    for d in devs:
        fails = []
        check_device(root, d, line, os.path.join(a.workdir, d.name), fails)
        for f in fails:
            print(f"FAIL: {f}")
        failed += bool(fails)
    print(f"{len(devs) - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
