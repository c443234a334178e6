#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Configuration table: every named configuration of rtl/configs.txt (pipelined top) and of the
serial core (its defaults and rtl/serial_n5r8.cfg) with its register words, LATENCY, clocks per
sample, iCE40 LUT4, HX8K logic cells, Fmax and samples/s, written as Markdown.

usage: scripts/config_table.py [--root DIR] [--measure] [--out FILE]
  --out      default synth/reports/config_table.md ("-" = stdout)
  --measure  place and route the serial configurations that no report covers yet
             (scripts/stage_fmax.py --whole acore_serial_top, about a minute each); the results are
             kept in synth/reports/config_table_measured.json and reused by later runs.

Where each figure comes from (the table says it per row):
  words, LATENCY, CYCLES  the RTL itself: `verilator --xml-only` elaborates the top with the
                          configuration's parameters and the script reads the top's WORDS, LATENCY
                          and CYCLES constants.
  default acore_top       scripts/synth.sh reports: ice40_top.txt (LUT4), nextpnr_top_pnr.log (LCs:
                          it does not fit an HX8K), Fmax bounded by the slowest stage placed alone
                          (nextpnr_{scaler,region,poly,cordic_top}_pnr.log).
  other acore_top         the design-space sweep (synth/reports/design_space.csv, the row with the
                          same parameters): LUT4 of the whole top (synth_ice40), Fmax of its slowest
                          stage placed alone; not placed whole (no LCs).
  default acore_top at    scripts/synth.sh reports: ice40_top_fold<N>.txt (LUT4),
  FOLD=N (2, 4, 8)        nextpnr_top_fold<N>_pnr.log (LCs, Fmax: the whole top placed and routed).
  default serial core     scripts/synth.sh reports: ice40_serial.txt (LUT4), nextpnr_serial_pnr.log
                          (LCs, Fmax; pin constraints synth/acore_hx8k_ct256.pcf).
  other serial            --measure (the serial core placed and routed whole).
Nothing is synthesized for a pipelined configuration without a report: it says "not measured".
"""
import argparse
import csv
import json
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

DEFAULTS = {
    "IN_W": 16, "REG_W": 18, "S_W": 18, "S_F": 16, "R_SHIFT": 13, "SCALE_G": 4, "CORRECTION": 0,
    "DEGREE": 3, "REGIONS": 4, "XCENTER": 0, "COEF_F": 15, "ACC_G": 4, "ACC_I": 6, "K": 16,
    "CORDIC_G": 3, "Z_W": 20, "ANGLE_W": 16, "FOURIER_K": 0, "FOURIER_M": 12, "FOURIER_CF": 22,
    "FOURIER_W": 16, "FOURIER_G": 2, "ZERO": 0, "FOLD": 1,
}


def rtl_constants(root, top, params, names):
    """The top's elaborated constants (verilator --xml-only with -G overrides)."""
    rtl = os.path.join(root, "rtl")
    files = [l.strip() for l in open(os.path.join(rtl, "files.f")) if l.strip().endswith(".v")]
    with tempfile.TemporaryDirectory(prefix="acore_xml_") as tmp:
        xml = os.path.join(tmp, "top.xml")
        r = subprocess.run(["verilator", "--xml-only", "--xml-output", xml, "--Mdir", tmp, "verilator.vlt", *files,
                            "--top-module", top, *[f"-G{k}={v}" for k, v in params.items()]],
                           cwd=rtl, capture_output=True, text=True)
        if r.returncode != 0:
            raise RuntimeError(f"verilator --xml-only {top} {params}: {r.stderr.strip()[:500]}")
        tree = ET.parse(xml)
    mod = next(m for m in tree.iter("module") if m.get("topModule") == "1")
    out = {}
    for var in mod.findall("var"):
        if var.get("name") in names:
            const = var.find("const").get("name")  # e.g. 32'h37 or 32'sh37
            out[var.get("name")] = int(const.split("h")[-1], 16)
    return out


