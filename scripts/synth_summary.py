#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Builds synth/reports/summary.md from the Yosys `stat` reports and nextpnr logs that
# scripts/synth.sh wrote for the lines of the build registry rtl/configs.txt (scripts/registry.py
# names the designs and their reports). The families and devices, their columns, cell classes and
# capacities are the devices table's (synth/devices.toml): the main table has a family's columns
# when a line uses it and the default device's placement columns; every other device placed gets a
# section of its own.
# usage: synth_summary.py ROOT > synth/reports/summary.md
import concurrent.futures
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import devices
import registry
from registry import cells

root = os.path.abspath(sys.argv[1])
lines = {l.name: l for l in registry.load(root)}
designs = registry.synth_designs(root)
table = registry.table(root)
dev = table.default  # the main table's device
fam = dev.family


def pnr(design, device=dev):
    return registry.pnr_result(registry.report(root, device.name, design), device)


def s(d, *classes, family=fam):
    """The count of these cell classes of the family in a report's cells ("-" without a report)."""
    n = family.count(d, classes)
    return "-" if n is None else str(n)


def label(cls, family=fam):
    """The family's column label of a cell class ("LUT4" for lut on iCE40)."""
    return next((lab for lab, count in family.columns if cls in count), cls.upper())


article = devices.article


# Row descriptions, in the table's order, by design (a registry name; <name>_pnr: its pin wrapper
# placed and routed). A line with synthesis flows that is not here gets a row after these, described
# by its module and parameters.
DESCRIPTIONS = {
    "default": "acore_top, default configuration (n=3, 4 regions, K=16)",
    "default_pnr": "acore_top, default, in the pin wrapper (P&R)",
    "stage_scaler_pnr": "stage: acore_scaler, pin wrapper (P&R)",
    "stage_region_pnr": "stage: acore_region_select, pin wrapper (P&R)",
    "stage_poly_pnr": "stage: acore_poly_correct, pin wrapper (P&R)",
    "stage_poly2d_pnr": (
        "stage: acore_poly2d_correct (CORRECTION=1, d=3, 4 regions, one curve), pin wrapper (P&R)"
    ),
    "stage_poly2d_d1_pnr": (
        "stage: acore_poly2d_correct, d=1 (same step logic, fits for Fmax), pin wrapper (P&R)"
    ),
    "stage_cordic_pnr": "stage: the top's CORDIC (18-bit, K=16), pin wrapper (P&R)",
    "serial": "acore_serial_top, serial core, default configuration",
    "serial_pnr": "acore_serial_top, default, in the pin wrapper (P&R)",
    "cordic16_rom": (
        "CORDIC alone, 16-bit (registry line cordic16), atan table as constants "
        "(ZTAB=1), inputs registered"
    ),
    "cordic16": "CORDIC alone, 16-bit, atan words on an input bus",
    "cordic16_rom_pnr": "CORDIC alone, 16-bit, angle only, x/y loaded serially (pin wrapper, P&R)",
    "cordic16_serial": (
        "word-serial CORDIC, 16-bit (cordic16 configuration), atan words on an input bus"
    ),
    "cordic16_serial_rom": "word-serial CORDIC, 16-bit, atan table as constants",
    "cordic16_serial_rom_pnr": (
        "word-serial CORDIC, 16-bit, atan constants, x/y loaded serially (pin wrapper, P&R)"
    ),
    "stage_fourier": "stage: acore_fourier_correct, K=21 harmonics, M=12 (area)",
    "stage_fourier_k4_pnr": "stage: acore_fourier_correct, K=4 harmonics, M=12, pin wrapper (P&R)",
    "apb_serial": "acore_apb, APB register shell around the serial core (default)",
    "apb_serial_pnr": "acore_apb around the serial core, in the pin wrapper (P&R)",
    "apb": "acore_apb, APB register shell around acore_top (default)",
    "apb_none_pnr": (
        "acore_apb around acore_top with CORRECTION=2 (no polynomial, fits), pin wrapper (P&R)"
    ),
}
for n in (2, 4, 8, 16, 32):
    DESCRIPTIONS[f"fold{n}"] = f"acore_top, default, FOLD={n} (folded: a sample every {n} clocks)"
    DESCRIPTIONS[f"fold{n}_pnr"] = (
        f"acore_top, default, FOLD={n}, whole top in the pin wrapper (P&R)"
    )
