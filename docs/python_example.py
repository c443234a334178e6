# SPDX-License-Identifier: MIT
"""The demo's Table 3 and error plot (`anglecore demo`) in Python:
.venv/bin/python docs/python_example.py [PNG]"""

import sys

import anglecore as ac
import numpy as np

cal = ac.simulate("paper", samples=4096, seed=1)  # the demo's calibration and validation seeds
val = ac.simulate("paper", samples=4096, seed=2)
img = ac.calibrate(cal)
fixed = ac.estimate(img, val, engine="fixed")
flt = ac.estimate(img, val, engine="float")
printed = ac.estimate(ac.calibrate(cal, zero_offset=0), val, engine="fixed")  # Eq. 6 as printed
raw = (fixed.uncorrected_error + np.degrees(img.zero_offset) + 180) % 360 - 180  # offset kept


def row(name, e):
    print(f"  {name:<36} {np.sqrt(np.mean(e**2)):7.3f} {np.max(np.abs(e)):7.3f} {np.mean(e):+7.3f}")


print(f"  {'':<36} {'RMS':>7} {'max|e|':>7} {'mean':>7}")
row("ours, uncorrected", raw)
row("ours, zero offset removed only", fixed.uncorrected_error)
row("ours, corrected, float", flt.error)
row("ours, corrected, bit-accurate", fixed.error)
row("ours, bit-accurate, Eq. 6 as printed", printed.error)
print(f"  register file {len(img.words)} words, zero offset {np.degrees(img.zero_offset):+.3f} deg")

if len(sys.argv) > 1:  # the error plot: uncorrected and corrected error against the angle
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    order = np.argsort(val.theta_ref % (2 * np.pi))
    theta = np.degrees(val.theta_ref % (2 * np.pi))[order]
    plt.plot(theta, fixed.uncorrected_error[order], ",", label="uncorrected")
    plt.plot(theta, fixed.error[order], ",", label="corrected, bit-accurate")
    plt.xlabel("theta_ref (deg)"), plt.ylabel("error (deg)"), plt.legend(), plt.grid(True)
    plt.savefig(sys.argv[1], dpi=120)
