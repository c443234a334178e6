#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Plots for `anglecore harmonics --plot DIR` (like Kuntz et al., Fig. 7).

Reads DIR/harmonics.json and DIR/harmonics_curve.csv written by the command and writes
DIR/harmonics_error.png (exact error, first/second-order Taylor predictions and their residuals over
one turn, with the Eq. 32 residual bounds) and DIR/harmonics_spectrum.png (per-order amplitudes:
exact DFT vs first- and second-order predictions).
usage: plot_harmonics.py DIR
"""

import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def main(out_dir):
    with open(os.path.join(out_dir, "harmonics.json")) as f:
        res = json.load(f)
    curve = np.genfromtxt(os.path.join(out_dir, "harmonics_curve.csv"), delimiter=",", names=True)
    bounds = res["bounds"]

    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(9, 7), sharex=True)
    ax1.plot(curve["phi_deg"], curve["exact_deg"], "k-", lw=1.6, label="exact (atan2)")
    ax1.plot(curve["phi_deg"], curve["first_deg"], "C0--", lw=1.0, label="Taylor k=1 (Eq. 18)")
    ax1.plot(curve["phi_deg"], curve["second_deg"], "C1:", lw=1.2, label="Taylor k=2 (Eq. 26)")
    ax1.set_ylabel("electrical error (deg)")
    ax1.set_title(
        f"p = {res['p']}: max |error| {res['max_error_deg']:.3f} deg "
        f"(geometric bound {bounds['geometric_deg']:.3f} deg)"
    )
    ax1.legend(loc="upper right", fontsize=8)
    ax1.grid(alpha=0.3)
    ax2.plot(
        curve["phi_deg"],
        curve["residual_first_deg"],
        "C0-",
        lw=1.0,
        label=f"residual k=1 (max {res['residual_first_deg']:.3f} deg)",
    )
    ax2.plot(
        curve["phi_deg"],
        curve["residual_second_deg"],
        "C1-",
        lw=1.0,
        label=f"residual k=2 (max {res['residual_second_deg']:.4f} deg)",
    )
    if bounds.get("taylor_first_deg") is not None:
        b1 = bounds["taylor_first_deg"]
        ax2.fill_between(
            curve["phi_deg"], -b1, b1, color="C0", alpha=0.12, label=f"bound k=1 (+-{b1:.3f} deg)"
        )
    if bounds.get("taylor_second_deg") is not None:
        b2 = bounds["taylor_second_deg"]
        ax2.axhline(b2, color="C1", ls="--", lw=0.8, label=f"bound k=2 (+-{b2:.3f} deg)")
        ax2.axhline(-b2, color="C1", ls="--", lw=0.8)
    ax2.set_xlabel("mechanical angle (deg)")
    ax2.set_ylabel("residual (deg)")
    ax2.set_xlim(0, 360)
    ax2.legend(loc="upper right", fontsize=8)
    ax2.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "harmonics_error.png"), dpi=120)
    plt.close(fig)

    h = [
        r for r in res["harmonics"] if max(r["exact_deg"], r["first_deg"], r["second_deg"]) >= 1e-4
    ]
    orders = np.array([r["order"] for r in h])
    w = 0.27
    fig, ax = plt.subplots(figsize=(9, 4))
    ax.bar(orders - w, [r["exact_deg"] for r in h], w, color="k", label="exact (DFT)")
    ax.bar(orders, [r["first_deg"] for r in h], w, color="C0", label="first order")
    ax.bar(orders + w, [r["second_deg"] for r in h], w, color="C1", label="second order")
    ax.set_yscale("log")
    ax.set_xlabel("angle-error order (per turn)")
    ax.set_ylabel("amplitude (deg, electrical)")
    ax.set_xticks(orders)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, axis="y")
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "harmonics_spectrum.png"), dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