# The Fmax cell of an area row whose figure is elsewhere (default: the P&R rows of the whole top and
# of its stages; apb: the shell around a top that does not fit is not placed). Any other area row
# of a placed line points at its P&R row.
FMAX_NOTES = {"default": "see P&R rows", "apb": "does not fit (as acore_top)"}


def line_of(design):
    if design in lines:
        return lines[design]
    for d in table.devices.values():
        for suffix in {d.suffix, d.bare_suffix} - {""}:
            if design.endswith(suffix) and design[: -len(suffix)] in lines:
                return lines[design[: -len(suffix)]]
    raise KeyError(design)


def timing(line):
    """(latency, clocks per sample): the module's LATENCY and CYCLES (1 when it has none) with the
    line's parameters, as the RTL elaborates them. acore_cordic16 (synth/) is acore_cordic at the
    cordic16 line's parameters with its inputs registered once: one clock more."""
    if line.module == "acore_cordic16":
        k = registry.rtl_constants(root, "acore_cordic", lines["cordic16"].params)
        return k["LATENCY"] + 1, 1
    if line.module == "acore_cordic16_serial":  # acore_cordic_serial at the cordic16_serial line's
        k = registry.rtl_constants(root, "acore_cordic_serial", lines["cordic16_serial"].params)
        return k["LATENCY"], k["CYCLES"]
    k = registry.rtl_constants(root, line.module, line.params)
    return k.get("LATENCY", "-"), k.get("CYCLES", 1)


# The main table: every design but those placed on another device (their own sections below).
others = [d for d in table.devices.values() if d is not dev]
other_designs = {d.name: [x for x in designs if d.name in x.flows] for d in others}
main_designs = [x for x in designs if not any(d.name in x.flows for d in others)]
order = [d for d in DESCRIPTIONS if any(x.name == d for x in main_designs)]
order += [x.name for x in main_designs if x.name not in DESCRIPTIONS]
by_name = {x.name: x for x in designs}
placed_elsewhere = [x for xs in other_designs.values() for x in xs]
with concurrent.futures.ThreadPoolExecutor(2) as ex:
    times = dict(zip(order, ex.map(lambda d: timing(line_of(d)), order)))
    # The shell's clocks per sample are its core's (the serial core's CYCLES, FOLD for acore_top).
    other_times = dict(
        zip(
            [x.name for x in placed_elsewhere],
            ex.map(lambda x: timing(line_of(x.name)), placed_elsewhere),
        )
    )
SERIAL_CYCLES = times["serial"][1] if "serial" in times else None
# The families with a column in the main table: those a design of it is synthesized for (area, or
# the netlist it places); a family placed only on another device has that device's section.
used = {f for x in main_designs for f in x.flows} | {
    table.devices[f].family.name for x in main_designs for f in x.flows if f in table.devices
}
families = [f for f in table.families.values() if f.name in used]
fmax_col = f"Fmax {dev.short} (MHz)"

print("# AngleCore synthesis summary\n")
print(
    f"Generated by `scripts/synth.sh` ({table.flow['yosys']}, {fam.measured_with}, {dev.title} "
    f"{dev.package}, seed {table.seed}, target {table.freq} MHz). samples/s = Fmax / clocks per "
    "sample (the pipelined designs take one sample per clock, the folded ones one every FOLD "
    "clocks). See synth/README.md for caveats.\n"
)
head = ["design", "latency (clk)", "clk/sample"]
for f in families:
    head += f.column_titles()
    if f is fam:
        head += [f"{dev.short} {fam.pnr_cell_label}", fmax_col, "samples/s at Fmax"]
