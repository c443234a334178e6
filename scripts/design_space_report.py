#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Design-space sweep, merge step: joins every shard of a sweep directory into the table and plots.

usage: design_space_report.py DIR
  reads  DIR/grid.json, DIR/accuracy-*-of-*.jsonl (anglecore sweep), DIR/hw-*-of-*.jsonl
         (scripts/design_space_hw.py, optional)
  writes DIR/design_space.md (table, Pareto fronts, targets), DIR/design_space.csv,
         DIR/pareto.png (accuracy against register words, LUT4, Fmax and samples/s)
Fails (exit 1) when a shard is missing, two shards disagree on the grid, or a point is missing.
The device, its family's LUT and flip-flop names come from synth/devices.toml (the hardware rows'
"device", the default device for rows written before they named it).
Uses Debian's python3-matplotlib (run with /usr/bin/python3).
"""

import csv
import glob
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import devices

TARGETS = [
    (64, 0.10, 0.35),
    (104, 0.01, 0.07),
]  # words, RMS, max (accuracy targets, noise-free paper scenario)
MAIN = "paper-noiseless"


def load(d):
    grid = json.load(open(os.path.join(d, "grid.json")))
    files = sorted(glob.glob(os.path.join(d, "accuracy-*-of-*.jsonl")))
    if not files:
        sys.exit(
            f"design_space_report.py: {d}: no accuracy-*-of-*.jsonl (run anglecore sweep first)"
        )
    counts = {re.search(r"-of-(\d+)\.jsonl$", f).group(1) for f in files}
    if len(counts) != 1:
        sys.exit(f"design_space_report.py: shards of different splits in {d}: {sorted(counts)}")
    n = int(counts.pop())
    have = {int(re.search(r"accuracy-(\d+)-of-", f).group(1)) for f in files}
    missing = sorted(set(range(n)) - have)
    if missing:
        sys.exit(f"design_space_report.py: shards {missing} of {n} are missing in {d}")
    rows = {}
    for f in files:
        for k, line in enumerate(open(f), 1):
            try:
                r = json.loads(line)
            except json.JSONDecodeError as e:
                sys.exit(f"design_space_report.py: {f}:{k}: not JSON ({e})")
            rows[r["index"]] = r
    lost = sorted(set(range(grid["points"])) - set(rows))
    if lost:
        sys.exit(
            f"design_space_report.py: points {lost[:10]}{'...' if len(lost) > 10 else ''} missing "
            f"(a shard stopped early?)"
        )
    hw = {}
    for f in glob.glob(os.path.join(d, "hw-*-of-*.jsonl")):
        for line in open(f):
            h = json.loads(line)
            if "error" not in h:
                hw[h["final_params"]] = h
    return grid, [rows[i] for i in sorted(rows)], hw


def coef_f(r):
    m = re.search(r"COEF_F=(\d+)", r.get("final_params", ""))
    return int(m.group(1)) if m else None


def short(r):
    """A compact label of a point for the plots, e.g. 'poly2d d3', 'n5 r8 xc', 'F21',
    'serial n3'."""
    p = dict(kv.split("=") for kv in r["params"].split())
    mode = {"0": "n", "1": "poly2d d", "2": ""}[p.get("CORRECTION", "0")]
    lab = f"{mode}{p.get('DEGREE', 3)}" if p.get("CORRECTION", "0") != "2" else "none"
    if p.get("REGIONS", "4") == "8":
        lab += " r8"
    if p.get("XCENTER", "0") == "1":
        lab += " xc"
    if p.get("FOURIER_K", "0") != "0":
        lab = (lab + " + " if lab != "none" else "") + f"F{p['FOURIER_K']}"
    if p.get("K") and p.get("K") != "16" and "ANGLE_W" not in p:
        lab += f" k{p['K']}"
    if "ANGLE_W" in p:
        lab += f" a{p['ANGLE_W']}"
    if p.get("FOLD", "1") != "1":
        lab += f" /{p['FOLD']}"
    return ("serial " if r.get("engine") == "serial" else "") + lab


def fold(r):
    """Clocks per sample of the pipelined top (FOLD; 1 unless the point folds it)."""
    m = re.search(r"FOLD=(\d+)", r.get("final_params", "") or r.get("params", ""))
    return int(m.group(1)) if m else 1


def pareto(points):
    """Indices of points not dominated in (cost, error): no other point is <= in both
    and < in one."""
    front = []
    for i, (c, e) in enumerate(points):
        if not any(
            (c2 <= c and e2 <= e) and (c2 < c or e2 < e)
            for j, (c2, e2) in enumerate(points)
            if j != i
        ):
            front.append(i)
    return front


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    d = sys.argv[1]
    grid, rows, hw = load(d)
    try:
        table = devices.load(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    except devices.DevicesError as e:
        sys.exit(f"design_space_report.py: {e}")
    used = {h.get("device", table.flow["default_device"]) for h in hw.values()}
    if len(used) > 1 or not used <= set(table.devices):
        sys.exit(
            f"design_space_report.py: {d}: hardware rows of devices {sorted(used)} (one device of "
            f"synth/devices.toml a sweep)"
        )
    dev = table.devices[used.pop() if used else table.flow["default_device"]]
    fam = dev.family
    label = lambda cls: next((lab for lab, count in fam.columns if cls in count), cls.upper())
    lut, ff = label("lut"), label("ff")
    ok = [r for r in rows if "error" not in r]
    scen = list(ok[0]["accuracy"].keys()) if ok else []
    serial_rows = []
    for r in ok:
        h = hw.get(r["final_params"], {})
        r["engine"] = "pipelined"
        r["lut4"], r["dff"], r["fmax"] = h.get("lut4"), h.get("dff"), h.get("fmax_mhz")
        # Stages too large for the device alone were not placed: Fmax is then that of the others.
        big = {}
        for st in h.get("stages", []):
            if not st.get("fits"):
                big[st["module"]] = max(big.get(st["module"], 0), st.get("lcs") or 0)
        r["unplaced"] = [f"{m} ({n} LCs)" for m, n in sorted(big.items())]
        r["fold"] = fold(r)
        r["sps"] = r["fmax"] * 1e6 / r["fold"] if r["fmax"] else None  # a sample every FOLD clocks
        if h.get("whole") and not h["whole"].get("fits"):
            r["nofit"] = h["whole"].get("lcs")  # the folded top placed whole did not fit the device
        r["rms"] = r["accuracy"][MAIN]["fixed"]["rms"]
        r["max"] = r["accuracy"][MAIN]["fixed"]["max_abs"]
        if h.get("serial"):
            # The serial core is bit-exact to the same model: same accuracy, its own area and rate.
            sr = h["serial"]
            s2 = dict(
                r,
                engine="serial",
                lut4=sr["lut4"],
                dff=sr["dff"],
                fmax=sr.get("fmax_mhz"),
                unplaced=[],
            )
            s2["sps"] = s2["fmax"] * 1e6 / sr["cycles"] if s2["fmax"] else None
            s2["cycles"] = sr["cycles"]
            serial_rows.append(s2)
    rows = rows + serial_rows
    ok = ok + serial_rows
    rid = lambda r: (r["index"], r.get("engine"))
    front_words = {rid(ok[i]) for i in pareto([(r["words"], r["rms"]) for r in ok])}
    with_hw = [r for r in ok if r["lut4"]]
    front_lut = {rid(with_hw[i]) for i in pareto([(r["lut4"], r["rms"]) for r in with_hw])}

    with open(os.path.join(d, "design_space.csv"), "w", newline="") as f:
        w = csv.writer(f)
        head = ["index", "engine", "params", "words", "coef_f"]
        for s in scen:
            head += [f"{s}_fixed_rms", f"{s}_fixed_max", f"{s}_float_rms", f"{s}_float_max"]
        w.writerow([*head, "lut4", "dff", "fmax_mhz", "samples_per_s", "error"])
        for r in rows:
            line = [
                r["index"],
                r.get("engine", "pipelined"),
                r["params"],
                r.get("words"),
                coef_f(r),
            ]
            for s in scen:
                a = r.get("accuracy", {}).get(s)
                line += (
                    [
                        a["fixed"]["rms"],
                        a["fixed"]["max_abs"],
                        a["float"]["rms"],
                        a["float"]["max_abs"],
                    ]
                    if a
                    else [""] * 4
                )
            line += [r.get("lut4"), r.get("dff"), r.get("fmax"), r.get("sps"), r.get("error", "")]
            w.writerow(line)

    md = [
        "# Design space",
        "",
        (
            "Generated by the design-space workflow (`workflow/Snakefile`, "
            f"`scripts/design_space.sh`; {grid['points']} points; calibration "
            f"{grid['cal_samples']} samples, validation {grid['val_samples']} samples at other "
            "angles, noise-free scenarios). Accuracy: bit-accurate model (= RTL), error = estimate "
            f"− reference, degrees. {lut}/{ff}: Yosys `{fam.synth}` of the whole `acore_top`; "
            f"Fmax: slowest datapath stage placed and routed alone on {devices.article(dev.title)} "
            "(`scripts/stage_fmax.py`), or for a folded top (FOLD > 1: a sample every FOLD clocks) "
            "the whole top placed and routed; samples/s = Fmax / FOLD. Rows marked *serial*: the "
            "serial core (`rtl/acore_serial_top.v`, same parameters, bit-exact to the same model) "
            "placed and routed whole; samples/s = Fmax / CYCLES. P = on the Pareto front of RMS "
            f"against words (w) or {lut} (l)."
        ),
        "",
    ]
    hdr = "| # | configuration | words | COEF_F |"
    sep = "|---|---|---|---|"
    for s in scen:
        hdr += f" {s} RMS ° | {s} max ° |"
        sep += "---|---|"
    hdr += f" float RMS ({MAIN}) ° | {lut} | {ff} | Fmax MHz | Msamples/s | P |"
    sep += "---|---|---|---|---|---|"
    md += [hdr, sep]
    for r in rows:
        if "error" in r:
            md.append(
                f"| {r['index']} | `{r['params']}` | - | - | "
                + "- | - | " * len(scen)
                + f"calibration failed: {r['error']} | | | | | |"
            )
            continue
        name = f"`{r['params']}`" + (
            f" *serial* ({r['cycles']} clk/sample)" if r.get("engine") == "serial" else ""
        )
        line = f"| {r['index']} | {name} | {r['words']} | {coef_f(r)} |"
        for s in scen:
            a = r["accuracy"][s]["fixed"]
            line += f" {a['rms']:.4f} | {a['max_abs']:.3f} |"
        p = ("w" if rid(r) in front_words else "") + ("l" if rid(r) in front_lut else "")
        fm = (f"{r['fmax']:.1f}" + ("†" if r.get("unplaced") else "")) if r["fmax"] else "-"
        if r.get("nofit"):
            fm = f"no fit ({r['nofit']} {fam.pnr_cell_label})"
        sps = f"{r['sps'] / 1e6:.1f}" if r["sps"] else "-"
        line += (
            f" {r['accuracy'][MAIN]['float']['rms']:.4f} | {r['lut4'] or '-'} | {r['dff'] or '-'} "
            f"| {fm} | {sps} | {p} |"
        )
        md.append(line)
    unplaced = [r for r in ok if r.get("unplaced")]
    if unplaced:
        md += [
            "",
            f"† A stage of this configuration is larger than {devices.article(dev.short)} placed "
            "alone, so it was not placed; the Fmax shown is that of the other stages (the large "
            "stage repeats the same one-adder-per-clock step, but its routing is not measured): "
            + "; ".join(
                f"#{r['index']}: {', '.join(r['unplaced'])}"
                for r in unplaced
                if r.get("engine") != "serial"
            )
            + ".",
        ]
    md += [
        "",
        f"## Targets ({MAIN}, bit-accurate, validation recording)",
        "",
        "| budget | required RMS / max | best point (by RMS) | its RMS / max | met |",
        "|---|---|---|---|---|",
    ]
    status = 0
    for words, rms, mx in TARGETS:
        cand = [r for r in ok if r["words"] <= words]
        meeting = [r for r in cand if r["rms"] <= rms and r["max"] <= mx]
        best = min(meeting or cand, key=lambda r: r["rms"]) if cand else None
        if best:
            md.append(
                f"| ≤ {words} words | {rms} / {mx} | `{best['params']}` "
                f"({best['words']} words) | {best['rms']:.4f} / {best['max']:.3f} | "
                f"{'yes' if meeting else 'NO'} |"
            )
        else:
            md.append(f"| ≤ {words} words | {rms} / {mx} | none in the grid | - | NO |")
    open(os.path.join(d, "design_space.md"), "w").write("\n".join(md) + "\n")

    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("design_space_report.py: matplotlib missing, no plot", file=sys.stderr)
        return status
    fig, axes = plt.subplots(2, 2, figsize=(12, 9))
    axes_spec = [
        ("words", "register words"),
        ("lut4", f"{fam.title} {lut}"),
        ("fmax", f"Fmax, MHz ({dev.short}, slowest stage)"),
        ("sps", "samples / s"),
    ]
    for ax, (key, label) in zip(axes.flat, axes_spec):
        pts = [r for r in ok if r.get(key)]
        if not pts:
            ax.text(
                0.5,
                0.5,
                f"no {label} data (sweep run with --no-synth)",
                ha="center",
                transform=ax.transAxes,
            )
            continue
        pip = [
            r
            for r in pts
            if r.get("engine") != "serial" and not (key in ("fmax", "sps") and r.get("unplaced"))
        ]
        part = [r for r in pts if key in ("fmax", "sps") and r.get("unplaced")]
        if part:
            ax.scatter(
                [r[key] for r in part],
                [r["rms"] for r in part],
                s=14,
                facecolors="none",
                edgecolors="C0",
                label="RMS (a stage too large to place: other stages' Fmax)",
            )
        ser = [r for r in pts if r.get("engine") == "serial"]
        ax.scatter(
            [r[key] for r in pip], [r["rms"] for r in pip], s=14, label="RMS (pipelined top)"
        )
        if ser and key != "words":
            ax.scatter(
                [r[key] for r in ser],
                [r["rms"] for r in ser],
                s=14,
                marker="s",
                label="RMS (serial core)",
            )
        ax.scatter(
            [r[key] for r in pts], [r["max"] for r in pts], s=8, marker="x", alpha=0.6, label="max"
        )
        if key in ("words", "lut4"):
            # Words: the serial core has the pipelined top's words and accuracy, so one
            # front suffices.
            cand = [r for r in pts if key == "lut4" or r.get("engine") != "serial"]
            fr = sorted(
                (cand[i] for i in pareto([(r[key], r["rms"]) for r in cand])), key=lambda r: r[key]
            )
            ax.step(
                [r[key] for r in fr],
                [r["rms"] for r in fr],
                where="post",
                color="k",
                lw=1,
                label="Pareto (RMS)",
            )
            for r in fr:
                ax.annotate(
                    short(r),
                    (r[key], r["rms"]),
                    fontsize=7,
                    xytext=(3, 3),
                    textcoords="offset points",
                )
        if key == "words":
            for words, rms, _mx in TARGETS:
                ax.plot([0, words, words], [rms, rms, 1e-4], "g--", lw=0.8)
        if key in ("sps", "lut4"):
            ax.set_xscale("log")
        ax.set_xlabel(label)
        ax.set_ylabel(f"angle error, ° ({MAIN}, bit-accurate)")
        ax.set_yscale("log")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("AngleCore design space: accuracy against cost")
    fig.tight_layout()
    fig.savefig(os.path.join(d, "pareto.png"), dpi=110)
    return status


if __name__ == "__main__":
    sys.exit(main())
