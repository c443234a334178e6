#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Configuration table: every acore_top and acore_serial_top line of the build registry
rtl/configs.txt with its register words, LATENCY, clocks per sample, and on the default device of
synth/devices.toml (the iCE40 HX8K) its family's LUTs, the device's logic cells, Fmax and samples/s,
written as Markdown.

usage: scripts/config_table.py [--root DIR] [--measure] [--out FILE]
  --out      default synth/reports/config_table.md ("-" = stdout)
  --measure  place and route the serial configurations that no report covers yet
             (scripts/stage_fmax.py --whole acore_serial_top, about a minute each); the results are
             kept in synth/reports/config_table_measured.json and reused by later runs.

Where each figure comes from (the table says it per row):
  words, LATENCY, CYCLES  the RTL itself: `verilator --xml-only` elaborates the top with the line's
                          parameters and the script reads the top's WORDS, LATENCY and CYCLES.
  a line with reports     scripts/synth.sh reports of that line (its family's flow, e.g. ice40:
                          ice40_<name>.txt, LUT4; the device's flow, e.g. hx8k:
                          nextpnr_<name>_pnr.log, LCs and Fmax of the whole top or core in its pin
                          wrapper). When the whole top does not fit the device (the
                          default acore_top), its Fmax is bounded by its slowest stage placed alone:
                          the registry's placed lines of the modules it instantiates, at their
                          defaults (scripts/registry.py default_top_stages).
  other acore_top         the design-space sweep (synth/reports/design_space.csv, the row with the
                          same parameters): LUT4 of the whole top (synth_ice40), Fmax of its slowest
                          stage placed alone; not placed whole (no LCs).
  other serial            --measure (the serial core placed and routed whole).
