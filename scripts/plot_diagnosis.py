#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Plots for `anglecore diagnose --report DIR`, from DIR/gap_series.csv and DIR/stages.csv.

usage: /usr/bin/python3 scripts/plot_diagnosis.py DIR
"""

import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def load(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return rows


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    rows = load(os.path.join(out, "gap_series.csv"))
    col = {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}
    deg = np.degrees(np.mod(col["theta_ref"], 2 * math.pi))

    fig, ax = plt.subplots(figsize=(9, 4))
    ax.plot(deg, col["g"], ".", ms=1, alpha=0.3, label="gap g (real - model error)")
    ax.plot(deg, col["g_systematic"], ".", ms=1.5, label="systematic part, before")
    ax.plot(
        deg,
        col["g_after_systematic"],
        ".",
        ms=1.5,
        label="systematic part, after adding the effect",
    )
    ax.set_xlabel("reference angle [deg]")
    ax.set_ylabel("[deg]")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper right", markerscale=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "gap_vs_angle.png"), dpi=110)

    fig, ax = plt.subplots(1, 3, figsize=(13, 4))
    ax[0].plot(col["omega"], col["g_systematic"], ".", ms=1)
    ax[0].set_xlabel("angular velocity [rad/s]")
    ax[1].plot(col["temp"], col["g_systematic"], ".", ms=1)
    ax[1].set_xlabel("temperature [C]")
    fwd = col["omega"] >= 0
    ax[2].boxplot(
        [col["g_systematic"][fwd], col["g_systematic"][~fwd]], labels=["forward", "backward"]
    )
    for a in ax:
        a.set_ylabel("systematic gap [deg]")
        a.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "gap_domains.png"), dpi=110)

    st = load(os.path.join(out, "stages.csv"))
    fig, ax = plt.subplots(figsize=(9, 3.5))
    labels = [f"{r['stage']}\n{r['signal']}" for r in st]
    ax.bar(range(len(st)), [float(r["rms_over_noise"]) for r in st])
    ax.axhline(1.0, color="k", lw=0.8, ls="--")
    ax.set_xticks(range(len(st)))
    ax.set_xticklabels(labels, fontsize=8)
    ax.set_ylabel("RMS(real - model) / noise")
    ax.set_yscale("log")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "stages.png"), dpi=110)

    th = col["theta_ref"]
    orders = np.arange(1, 17)
    amp = []
    for k in orders:
        a = 2 * np.mean(col["g"] * np.cos(k * th))
        b = 2 * np.mean(col["g"] * np.sin(k * th))
        amp.append(math.hypot(a, b))
    fig, ax = plt.subplots(figsize=(8, 3.5))
    ax.bar(orders, amp)
    ax.set_xlabel("mechanical order")
    ax.set_ylabel("gap amplitude [deg]")
    ax.set_title("gap spectrum (before)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "gap_spectrum.png"), dpi=110)


if __name__ == "__main__":
    main()