print("| " + " | ".join(head) + " |")
print("|" + "---|" * len(head))
stage_designs = {registry.placed_design(root, l) for l in registry.default_top_stages(root)}
stage_fmax = []
for d in order:
    line = line_of(d)
    desc = DESCRIPTIONS.get(d) or (
        f"{line.module} {line.param_text() or '(defaults)'}"
        + (", in its pin wrapper (P&R)" if d != line.name else "")
    )
    lat, cps = times[d]
    placed = dev.name in by_name[d].flows
    fmax, lc, why = pnr(d) if placed else (None, None, "")
    if d in stage_designs and fmax:
        stage_fmax.append(fmax)
    if d in FMAX_NOTES:
        fmax_s = FMAX_NOTES[d]
    elif not placed and dev.name in line.flows:
        fmax_s = "see P&R row"
    elif fmax is not None:
        fmax_s = f"{fmax:.1f}"
    else:
        fmax_s = why or "-"
    sps = f"{fmax * 1e6 / cps:.3g}" if fmax else "-"
    lcs = f"{lc[0]}/{lc[1]}" if lc else "-"
    row = [desc, str(lat), str(cps)]
    for f in families:
        c = cells(registry.report(root, f.name, d))
        row += [s(c, *count, family=f) for _, count in f.columns]
        if f is fam:
            row += [lcs, fmax_s, sps]
    print("| " + " | ".join(row) + " |")

if stage_fmax:
    f = min(stage_fmax)
    print(
        f"\nThe default top does not fit {article(dev.short)}; its clock rate there is bounded by "
        f"its slowest stage: **{f:.1f} MHz, {f * 1e6:.3g} samples/s** (stages placed one at a "
        "time, so routing congestion of the full design is not included; the pre-filter and the "
        "output register are one short adder or compare deep)."
    )

ff, _, _ = pnr("stage_fourier_k4_pnr")
if ff and stage_fmax:
    print(
        "\nWith the Fourier correction (any K: each harmonic's pipeline, the adder tree and the "
        "output subtraction do not change with K but for the tree's depth) the bound is "
        f"**{min(min(stage_fmax), ff):.1f} MHz**; the Fourier stage alone places at {ff:.1f} MHz."
    )

top = cells(registry.report(root, fam.name, "default"))
ser = cells(registry.report(root, fam.name, "serial"))
fser, _, _ = pnr("serial_pnr")
if top and ser:
    lt, ls = int(s(top, "lut")), int(s(ser, "lut"))
    print("\n## Serial core target\n")
    print("| target | required | measured |")
    print("|---|---|---|")
    print(
        f"| {fam.title} {label('lut')}, serial core vs pipelined top (defaults) | <= 25 % of {lt} "
        f"= {lt // 4} | {ls} ({100.0 * ls / lt:.1f} %), {s(ser, 'ff')} {label('ff')}, "
        f"{s(ser, 'bram')} {label('bram')} |"
    )
    if fser:
        print(
            f"| throughput on the {dev.short} | - | {fser:.1f} MHz / {SERIAL_CYCLES} clk = "
            f"{fser * 1e6 / SERIAL_CYCLES:.3g} samples/s |"
        )

# The folded tops: the acore_top lines whose only parameter is FOLD (the default configuration
# folded), with their area and their whole-top P&R.
folds = sorted(
    (dict(l.params)["FOLD"], l)
    for l in lines.values()
    if l.module == "acore_top" and [k for k, _ in l.params] == ["FOLD"]
)
fold_rows = [
    (n, cells(registry.report(root, fam.name, l.name)), pnr(registry.placed_design(root, l)))
    for n, l in folds
]
if any(c for _, c, _ in fold_rows):
    print("\n## Folded top targets\n")
    lcs_cap = dev.capacity["logic_cells"]
    print(
        f"| FOLD | {fam.title} {label('lut')} / {label('ff')} / {label('bram')} | {dev.short} "
        f"{fam.pnr_cell_label} (whole top, pin wrapper) | Fmax | samples/s | target |"
    )
    print("|---|---|---|---|---|---|")
    for n, c, (fm, lc, why) in fold_rows:
        if not c:
            continue
        lcs = f"{lc[0]}/{lc[1]} ({100.0 * lc[0] / lc[1]:.1f} %)" if lc else "-"
        target = {
            2: f"<= 87 % of the {fam.pnr_cell_label} ({int(0.87 * lcs_cap)}) and >= 100 MHz",
            8: f"<= 2500 {label('lut')}",
            # The drive board's estimator: 1 M samples/s at 48 MHz and up, half the HX8K's blocks.
            16: ">= 1e+06 samples/s, <= 16 BRAM",
            32: ">= 1e+06 samples/s, <= 16 BRAM",
        }.get(n, "-")
        print(
            f"| {n} | {s(c, 'lut')} / {s(c, 'ff')} / {s(c, 'bram')} | {lcs} | "
            f"{f'{fm:.1f} MHz' if fm else why} | "
            f"{f'{fm * 1e6 / n:.3g}' if fm else '-'} | {target} |"
        )