def cells(path):
    """Cell type -> count of the last `stat` block of a Yosys report (as scripts/synth_summary.py)."""
    if not os.path.exists(path):
        return None
    blocks = open(path).read().split("Number of cells:")
    if len(blocks) < 2:
        return None
    return {m.group(1): int(m.group(2)) for m in re.finditer(r"^\s+(\S+)\s+(\d+)\s*$", blocks[-1], re.M)}


def pnr(path):
    """(Fmax MHz or None, "used/total" LCs or None) of a nextpnr-ice40 log."""
    if not os.path.exists(path):
        return None, None
    text = open(path).read()
    fmax = re.findall(r"Max frequency for clock\s+'[^']*':\s+([\d.]+) MHz", text)
    lc = re.findall(r"ICESTORM_LC:\s+(\d+)/\s*(\d+)", text)
    return (float(fmax[-1]) if fmax else None), (f"{lc[-1][0]}/{lc[-1][1]}" if lc else None)


def parse_params(tokens):
    return {k: int(v) for k, v in (t.split("=", 1) for t in tokens)}


def named_configs(root):
    rows = []
    for line in open(os.path.join(root, "rtl", "configs.txt")):
        f = line.split()
        if re.match(r"[a-z]", line) and f[1] == "acore_top" and "sim" in f[2].split(","):
            rows.append(("acore_top", f[0], parse_params(f[3:])))
    rows.append(("acore_serial_top", "serial (defaults)", {}))
    cfg = [l.strip() for l in open(os.path.join(root, "rtl", "serial_n5r8.cfg")) if re.match(r"[A-Z_]+=", l)]
    rows.append(("acore_serial_top", "serial_n5r8", parse_params(cfg)))
    return rows


def sweep_rows(root):
    path = os.path.join(root, "synth", "reports", "design_space.csv")
    return list(csv.DictReader(open(path))) if os.path.exists(path) else []