Nothing is synthesized for a pipelined configuration without a report: it says "not measured".
The parameters' defaults (to match a sweep row) are the RTL's (acore_top's header, elaborated).
"""

import argparse
import concurrent.futures
import csv
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import devices
import registry
from registry import cells

TOPS = ("acore_top", "acore_serial_top")


def parse_params(tokens):
    return {k: int(v) for k, v in (t.split("=", 1) for t in tokens)}


def sweep_rows(root):
    path = os.path.join(root, "synth", "reports", "design_space.csv")
    return list(csv.DictReader(open(path))) if os.path.exists(path) else []


def sweep_match(rows, engine, params, defaults):
    """The design-space row with these parameters. The sweep lists the grid point and the COEF_F its
    calibration chose; a lower COEF_F comes with ACC_G raised by as much and ACC_I >= REG_W-COEF_F+1
    (calibration.cpp quantize_auto_range), which a named configuration spells out."""
    full = dict(defaults, **params)
    for r in rows:
        if r["engine"] != engine or r.get("error"):
            continue
        p = dict(defaults, **parse_params(r["params"].split()))
        c = int(r["coef_f"])
        if c != p["COEF_F"]:
            acc_f = p["COEF_F"] + p["ACC_G"]
            p["ACC_I"] = max(p["ACC_I"], p["REG_W"] - c + 1)
            p["COEF_F"], p["ACC_G"] = c, acc_f - c
        if p == full:
            return r
    return None


def fmt_rate(x):
    if x is None:
        return "-"
    m, e = f"{x:.2e}".split("e")
    return f"{m} × 10^{int(e)}"


def main():
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    ap.add_argument("--measure", action="store_true")
    ap.add_argument("--out", default=None)
    a = ap.parse_args()
    root = a.root
    rep = os.path.join(root, "synth", "reports")
    out_path = a.out or os.path.join(rep, "config_table.md")
    measured_path = os.path.join(rep, "config_table_measured.json")
    measured = json.load(open(measured_path)) if os.path.exists(measured_path) else {}
    sweep = sweep_rows(root)

    lines = []
    table = registry.table(root)
    dev = table.default
    fam = dev.family
    pnr_result = lambda log: registry.pnr_result(log, dev)
    rows = [l for l in registry.load(root) if l.module in TOPS]
    defaults = registry.rtl_parameters(root, "acore_top")
    stages = [registry.placed_design(root, l) for l in registry.default_top_stages(root)]
    with concurrent.futures.ThreadPoolExecutor(2) as ex:  # each elaboration takes a second or two
        list(ex.map(lambda l: registry.rtl_constants(root, l.module, l.params), rows))
    for line in rows:
        top, name, params = line.module, line.name, dict(line.params)
        serial = top == "acore_serial_top"
        k = registry.rtl_constants(root, top, line.params)
        cycles = k["CYCLES"]
        lut4 = lcs = fmax = None
        bound = False
        area = registry.report(root, fam.name, name)
        log = registry.report(root, dev.name, registry.placed_design(root, line))
        lut = next(label for label, count in fam.columns if "lut" in count)
        if os.path.exists(area):
            lut4 = fam.count(cells(area) or {"total": 0}, ["lut"]) or None
            how = [f"{lut} `{os.path.basename(area)}`"]
            if os.path.exists(log):
                fmax, lc, _ = pnr_result(log)
                lcs = f"{lc[0]}/{lc[1]}" if lc else None
                whole = "core" if serial else "top"
                fmt_name = os.path.splitext(dev.constraints)[1][1:].upper()
                pins = f", {fmt_name}" if registry.pnr_constrained(log, dev) else ""
                lcs_name = fam.pnr_cell_label
                if fmax:
                    how.append(
                        f"{lcs_name}, Fmax `{os.path.basename(log)}` (whole {whole} "
                        f"placed and routed{pins})"
                    )
                else:
                    how.append(
                        f"{lcs_name} `{os.path.basename(log)}` (does not fit the {dev.short})"
                    )
            if fmax is None and not serial and not params:
                fs = [pnr_result(registry.report(root, dev.name, d))[0] for d in stages]
                fmax = min(f for f in fs if f) if any(fs) else None
                bound = True
                how.append("Fmax = slowest stage placed alone (≤)")
            how = f"measured, `scripts/synth.sh -d {name}`: " + "; ".join(how)
        elif serial:
            key = " ".join(f"{p}={v}" for p, v in sorted(params.items()))
            if key not in measured and a.measure:
                r = subprocess.run(
                    [
                        sys.executable,
                        os.path.join(root, "scripts", "stage_fmax.py"),
                        "--whole",
                        "acore_serial_top",
                        root,
                        os.path.join(root, "synth", "build", "config_table"),
                        *key.split(),
                    ],
                    capture_output=True,
                    text=True,
                )
                if r.returncode != 0:
                    raise RuntimeError(
                        f"stage_fmax.py --whole acore_serial_top {key}: {r.stderr.strip()}"
                    )
                measured[key] = json.loads(r.stdout)
                with open(measured_path, "w") as f:
                    json.dump(measured, f, indent=1, sort_keys=True)
                    f.write("\n")
            m = measured.get(key)
            if m:
                lut4, fmax = m.get("lut4"), m.get("fmax_mhz")
                lcs = f"{m['lcs']}/{dev.capacity['logic_cells']}" if m.get("lcs") else None
                how = (
                    "measured, `scripts/config_table.py --measure` (`stage_fmax.py --whole`: whole "
                    "core placed and routed, generated wrapper, pins unconstrained)"
                )
            else:
                how = "not measured (run `scripts/config_table.py --measure`)"
        else:
            r = sweep_match(sweep, "pipelined", params, defaults)
            if r and r.get("lut4"):
                lut4 = int(r["lut4"])
                fmax = float(r["fmax_mhz"]) if r.get("fmax_mhz") else None
                bound = True
                how = (
                    f"measured, design-space sweep (`design_space.csv` row {r['index']}): {lut} of "
                    "the whole top; Fmax = slowest stage placed alone (≤); not placed whole"
                )
            else:
                how = (
                    "not measured (no report has this configuration; a whole-top synthesis takes "
                    "minutes)"
                )
        rate = fmax * 1e6 / cycles if fmax else None
        ptxt = " ".join(f"{p}={v}" for p, v in params.items()) or "(defaults)"
        le = "≤ " if bound and fmax else ""
        lines.append(
            f"| {name} | `{top}` {ptxt} | {k['WORDS']} | {k['LATENCY']} | {cycles} | "
            f"{lut4 if lut4 is not None else '-'} | {lcs or '-'} | "
            f"{le + f'{fmax:.1f}' if fmax else '-'} | "
            f"{le + fmt_rate(rate) if rate else '-'} | {how} |"
        )

    shown = [
        x
        for i, x in enumerate(sys.argv[1:])
        if not x.startswith("--root") and sys.argv[i] != "--root"
    ]
    cmd = " ".join(["scripts/config_table.py", *shown])
    text = [
        "# Configuration table",
        "",
        (
            f"Generated by `{cmd}` from the repository root (`--measure` places and routes the "
            "serial configurations no report covers, results kept in `config_table_measured.json`; "
            "without it the script only reads reports). Every `acore_top` and `acore_serial_top` "
            "line of the build registry `rtl/configs.txt` (pipelined `acore_top`, one sample per "
            "clock, or folded to one sample every FOLD clocks; the serial core `acore_serial_top`, "
            "one sample every CYCLES clocks). Words, LATENCY and CYCLES are the RTL's own "
            "constants (`verilator --xml-only` with the configuration's parameters); area and "
            f"clock come from the reports named in the last column ({table.flow['yosys']} "
            f"`{fam.synth}`, {fam.measured_with} on {devices.article(dev.short)} {dev.package}, "
            f'seed {table.seed}). samples/s = Fmax / clocks per sample. "≤": the pipelined top '
            "was not placed whole, its clock is bounded by its slowest stage placed alone "
            "(routing congestion of the whole design not included)."
        ),
        "",
        (
            "| configuration | top and parameters | words | LATENCY (clk) | clk/sample | "
            f"{fam.title} {lut} | {dev.short} {fam.pnr_cell_label} | Fmax (MHz) "
            "| samples/s | source |"
        ),
        "|---|---|---|---|---|---|---|---|---|---|",
        *lines,
    ]
    text = "\n".join(text) + "\n"
    if out_path == "-":
        sys.stdout.write(text)
    else:
        with open(out_path, "w") as f:
            f.write(text)
        print(f"wrote {out_path}")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except registry.RegistryError as e:
        print(f"config_table: {e}", file=sys.stderr)
        sys.exit(2)