# What the register shell adds to each top (rtl/acore_apb.v: APB decode and registers, shadow bank,
# commit, CRC-32, scrubber).
shell_rows = [
    (
        name,
        cells(registry.report(root, fam.name, core)),
        cells(registry.report(root, fam.name, shell)),
    )
    for name, core, shell in (
        ("serial core", "serial", "apb_serial"),
        ("pipelined top", "default", "apb"),
    )
]
if any(c and sh for _, c, sh in shell_rows):
    print("\n## Register shell (rtl/acore_apb.v)\n")
    print(
        f"| around | core {label('lut')} / {label('ff')} / {label('bram')} | with the "
        "shell | the shell adds |"
    )
    print("|---|---|---|---|")
    for name, c, sh in shell_rows:
        if not (c and sh):
            continue
        dl, dd, db = (int(s(sh, k)) - int(s(c, k)) for k in ("lut", "ff", "bram"))
        print(
            f"| {name} | {s(c, 'lut')} / {s(c, 'ff')} / {s(c, 'bram')} | {s(sh, 'lut')} / "
            f"{s(sh, 'ff')} / {s(sh, 'bram')} | {dl} {label('lut')}, {dd} {label('ff')}, "
            f"{db} {label('bram')} |"
        )
    fa, lca, _ = pnr("apb_serial_pnr")
    if fa:
        print(
            f"\nThe shell around the serial core placed and routed on the {dev.short} "
            f"({lca[0]}/{lca[1]} logic cells): **{fa:.1f} MHz**, "
            f"{fa * 1e6 / SERIAL_CYCLES:.3g} samples/s."
        )
    fn, lcn, _ = pnr("apb_none_pnr")
    if fn:
        print(
            f"Around a pipelined top that fits (CORRECTION=2, {lcn[0]}/{lcn[1]} logic cells): "
            f"**{fn:.1f} MHz** (see the critical path in synth/reports/nextpnr_apb_none_pnr.log)."
        )

c16 = cells(registry.report(root, fam.name, "cordic16_rom"))
c16w = cells(registry.report(root, fam.name, registry.placed_design(root, lines["cordic16_rom"])))
f16, lc16, _ = pnr(registry.placed_design(root, lines["cordic16_rom"]))
c16s = cells(registry.report(root, fam.name, "cordic16_serial_rom_pnr"))
f16s, lc16s, _ = pnr("cordic16_serial_rom_pnr")
k16s = times.get("cordic16_serial_rom", (None, None))[1]
acc = os.path.join(root, "synth", "reports", "cordic16_accuracy.txt")
measured = open(acc).read().strip() if os.path.exists(acc) else "not measured (see synth/README.md)"
m = re.search(r"RMS ([\d.]+) LSB, max ([\d.]+) LSB", measured)
err = f"{m.group(2)} / {m.group(1)}" if m else "-"
print("\n## 16-bit CORDIC targets\n")
print("| target | required | measured |")
print("|---|---|---|")
print(
    f"| {fam.title} {label('lut')} (pipelined, x/y loaded serially, angle only; module with "
    f"magnitude output) | <= 1600 | {s(c16w, 'lut')} ({lc16[0] if lc16 else '-'} "
    f"{fam.pnr_cell_label}); {s(c16, 'lut')} |"
)
print(f"| Fmax on {dev.short} ({fam.pnr}) | >= 150 MHz | {f'{f16:.1f} MHz' if f16 else '-'} |")
print(f"| angle error vs double atan2, RMS / max; no overflow | <= 0.5 / 1 LSB | {measured} |")
if c16s:
    print(
        f"| word-serial CORDIC: {fam.title} {label('lut')} (x/y loaded serially) | <= 700 | "
        f"{s(c16s, 'lut')} ({lc16s[0] if lc16s else '-'} {fam.pnr_cell_label}) |"
    )
    print(
        f"| word-serial CORDIC: samples/s on {dev.short} | >= 3e6 | "
        f"{f'{f16s:.1f} MHz / {k16s} clk = {f16s * 1e6 / k16s:.3g}' if f16s and k16s else '-'} |"
    )
