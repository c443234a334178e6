#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Builds synth/reports/summary.md from the Yosys `stat` reports and nextpnr-ice40 logs that
# scripts/synth.sh wrote for the lines of the build registry rtl/configs.txt (scripts/registry.py
# names the designs and their reports). usage: synth_summary.py ROOT > synth/reports/summary.md
import concurrent.futures
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import registry  # noqa: E402
from registry import cells  # noqa: E402

root = os.path.abspath(sys.argv[1])
lines = {l.name: l for l in registry.load(root)}
designs = registry.synth_designs(root)


def pnr(design):
    return registry.pnr_result(registry.report(root, "pnr", design))


def s(d, *keys):
    if d is None:
        return "-"
    return str(sum(v for k, v in d.items() if any(re.fullmatch(p, k) for p in keys)))


# Row descriptions, in the table's order, by design (a registry name; <name>_pnr: its pin wrapper
# placed and routed). A line with synthesis flows that is not here gets a row after these, described
# by its module and parameters.
DESCRIPTIONS = {
    "default": "acore_top, default configuration (n=3, 4 regions, K=16)",
    "default_pnr": "acore_top, default, in the pin wrapper (P&R)",
    "stage_scaler_pnr": "stage: acore_scaler, pin wrapper (P&R)",
    "stage_region_pnr": "stage: acore_region_select, pin wrapper (P&R)",
    "stage_poly_pnr": "stage: acore_poly_correct, pin wrapper (P&R)",
    "stage_poly2d_pnr": "stage: acore_poly2d_correct (CORRECTION=1, d=3, 4 regions, one curve), pin wrapper (P&R)",
    "stage_poly2d_d1_pnr": "stage: acore_poly2d_correct, d=1 (same step logic, fits for Fmax), pin wrapper (P&R)",
    "stage_cordic_pnr": "stage: the top's CORDIC (18-bit, K=16), pin wrapper (P&R)",
    "serial": "acore_serial_top, serial core, default configuration",
    "serial_pnr": "acore_serial_top, default, in the pin wrapper (P&R)",
    "cordic16_rom": "CORDIC alone, 16-bit (registry line cordic16), atan table as constants (ZTAB=1), inputs registered",
    "cordic16": "CORDIC alone, 16-bit, atan words on an input bus",
    "cordic16_rom_pnr": "CORDIC alone, 16-bit, angle only, x/y loaded serially (pin wrapper, P&R)",
    "cordic16_serial": "word-serial CORDIC, 16-bit (cordic16 configuration), atan words on an input bus",
    "cordic16_serial_rom": "word-serial CORDIC, 16-bit, atan table as constants",
    "cordic16_serial_rom_pnr": "word-serial CORDIC, 16-bit, atan constants, x/y loaded serially (pin wrapper, P&R)",
    "stage_fourier": "stage: acore_fourier_correct, K=21 harmonics, M=12 (area)",
    "stage_fourier_k4_pnr": "stage: acore_fourier_correct, K=4 harmonics, M=12, pin wrapper (P&R)",
    "apb_serial": "acore_apb, APB register shell around the serial core (default)",
    "apb_serial_pnr": "acore_apb around the serial core, in the pin wrapper (P&R)",
    "apb": "acore_apb, APB register shell around acore_top (default)",
    "apb_none_pnr": "acore_apb around acore_top with CORRECTION=2 (no polynomial, fits), pin wrapper (P&R)",
}
for n in (2, 4, 8):
    DESCRIPTIONS[f"fold{n}"] = f"acore_top, default, FOLD={n} (folded: a sample every {n} clocks)"
    DESCRIPTIONS[f"fold{n}_pnr"] = f"acore_top, default, FOLD={n}, whole top in the pin wrapper (P&R)"
# The Fmax cell of an area row whose figure is elsewhere (default: the P&R rows of the whole top and
# of its stages; apb: the shell around a top that does not fit is not placed). Any other area row
# of a placed line points at its P&R row.
FMAX_NOTES = {"default": "see P&R rows", "apb": "does not fit (as acore_top)"}


def line_of(design):
    for suffix in ("_pnr", "_up5k"):
        if design.endswith(suffix):
            return lines[design[:-len(suffix)]]
    return lines[design]


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


