#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Plots for the demo report, from the CSV files `anglecore demo` writes into its output folder.

usage: /usr/bin/python3 scripts/plot_demo.py OUT_DIR
Reads OUT_DIR/validation_angles.csv (theta_ref, s13, s24, y13, y24, err_uncorrected,
err_float, err_fixed[, err_rtl]) and writes error_vs_angle.png, lissajous.png, histogram.png; and
the drive outputs, OUT_DIR/velocity.csv (t_ms, velocity_rpm, reference_rpm, profile_rpm) and
velocity_noise.csv (t_ms, observer_rpm, finite_difference_rpm), into velocity.png.
"""

import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def load(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    d = load(os.path.join(out, "validation_angles.csv"))
    deg = [t * 180.0 / 3.141592653589793 for t in d["theta_ref"]]

    fig, ax = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    ax[0].plot(deg, d["err_uncorrected"], lw=1, label="uncorrected")
    ax[0].set_ylabel("error [deg]")
    ax[0].legend(loc="upper right")
    ax[0].grid(alpha=0.3)
    ax[1].plot(deg, d["err_float"], lw=1, label="corrected, float")
    ax[1].plot(deg, d["err_fixed"], lw=1, ls="--", label="corrected, bit-accurate")
    if "err_rtl" in d:
        ax[1].plot(deg, d["err_rtl"], lw=1, ls=":", label="corrected, RTL")
    ax[1].set_ylabel("error [deg]")
    ax[1].set_xlabel("reference angle [deg]")
    ax[1].legend(loc="upper right")
    ax[1].grid(alpha=0.3)
    fig.suptitle("Angle error before and after correction (validation recording)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "error_vs_angle.png"), dpi=110)

    fig, ax = plt.subplots(figsize=(5.5, 5.5))
    ax.plot(d["s24"], d["s13"], lw=1, label="scaled (before)")
    ax.plot(d["y24"], d["y13"], lw=1, label="corrected (after)")
    ax.set_aspect("equal")
    ax.set_xlabel("cosine curve")
    ax.set_ylabel("sine curve")
    ax.grid(alpha=0.3)
    ax.legend(loc="upper right")
    ax.set_title("Lissajous figure")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "lissajous.png"), dpi=110)

    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    ax[0].hist(d["err_uncorrected"], bins=80)
    ax[0].set_title("uncorrected")
    ax[0].set_xlabel("error [deg]")
    ax[1].hist(d["err_fixed"], bins=80, color="C1")
    ax[1].set_title("corrected, bit-accurate")
    ax[1].set_xlabel("error [deg]")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "histogram.png"), dpi=110)

    v = load(os.path.join(out, "velocity.csv"))
    n = load(os.path.join(out, "velocity_noise.csv"))
    fig, ax = plt.subplots(3, 1, figsize=(9, 9))
    ax[0].plot(v["t_ms"], v["velocity_rpm"], lw=0.8, label="observer (estimated angle)")
    ax[0].plot(v["t_ms"], v["reference_rpm"], lw=0.8, ls="--", label="observer (reference angle)")
    ax[0].plot(v["t_ms"], v["profile_rpm"], "k:", lw=0.8, label="profile speed")
    ax[0].set_ylim(min(v["profile_rpm"]) - 150, max(v["profile_rpm"]) + 150)  # the settled loop
    ax[0].set_ylabel("velocity [rpm]")
    ax[0].set_title("Velocity against the reference (3000 rpm, 2 % ripple at 40 Hz)")
    ax[0].legend(loc="lower right", fontsize=8)
    ax[0].grid(alpha=0.3)
    err = [a - b for a, b in zip(v["velocity_rpm"], v["reference_rpm"])]
    ax[1].plot(v["t_ms"], err, lw=0.8)
    ax[1].set_ylabel("error [rpm]")
    ax[1].set_xlabel("time [ms]")
    ax[1].set_title("Velocity error: estimated minus reference, through the same observer")
    ax[1].grid(alpha=0.3)
    ax[2].plot(n["t_ms"], n["finite_difference_rpm"], lw=0.8, label="finite difference")
    ax[2].plot(n["t_ms"], n["observer_rpm"], lw=0.8, label="observer")
    ax[2].set_ylabel("velocity [rpm]")
    ax[2].set_xlabel("time [ms]")
    ax[2].set_title("Velocity noise at constant speed, equal bandwidth")
    ax[2].legend(loc="lower right", fontsize=8)
    ax[2].grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "velocity.png"), dpi=110)


if __name__ == "__main__":
    main()
