#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The tracking observer's figures through the CLI (`anglecore simulate` + `calibrate` +
`estimate`):

  1. residual lag of the compensated angle (estimate --track-lead D: the angle D samples after the
     sample it was estimated from) at 10 and 60 krpm, 1 MS/s, D = 1 and 10 samples, against the
     reference angle D samples later, with and without the compensation;
  2. velocity on a 3000 rpm profile with a 2 % speed ripple (40 Hz), 1 MS/s: error RMS, max, mean
     against the reference through the same observer (velocity_error_rpm) and against the profile's
     own speed; a plot (docs/reports/track_velocity.png, matplotlib of /usr/bin/python3);
  3. velocity noise at constant speed: the observer's velocity against a finite difference whose
     -3 dB frequency equals the observer's velocity bandwidth wn, on the same estimated angles.

usage: track_measure.py ANGLECORE [--out DIR] [--plot PNG]
Writes DIR/track_measure.md (a table per measurement, with the commands) and prints it.
Runs on both sensors: `ideal` (the observer's own error) and `paper` (the paper scenario: its
residual systematic error and noise pass into the velocity).
"""

import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile

FS = 1_000_000


def run(cmd, log):
    log.append("$ " + " ".join(cmd))
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"failed ({r.returncode}): {' '.join(cmd)}\n{r.stderr}")
    return r.stdout


def read(path):
    return list(csv.DictReader(open(path)))


def wrap_deg(rad):
    return math.degrees(math.remainder(rad, 2 * math.pi))


def stats(xs):
    n = len(xs)
    mean = sum(xs) / n
    return math.sqrt(sum(x * x for x in xs) / n), max(abs(x) for x in xs), mean


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("anglecore")
    ap.add_argument("--out", default=".")
    ap.add_argument("--plot", default="")
    a = ap.parse_args()
    log, md = [], []
    os.makedirs(a.out, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        p = lambda n: os.path.join(tmp, n)
        regs = {}

        def estimate(sc, rec, out, *opts):
            """anglecore estimate of a recording with the sensor's image, the angles to OUT."""
            cmd = [a.anglecore, "estimate", "--regs", regs[sc], "--in", rec, "--out", out, *opts]
            return run(cmd, log)

        for sc in ("ideal", "paper"):
            run(
                [
                    a.anglecore,
                    "simulate",
                    "--scenario",
                    sc,
                    "--samples",
                    "20000",
                    "--seed",
                    "1",
                    "--out",
                    p(sc + "_cal.csv"),
                ],
                log,
            )
            run(
                [
                    a.anglecore,
                    "calibrate",
                    "--in",
                    p(sc + "_cal.csv"),
                    "--out",
                    p(sc + ".hex"),
                    "--zero-offset",
                    "0",
                ],
                log,
            )
            regs[sc] = p(sc + ".hex")

        # 1. Residual lag.
        md += [
            "## Residual lag of the compensated angle (1 MS/s, bandwidth code 6 = 3.6 kHz)",
            "",
            (
                "| sensor | speed | D (samples) | lag without compensation | residual mean | "
                "residual RMS | residual max |"
            ),
            "|---|---|---|---|---|---|---|",
        ]
        for sc in ("ideal", "paper"):
            for rpm in (10000, 60000):
                rec = p(f"{sc}_{rpm}.csv")
                run(
                    [
                        a.anglecore,
                        "simulate",
                        "--scenario",
                        sc,
                        "--profile",
                        "constant",
                        "--speed-rpm",
                        str(rpm),
                        "--sample-rate",
                        str(FS),
                        "--samples",
                        "100000",
                        "--seed",
                        "3",
                        "--out",
                        rec,
                    ],
                    log,
                )
                for d in (1, 10):
                    ang = p(f"{sc}_{rpm}_{d}.ang.csv")
                    estimate(sc, rec, ang, "--track-lead", str(d))
                    rows = read(ang)
                    settle = 20000
                    res = [
                        wrap_deg(float(rows[i]["angle_comp_rad"]) - float(rows[i + d]["theta_ref"]))
                        for i in range(settle, len(rows) - d)
                    ]
                    raw = [
                        wrap_deg(float(rows[i]["angle_rad"]) - float(rows[i + d]["theta_ref"]))
                        for i in range(settle, len(rows) - d)
                    ]
                    rms, mx, mean = stats(res)
                    md.append(
                        f"| {sc} | {rpm} rpm | {d} | {-sum(raw) / len(raw):.4f} deg | "
                        f"{mean:+.5f} deg | {rms:.5f} deg | {mx:.5f} deg |"
                    )
        md.append("")

        # 2. Velocity on the ripple profile.
        md += [
            "## Velocity on 3000 rpm with a 2 % speed ripple at 40 Hz (1 MS/s)",
            "",
            (
                "| sensor | bandwidth | vs reference through the observer: RMS / max / mean | vs "
                "the profile's speed: RMS / max |"
            ),
            "|---|---|---|---|",
        ]
        plot_data = {}
        for sc in ("ideal", "paper"):
            rec = p(f"{sc}_rip.csv")
            run(
                [
                    a.anglecore,
                    "simulate",
                    "--scenario",
                    sc,
                    "--profile",
                    "ripple",
                    "--speed-rpm",
                    "3000",
                    "--ripple",
                    "0.02",
                    "--ripple-hz",
                    "40",
                    "--sample-rate",
                    str(FS),
                    "--samples",
                    "200000",
                    "--seed",
                    "4",
                    "--out",
                    rec,
                ],
                log,
            )
            for bw in (200, 1000):
                ang, js = p(f"{sc}_rip_{bw}.csv"), p(f"{sc}_rip_{bw}.json")
                out = estimate(sc, rec, ang, "--track-bandwidth", str(bw), "--json", js)
                j = json.load(open(js))
                ve = j["velocity_error_rpm"]
                rows = read(ang)
                v = [float(r["velocity_rpm"]) for r in rows]
                true = [
                    3000 * (1 + 0.02 * math.sin(2 * math.pi * 40 * i / FS)) for i in range(len(v))
                ]
                settle = 50000
                rms, mx, _ = stats([v[i] - true[i] for i in range(settle, len(v))])
                md.append(
                    f"| {sc} | {j['track']['bandwidth_hz']:.0f} Hz (code {j['track']['code']}) | "
                    f"{ve['rms']:.2f} / {ve['max_abs']:.2f} / {ve['mean']:+.3f} rpm | "
                    f"{rms:.2f} / {mx:.2f} rpm |"
                )
                plot_data[(sc, bw)] = (v, true, j["track"]["bandwidth_hz"])
        md.append("")

        # 3. Velocity noise against a finite difference of the same bandwidth.
        md += [
            (
                "## Velocity noise at constant speed (3000 rpm, 1 MS/s) vs a finite "
                "difference of equal bandwidth"
            ),
            "",
            "| sensor | code | observer RMS | finite difference (N) RMS | ratio |",
            "|---|---|---|---|---|",
        ]
        for sc in ("paper",):
            rec = p(f"{sc}_const.csv")
            run(
                [
                    a.anglecore,
                    "simulate",
                    "--scenario",
                    sc + "-indep" if sc == "paper" else sc,
                    "--profile",
                    "constant",
                    "--speed-rpm",
                    "3000",
                    "--sample-rate",
                    str(FS),
                    "--samples",
                    "300000",
                    "--seed",
                    "5",
                    "--out",
                    rec,
                ],
                log,
            )
            for code_bw in (900, 3600):
                ang = p(f"{sc}_const_{code_bw}.csv")
                out = estimate(sc, rec, ang, "--track-bandwidth", str(code_bw))
                code = int(out.split("code ")[1].split()[0])
                wn = 2**-code / math.sqrt(2)
                n = 1
                while abs(
                    math.sin(wn * (n + 1) / 2) / ((n + 1) * math.sin(wn / 2))
                ) > 1 / math.sqrt(2):
                    n += 1
                rows = read(ang)
                th = [float(r["angle_rad"]) for r in rows]
                v = [float(r["velocity_rpm"]) for r in rows]
                settle = 100000
                fd = [
                    math.remainder(th[i] - th[i - n], 2 * math.pi) / (2 * math.pi) / n * FS * 60
                    for i in range(settle, len(th))
                ]
                ob = v[settle:]

                def sd(xs):
                    m = sum(xs) / len(xs)
                    return math.sqrt(sum((x - m) ** 2 for x in xs) / len(xs))

                md.append(
                    f"| {sc}-indep | {code} | {sd(ob):.2f} rpm | {sd(fd):.2f} rpm (N = {n}) | "
                    f"{sd(fd) / sd(ob):.2f} |"
                )
        md.append("")

        if a.plot:
            import matplotlib

            matplotlib.use("Agg")
            import matplotlib.pyplot as plt

            fig, axes = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
            for ax, sc in zip(axes, ("ideal", "paper")):
                for bw in (200, 1000):
                    v, true, hz = plot_data[(sc, bw)]
                    t = [i / FS * 1e3 for i in range(len(v))]
                    ax.plot(t[::50], v[::50], lw=0.8, label=f"observer, {hz:.0f} Hz")
                ax.plot(t[::50], true[::50], "k--", lw=0.8, label="profile speed")
                ax.set_ylim(2850, 3150)
                ax.set_ylabel("rpm")
                ax.set_title(f"{sc} sensor: 3000 rpm, 2 % ripple at 40 Hz, 1 MS/s")
                ax.legend(loc="lower right", fontsize=8)
            axes[-1].set_xlabel("time (ms)")
            fig.tight_layout()
            fig.savefig(a.plot, dpi=110)
    text = "\n".join(
        [
            "# Tracking observer measurements",
            "",
            "Generated by `scripts/track_measure.py` (commands at the end).",
            "",
            *md,
            "## Commands",
            "",
            "```",
            *log,
            "```",
            "",
        ]
    )
    os.makedirs(a.out, exist_ok=True)
    open(os.path.join(a.out, "track_measure.md"), "w").write(text)
    print("\n".join(md))


if __name__ == "__main__":
    main()