# The HX8K table: every design but the UP5K placements (their own section below).
hx_designs = [x for x in designs if "pnr_up5k" not in x.flows]
up5k_designs = [x for x in designs if "pnr_up5k" in x.flows]
order = [d for d in DESCRIPTIONS if any(x.name == d for x in hx_designs)]
order += [x.name for x in hx_designs if x.name not in DESCRIPTIONS]
by_name = {x.name: x for x in designs}
with concurrent.futures.ThreadPoolExecutor(2) as ex:
    times = dict(zip(order, ex.map(lambda d: timing(line_of(d)), order)))
    # The shell's clocks per sample are its core's (the serial core's CYCLES, FOLD for acore_top).
    up5k_times = dict(zip([x.name for x in up5k_designs],
                          ex.map(lambda x: timing(line_of(x.name)), up5k_designs)))
SERIAL_CYCLES = times["serial"][1] if "serial" in times else None

print("# AngleCore synthesis summary\n")
print("Generated by `scripts/synth.sh` (Yosys 0.23, nextpnr-ice40 0.4, iCE40 HX8K ct256, seed 1, "
      "target 150 MHz). samples/s = Fmax / clocks per sample (the pipelined designs take one sample "
      "per clock, the folded ones one every FOLD clocks). See synth/README.md for caveats.\n")