def sweep_match(rows, engine, params):
    """The design-space row with these parameters. The sweep lists the grid point and the COEF_F its
    calibration chose; a lower COEF_F comes with ACC_G raised by as much and ACC_I >= REG_W-COEF_F+1
    (calibration.cpp quantize_auto_range), which a named configuration spells out."""
    full = dict(DEFAULTS, **params)
    for r in rows:
        if r["engine"] != engine or r.get("error"):
            continue
        p = dict(DEFAULTS, **parse_params(r["params"].split()))
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
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
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
    for top, name, params in named_configs(root):
        serial = top == "acore_serial_top"
        k = rtl_constants(root, top, params, {"WORDS", "LATENCY", "CYCLES"})
        cycles = k["CYCLES"]
        lut4 = lcs = fmax = None
        bound = False
        if not params and not serial:
            lut4 = (cells(os.path.join(rep, "ice40_top.txt")) or {}).get("SB_LUT4")
            _, lcs = pnr(os.path.join(rep, "nextpnr_top_pnr.log"))
            stages = [pnr(os.path.join(rep, f"nextpnr_{s}_pnr.log"))[0] for s in ("scaler", "region", "poly", "cordic_top")]
            fmax = min(f for f in stages if f) if any(stages) else None
            bound = True
            how = ("measured, `scripts/synth.sh`: LUT4 `ice40_top.txt`; LCs `nextpnr_top_pnr.log` (does not fit "
                   "the HX8K); Fmax = slowest stage placed alone (≤)")
        elif not serial and list(params) == ["FOLD"]:
            n = params["FOLD"]
            lut4 = (cells(os.path.join(rep, f"ice40_top_fold{n}.txt")) or {}).get("SB_LUT4")
            fmax, lcs = pnr(os.path.join(rep, f"nextpnr_top_fold{n}_pnr.log"))
            how = (f"measured, `scripts/synth.sh -d top_fold{n},top_fold{n}_pnr`: LUT4 `ice40_top_fold{n}.txt`; "
                   f"LCs, Fmax `nextpnr_top_fold{n}_pnr.log` (whole top placed and routed)")
        elif not params:
            lut4 = (cells(os.path.join(rep, "ice40_serial.txt")) or {}).get("SB_LUT4")
            fmax, lcs = pnr(os.path.join(rep, "nextpnr_serial_pnr.log"))
            how = ("measured, `scripts/synth.sh -d serial,serial_pnr`: LUT4 `ice40_serial.txt`; LCs, Fmax "
                   "`nextpnr_serial_pnr.log` (whole core, PCF)")
        elif serial:
            key = " ".join(f"{p}={v}" for p, v in sorted(params.items()))
            if key not in measured and a.measure:
                r = subprocess.run([sys.executable, os.path.join(root, "scripts", "stage_fmax.py"), "--whole",
                                    "acore_serial_top", root, os.path.join(root, "synth", "build", "config_table")]
                                   + key.split(), capture_output=True, text=True)
                if r.returncode != 0:
                    raise RuntimeError(f"stage_fmax.py --whole acore_serial_top {key}: {r.stderr.strip()}")
                measured[key] = json.loads(r.stdout)
                with open(measured_path, "w") as f:
                    json.dump(measured, f, indent=1, sort_keys=True)
                    f.write("\n")
            m = measured.get(key)
            if m:
                lut4, fmax = m.get("lut4"), m.get("fmax_mhz")
                lcs = f"{m['lcs']}/7680" if m.get("lcs") else None
                how = ("measured, `scripts/config_table.py --measure` (`stage_fmax.py --whole`: whole core placed "
                       "and routed, generated wrapper, pins unconstrained)")
            else:
                how = "not measured (run `scripts/config_table.py --measure`)"
        else:
            r = sweep_match(sweep, "pipelined", params)
            if r and r.get("lut4"):
                lut4 = int(r["lut4"])
                fmax = float(r["fmax_mhz"]) if r.get("fmax_mhz") else None
                bound = True
                how = (f"measured, design-space sweep (`design_space.csv` row {r['index']}): LUT4 of the whole "
                       "top; Fmax = slowest stage placed alone (≤); not placed whole")
            else:
                how = "not measured (no report has this configuration; a whole-top synthesis takes minutes)"
        rate = fmax * 1e6 / cycles if fmax else None
        ptxt = " ".join(f"{p}={v}" for p, v in params.items()) or "(defaults)"
        le = "≤ " if bound and fmax else ""
        lines.append(f"| {name} | `{top}` {ptxt} | {k['WORDS']} | {k['LATENCY']} | {cycles} | "
                     f"{lut4 if lut4 is not None else '-'} | {lcs or '-'} | "
                     f"{le + f'{fmax:.1f}' if fmax else '-'} | {le + fmt_rate(rate) if rate else '-'} | {how} |")

    cmd = " ".join(["scripts/config_table.py"] + [x for x in sys.argv[1:] if not x.startswith("--root")])
    text = ["# Configuration table", "",
            f"Generated by `{cmd}` from the repository root (`--measure` places and routes the serial "
            "configurations no report covers, results kept in `config_table_measured.json`; without it the "
            "script only reads reports). Every named configuration of `rtl/configs.txt` "
            "(pipelined `acore_top`, one sample per clock, or folded to one sample every FOLD clocks) and of the serial core (`acore_serial_top`, one sample "
            "every CYCLES clocks). Words, LATENCY and CYCLES are the RTL's own constants (`verilator --xml-only` "
            "with the configuration's parameters); area and clock come from the reports named in the last "
            "column (Yosys 0.23 `synth_ice40`, nextpnr-ice40 0.4 on an HX8K ct256, seed 1). samples/s = Fmax / "
            "clocks per sample. \"≤\": the pipelined top was not placed whole, its clock is bounded by its "
            "slowest stage placed alone (routing congestion of the whole design not included).", "",
            "| configuration | top and parameters | words | LATENCY (clk) | clk/sample | iCE40 LUT4 | HX8K LCs | "
            "Fmax (MHz) | samples/s | source |",
            "|---|---|---|---|---|---|---|---|---|---|"] + lines
    text = "\n".join(text) + "\n"
    if out_path == "-":
        sys.stdout.write(text)
    else:
        with open(out_path, "w") as f:
            f.write(text)
        print(f"wrote {out_path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