print(
    "\nAccuracy: the C++ model (bit-exact to both RTL CORDICs, tb/blocks/test_cordic16.cpp checks "
    "them) over every input of the 16-bit square: `ACORE_C16_FULL=1 "
    "ACORE_CORDIC16_REPORT=synth/reports/cordic16_accuracy.txt build/tb/test_cordic16 "
    '--gtest_filter=*Accuracy*`; X/Y "uses" is the peak fraction of the RTL register range '
    "reached (no overflow: < 1)."
)
print(
    "\nBeside the 16-bit CORDICs measured the same way elsewhere (inputs loaded serially, iCE40 "
    "HX8K, nextpnr; figures quoted, not re-measured here):\n"
)
print("| CORDIC | LUT4 | Fmax | clk/sample | max error |")
print("|---|---|---|---|---|")
if c16w and f16:
    print(
        f"| this project, pipelined (acore_cordic, cordic16) | {s(c16w, 'lut')} | {f16:.1f} MHz | "
        f"1 | {m.group(2) if m else '-'} LSB |"
    )
if c16s and f16s:
    print(
        f"| this project, word-serial (acore_cordic_serial) | {s(c16s, 'lut')} | {f16s:.1f} MHz | "
        f"{k16s} | {m.group(2) if m else '-'} LSB |"
    )
for row in (
    ("ZipCPU topolar", "2792", "118 MHz", "1", "5.8 LSB"),
    ("ZipCPU topolar, <= 1 LSB setting", "4800", "105 MHz", "1", "<= 1 LSB"),
    ("pipelined angle-only prototype", "1625", "132-136 MHz", "1", "0.98 LSB"),
    ("word-serial angle-only prototype", "649", "71 MHz", "19", "0.9 LSB"),
    ("ZipCPU seqpolar", "900", "65 MHz", "-", "-"),
):
    print("| " + " | ".join(row) + " |")

# Every other device a line is placed on: its own section (headings by device; the default says
# what is placed).
SECTIONS = {"up5k": "The estimator with the register shell"}
for d in others:
    xs = other_designs[d.name]
    if not xs:
        continue
    f = d.family
    wrappers = sorted(
        {
            os.path.relpath(x.source, root)
            for x in xs
            if x.source and x.top != line_of(x.name).module
        }
    )
    print(f"\n## {SECTIONS.get(d.name, 'Placed and routed')} on {article(d.title)} ({d.package})\n")
    print(
        f"Placed and routed by {f.pnr} `{' '.join(d.pnr_args)}` ({d.capacity['logic_cells']} logic "
        f"cells, {d.capacity['bram_blocks']} block RAMs), in "
        f"{d.wrapper_doc.format(files=', '.join(wrappers))}.\n"
    )
    print(
        f"| design | {f.title} {label('lut', f)} / {label('ff', f)} / {label('bram', f)} | "
        f"{d.short} {f.pnr_cell_label} | {d.short} DSP | Fmax {d.short} | clk/sample | samples/s |"
    )
    print("|---|---|---|---|---|---|---|")
    for x in xs:
        line = line_of(x.name)
        c = cells(registry.report(root, f.name, x.name))
        fm, lc, why = pnr(x.name, d)
        cps = other_times[x.name][1]
        lcs = f"{lc[0]}/{lc[1]} ({100.0 * lc[0] / lc[1]:.1f} %)" if lc else "-"
        # Hard multipliers placed (the log's pnr_dsp line; Yosys's dsp cells where none).
        dsp = registry.pnr_count(registry.report(root, d.name, x.name), f.pnr_dsp)
        dsp = f"{dsp[0]}/{dsp[1]}" if dsp else s(c, "dsp", family=f)
        io = registry.pnr_count(registry.report(root, d.name, x.name), "USER_IO")
        if io:
            why = f"does not fit ({io[0]} I/O, {io[1]} pins)"
        print(
            f"| {line.module} {line.param_text()} | {s(c, 'lut', family=f)} / "
            f"{s(c, 'ff', family=f)} / {s(c, 'bram', family=f)} | {lcs} | {dsp} | "
            f"{f'{fm:.1f} MHz' if fm else why} | {cps} | {f'{fm * 1e6 / cps:.3g}' if fm else '-'} |"
        )