print("| design | latency (clk) | clk/sample | generic cells | iCE40 LUT4 | iCE40 DFF | iCE40 CARRY | "
      "iCE40 BRAM | HX8K LCs | Fmax HX8K (MHz) | samples/s at Fmax | xc7 LUT | xc7 FF | xc7 RAM | xc7 DSP |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
stage_designs = {registry.placed_design(root, l) for l in registry.default_top_stages(root)}
stage_fmax = []
for d in order:
    line = line_of(d)
    desc = DESCRIPTIONS.get(d) or (f"{line.module} {line.param_text() or '(defaults)'}"
                                   + (", in its pin wrapper (P&R)" if d != line.name else ""))
    lat, cps = times[d]
    g = cells(registry.report(root, "generic", d))
    i = cells(registry.report(root, "ice40", d))
    x = cells(registry.report(root, "xilinx", d))
    placed = "pnr" in by_name[d].flows
    fmax, lc, why = pnr(d) if placed else (None, None, "")
    if d in stage_designs and fmax:
        stage_fmax.append(fmax)
    if d in FMAX_NOTES:
        fmax_s = FMAX_NOTES[d]
    elif not placed and "pnr" in line.flows:
        fmax_s = "see P&R row"
    elif fmax is not None:
        fmax_s = f"{fmax:.1f}"
    else:
        fmax_s = why or "-"
    sps = f"{fmax * 1e6 / cps:.3g}" if fmax else "-"
    lcs = f"{lc[0]}/{lc[1]}" if lc else "-"
    print(f"| {desc} | {lat} | {cps} | {g['total'] if g else '-'} | {s(i, 'SB_LUT4')} | {s(i, 'SB_DFF.*')} | "
          f"{s(i, 'SB_CARRY')} | {s(i, 'SB_RAM40_4K')} | {lcs} | {fmax_s} | {sps} | {s(x, 'LUT[1-6]')} | "
          f"{s(x, 'FD.*')} | {s(x, 'RAMB.*', 'RAM[0-9].*')} | {s(x, 'DSP48.*')} |")

if stage_fmax:
    f = min(stage_fmax)
    print(f"\nThe default top does not fit an HX8K; its clock rate there is bounded by its slowest stage: "
          f"**{f:.1f} MHz, {f * 1e6:.3g} samples/s** (stages placed one at a time, so routing congestion of "
          f"the full design is not included; the pre-filter and the output register are one short adder or "
          f"compare deep).")

ff, _, _ = pnr("stage_fourier_k4_pnr")
if ff and stage_fmax:
    print(f"\nWith the Fourier correction (any K: each harmonic's pipeline, the adder tree and the output "
          f"subtraction do not change with K but for the tree's depth) the bound is "
          f"**{min(min(stage_fmax), ff):.1f} MHz**; the Fourier stage alone places at {ff:.1f} MHz.")

top = cells(registry.report(root, "ice40", "default"))
ser = cells(registry.report(root, "ice40", "serial"))
fser, _, _ = pnr("serial_pnr")
if top and ser:
    lt, ls = int(s(top, "SB_LUT4")), int(s(ser, "SB_LUT4"))
    print("\n## Serial core target\n")
    print("| target | required | measured |")
    print("|---|---|---|")
    print(f"| iCE40 LUT4, serial core vs pipelined top (defaults) | <= 25 % of {lt} = {lt // 4} | "
          f"{ls} ({100.0 * ls / lt:.1f} %), {s(ser, 'SB_DFF.*')} DFF, {s(ser, 'SB_RAM40_4K')} BRAM |")
    if fser:
        print(f"| throughput on the HX8K | - | {fser:.1f} MHz / {SERIAL_CYCLES} clk = "
              f"{fser * 1e6 / SERIAL_CYCLES:.3g} samples/s |")

# The folded tops: the acore_top lines whose only parameter is FOLD (the default configuration
# folded), with their area and their whole-top P&R.
folds = sorted((dict(l.params)["FOLD"], l) for l in lines.values()
               if l.module == "acore_top" and [k for k, _ in l.params] == ["FOLD"])
fold_rows = [(n, cells(registry.report(root, "ice40", l.name)), pnr(registry.placed_design(root, l)))
             for n, l in folds]
if any(c for _, c, _ in fold_rows):
    print("\n## Folded top targets\n")
    print("| FOLD | iCE40 LUT4 / DFF / BRAM | HX8K LCs (whole top, pin wrapper) | Fmax | samples/s | target |")
    print("|---|---|---|---|---|---|")
    for n, c, (fm, lc, why) in fold_rows:
        if not c:
            continue
        lcs = f"{lc[0]}/{lc[1]} ({100.0 * lc[0] / lc[1]:.1f} %)" if lc else "-"
        target = {2: "<= 87 % of the LCs (6681) and >= 100 MHz", 8: "<= 2500 LUT4"}.get(n, "-")
        print(f"| {n} | {s(c, 'SB_LUT4')} / {s(c, 'SB_DFF.*')} / {s(c, 'SB_RAM40_4K')} | {lcs} | "
              f"{f'{fm:.1f} MHz' if fm else why} | {f'{fm * 1e6 / n:.3g}' if fm else '-'} | {target} |")
# What the register shell adds to each top (rtl/acore_apb.v: APB decode and registers, shadow bank,
# commit, CRC-32, scrubber).
shell_rows = [(name, cells(registry.report(root, "ice40", core)), cells(registry.report(root, "ice40", shell)))
              for name, core, shell in (("serial core", "serial", "apb_serial"), ("pipelined top", "default", "apb"))]
if any(c and sh for _, c, sh in shell_rows):
    print("\n## Register shell (rtl/acore_apb.v)\n")
    print("| around | core LUT4 / DFF / BRAM | with the shell | the shell adds |")
    print("|---|---|---|---|")
    for name, c, sh in shell_rows:
        if not (c and sh):
            continue
        dl = int(s(sh, "SB_LUT4")) - int(s(c, "SB_LUT4"))
        dd = int(s(sh, "SB_DFF.*")) - int(s(c, "SB_DFF.*"))
        db = int(s(sh, "SB_RAM40_4K")) - int(s(c, "SB_RAM40_4K"))
        print(f"| {name} | {s(c, 'SB_LUT4')} / {s(c, 'SB_DFF.*')} / {s(c, 'SB_RAM40_4K')} | "
              f"{s(sh, 'SB_LUT4')} / {s(sh, 'SB_DFF.*')} / {s(sh, 'SB_RAM40_4K')} | {dl} LUT4, {dd} DFF, {db} BRAM |")
    fa, lca, _ = pnr("apb_serial_pnr")
    if fa:
        print(f"\nThe shell around the serial core placed and routed on the HX8K ({lca[0]}/{lca[1]} logic cells): "
              f"**{fa:.1f} MHz**, {fa * 1e6 / SERIAL_CYCLES:.3g} samples/s.")
    fn, lcn, _ = pnr("apb_none_pnr")
    if fn:
        print(f"Around a pipelined top that fits (CORRECTION=2, {lcn[0]}/{lcn[1]} logic cells): **{fn:.1f} MHz** "
              f"(see the critical path in synth/reports/nextpnr_apb_none_pnr.log).")

c16 = cells(registry.report(root, "ice40", "cordic16_rom"))
c16w = cells(registry.report(root, "ice40", "cordic16_rom_pnr"))
f16, lc16, _ = pnr(registry.placed_design(root, lines["cordic16_rom"]))
c16s = cells(registry.report(root, "ice40", "cordic16_serial_rom_pnr"))
f16s, lc16s, _ = pnr("cordic16_serial_rom_pnr")
k16s = times.get("cordic16_serial_rom", (None, None))[1]
acc = os.path.join(root, "synth", "reports", "cordic16_accuracy.txt")
measured = open(acc).read().strip() if os.path.exists(acc) else "not measured (see synth/README.md)"
m = re.search(r"RMS ([\d.]+) LSB, max ([\d.]+) LSB", measured)
err = f"{m.group(2)} / {m.group(1)}" if m else "-"
print("\n## 16-bit CORDIC targets\n")
print("| target | required | measured |")
print("|---|---|---|")
print(f"| iCE40 LUT4 (pipelined, x/y loaded serially, angle only; module with magnitude output) | <= 1600 | "
      f"{s(c16w, 'SB_LUT4')} ({lc16[0] if lc16 else '-'} LCs); {s(c16, 'SB_LUT4')} |")
print(f"| Fmax on HX8K (nextpnr-ice40) | >= 150 MHz | {f'{f16:.1f} MHz' if f16 else '-'} |")
print(f"| angle error vs double atan2, RMS / max; no overflow | <= 0.5 / 1 LSB | {measured} |")
if c16s:
    print(f"| word-serial CORDIC: iCE40 LUT4 (x/y loaded serially) | <= 700 | {s(c16s, 'SB_LUT4')} "
          f"({lc16s[0] if lc16s else '-'} LCs) |")
    print(f"| word-serial CORDIC: samples/s on HX8K | >= 3e6 | "
          f"{f'{f16s:.1f} MHz / {k16s} clk = {f16s * 1e6 / k16s:.3g}' if f16s and k16s else '-'} |")
print("\nAccuracy: the C++ model (bit-exact to both RTL CORDICs, tb/blocks/test_cordic16.cpp checks them) over every "
      "input of the 16-bit square: `ACORE_C16_FULL=1 ACORE_CORDIC16_REPORT=synth/reports/"
      "cordic16_accuracy.txt build/tb/test_cordic16 --gtest_filter=*Accuracy*`; "
      "X/Y \"uses\" is the peak fraction of the RTL register range reached (no overflow: < 1).")
print("\nBeside the 16-bit CORDICs measured the same way elsewhere (inputs loaded serially, iCE40 HX8K, "
      "nextpnr; figures quoted, not re-measured here):\n")
print("| CORDIC | LUT4 | Fmax | clk/sample | max error |")
print("|---|---|---|---|---|")
if c16w and f16:
    print(f"| this project, pipelined (acore_cordic, cordic16) | {s(c16w, 'SB_LUT4')} | {f16:.1f} MHz | 1 | "
          f"{m.group(2) if m else '-'} LSB |")
if c16s and f16s:
    print(f"| this project, word-serial (acore_cordic_serial) | {s(c16s, 'SB_LUT4')} | {f16s:.1f} MHz | {k16s} | "
          f"{m.group(2) if m else '-'} LSB |")
for row in (("ZipCPU topolar", "2792", "118 MHz", "1", "5.8 LSB"),
            ("ZipCPU topolar, <= 1 LSB setting", "4800", "105 MHz", "1", "<= 1 LSB"),
            ("pipelined angle-only prototype", "1625", "132-136 MHz", "1", "0.98 LSB"),
            ("word-serial angle-only prototype", "649", "71 MHz", "19", "0.9 LSB"),
            ("ZipCPU seqpolar", "900", "65 MHz", "-", "-")):
    print("| " + " | ".join(row) + " |")

if up5k_designs:
    print("\n## The estimator with the register shell on an iCE40 UP5K (sg48)\n")
    print("Placed and routed by nextpnr-ice40 `--up5k --package sg48` (5280 logic cells, 30 block RAMs), "
          "in the SG48 wrapper synth/acore_apb_sg48wrap.v (wide ports through shift registers).\n")
    print("| design | iCE40 LUT4 / DFF / BRAM | UP5K LCs | Fmax UP5K | clk/sample | samples/s |")
    print("|---|---|---|---|---|---|")
    for x in up5k_designs:
        line = line_of(x.name)
        c = cells(registry.report(root, "ice40", x.name))
        fm, lc, why = pnr(x.name)
        cps = up5k_times[x.name][1]
        lcs = f"{lc[0]}/{lc[1]} ({100.0 * lc[0] / lc[1]:.1f} %)" if lc else "-"
        print(f"| {line.module} {line.param_text()} | {s(c, 'SB_LUT4')} / {s(c, 'SB_DFF.*')} / {s(c, 'SB_RAM40_4K')} | "
              f"{lcs} | {f'{fm:.1f} MHz' if fm else why} | {cps} | {f'{fm * 1e6 / cps:.3g}' if fm else '-'} |")
