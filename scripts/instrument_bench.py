#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""A second benchmark of the gap diagnosis, on recordings written the way an instrument writes them.

Independent of the project's own physics rig (model/lab/physics): the field comes from magpylib (a
diametrically magnetized cylinder on a shaft), the sensing elements are Hall plates measuring B_z on
a ring (hall4: four plates at 90 degrees, columns c1..c4) or an in-plane pair at the axis (axis2:
B_y, B_x as sin, cos). The instrument has its own front end (volts or millitesla), its own noise,
an ADC whose range is not a power of two, a reference encoder of its own resolution, and prints
fixed decimals or significant digits. Each case injects one known effect of the vocabulary
(docs/contracts.md, effect vocabulary) into the real and holdout recordings; the simulation is the
designer's nominal model at one constant speed, in the same units.

    instrument_bench.py generate DIR [--per-case N] [--seed S] [--only NAME,...]
    instrument_bench.py score DIR --anglecore BUILD/anglecore [--jobs 2] [--min-top1 0.95]
                                    [--min-shrink 0.8]
    instrument_bench.py check --anglecore BUILD/anglecore [--only ...]   (generate into a temporary
                                    folder and score: every verdict must be right; the CTest)

`score` runs `anglecore diagnose --sim --real --holdout --json -` on each case and reports top-1
(the first named effect, or the verdict, is one the case accepts) and the median holdout shrink
(1 - after/before) over the cases with a gap; exit 1 when a target is missed.
"""

import argparse
import concurrent.futures
import json
import math
import os
import subprocess
import sys

import magpylib as magpy
import numpy as np

MM = 1e-3
SAMPLES = 4096


# --- the rig -----------------------------------------------------------------------------------
def nominal(rng, sensor):
    """The designer's geometry and the instrument's nominal front end."""
    g = {
        "sensor": sensor,
        "diameter": rng.uniform(5.5, 6.5) * MM,
        "height": rng.uniform(2.0, 3.0) * MM,
        "br": rng.uniform(1.1, 1.3),  # T
        "gap": rng.uniform(1.6, 2.4) * MM,  # sensor plane to magnet face
        "ring": rng.uniform(1.6, 2.2) * MM,  # plate radius (hall4)
        "ecc": 0.0,  # magnet centre off the shaft axis (run-out)
        "ecc_phase": 0.0,
        "ring_dx": 0.0,  # sensor ring displaced in its plane
        "ring_dy": 0.0,
        "plate_angle": [0.0, 0.0, 0.0, 0.0],  # extra placement angle per element, rad
        "sensitivity": [1.0, 1.0, 1.0, 1.0],
        "offset_T": [0.0, 0.0, 0.0, 0.0],
        "cubic": 0.0,  # front end x - a x^3 (x in units of the nominal peak)
        "clip_T": None,
        "unit": str(rng.choice(["mT", "V"])),
        "volts_per_T": rng.uniform(8.0, 30.0),  # V per T after the amplifier (unit V)
        "noise_T": rng.uniform(0.03, 0.08) * 1e-3,
        "noise_scale": 1.0,
        "adc_bits": None,
        "adc_range": None,  # +- range in recording units, not a power of two
        "delay_common_s": 0.0,  # every channel sampled this much earlier than its time stamp
        "delay_diff_s": [0.0, 0.0, 0.0, 0.0],  # per channel (mux slots, RC mismatch)
        "rc_s": 0.0,  # a first-order low-pass on every channel
        "encoder_zero": 0.0,  # the reference encoder's zero, rad
        "encoder_counts": int(rng.choice([1 << 14, 36000, 1 << 16])),
        "print": str(rng.choice(["fixed6", "sig6", "sig5"])),
    }
    return g


def element_positions(g):
    """Lab-frame position and measured axis of each element: plate k of hall4 at k*90 degrees."""
    if g["sensor"] == "hall4":
        pos = []
        for k in range(4):
            a = math.pi / 2 - k * math.pi / 2 + g["plate_angle"][k]
            pos.append(
                (g["ring"] * math.cos(a) + g["ring_dx"], g["ring"] * math.sin(a) + g["ring_dy"])
            )
        return pos
    return [(g["ring_dx"], g["ring_dy"])] * 2


def field(g, theta):
    """The measured field of each element (T) at shaft angles theta (array): magnet in the shaft
    frame, elements carried into it by R(-theta), the field turned back by R(theta)."""
    zc = g["gap"] + g["height"] / 2
    mag = magpy.magnet.Cylinder(
        polarization=(g["br"], 0, 0),
        dimension=(g["diameter"], g["height"]),
        position=(g["ecc"] * math.cos(g["ecc_phase"]), g["ecc"] * math.sin(g["ecc_phase"]), zc),
    )
    c, s = np.cos(theta), np.sin(theta)
    out = []
    for k, (x, y) in enumerate(element_positions(g)):
        q = np.stack([c * x + s * y, -s * x + c * y, np.zeros_like(theta)], 1)
        B = magpy.getB(mag, q)
        if g["sensor"] == "hall4":
            out.append(B[:, 2])
        else:
            bx = c * B[:, 0] - s * B[:, 1]
            by = s * B[:, 0] + c * B[:, 1]
            # axis2: sin = B_y, cos = B_x; a turned sensing axis (plate_angle) mixes them.
            a = g["plate_angle"][k]
            out.append(
                math.cos(a) * by - math.sin(a) * bx
                if k == 0
                else math.cos(a) * bx + math.sin(a) * by
            )
    return np.array(out)


def trajectory(rng, kind, n):
    """Time stamps and shaft angles: constant speed, or a ramp through a reversal."""
    dur = 1.0
    t = np.arange(n) * dur / n
    if kind == "constant":
        turns = rng.uniform(2, 5)
        # a drive at one speed: its ripple (+-0.5..2 %, a few times per second) is all that changes
        ripple, f = rng.uniform(0.005, 0.02), rng.uniform(2, 7)
        w = 2 * math.pi * turns / dur
        theta = (
            rng.uniform(0, 2 * math.pi)
            + w * t
            + w * ripple * (1 - np.cos(2 * math.pi * f * t)) / (2 * math.pi * f)
        )
    else:
        # speed w(t) = w0 + w1 cos(pi t / dur): from w0 + w1 to w0 - w1, through zero when |w0| < w1
        w1 = 2 * math.pi * rng.uniform(5, 8)
        w0 = w1 * rng.uniform(-0.3, 0.3)
        theta = (
            rng.uniform(0, 2 * math.pi) + w0 * t + w1 * dur / math.pi * np.sin(math.pi * t / dur)
        )
    return t, theta


def record(g, rng, kind, n=SAMPLES):
    """One recording as the instrument writes it: columns and their values."""
    t, theta = trajectory(rng, kind, n)
    nch = 4 if g["sensor"] == "hall4" else 2
    w = np.gradient(theta, t)
    # Each channel is sampled at its own time: the field it sees is the one at theta(t - d).
    chans = []
    for k in range(nch):
        d = g["delay_common_s"] + g["delay_diff_s"][k]
        th = np.interp(t - d, t, theta, left=None) if d else theta
        if d:  # extrapolate the first samples at the starting speed
            th = np.where(t - d < 0, theta[0] + w[0] * (t - d), th)
        chans.append(field(g, th)[k])
    x = np.array(chans)
    peak = np.max(np.abs(x))
    for k in range(nch):
        x[k] = g["sensitivity"][k] * x[k] + g["offset_T"][k]
    if g["cubic"]:
        x = x - g["cubic"] * x**3 / g["nominal_peak"] ** 2
    x = x + rng.normal(0, g["noise_T"] * g["noise_scale"], x.shape)
    if g["rc_s"]:
        # first-order low-pass, exact for a signal piecewise linear between samples
        dt = t[1] - t[0]
        a = math.exp(-dt / g["rc_s"])
        y = np.empty_like(x)
        y[:, 0] = x[:, 0]
        for i in range(1, x.shape[1]):
            y[:, i] = a * y[:, i - 1] + (1 - a) * x[:, i]
        x = y
    if g["clip_T"] is not None:
        x = np.clip(x, -g["clip_T"], g["clip_T"])
    unit = 1e3 if g["unit"] == "mT" else g["volts_per_T"]
    x = x * unit
    if g["adc_bits"]:
        step = 2 * g["adc_range"] / 2 ** g["adc_bits"]
        x = (
            np.clip(np.round(x / step), -(2 ** (g["adc_bits"] - 1)), 2 ** (g["adc_bits"] - 1) - 1)
            * step
        )
    enc = (
        np.round((theta + g["encoder_zero"]) / (2 * math.pi) * g["encoder_counts"])
        * 2
        * math.pi
        / g["encoder_counts"]
    )
    del peak
    names = ["c1", "c2", "c3", "c4"] if nch == 4 else ["sin", "cos"]
    return ["t", "theta_ref", *names], [t, enc, *list(x)]


def fmt_value(v, style):
    if style == "fixed6":
        return f"{v:.6f}"
    if style == "sig6":
        return f"{v:.6g}"
    if style == "sig5":
        return f"{v:.5g}"
    return repr(float(v))


def write_csv(path, cols, values, style, meta):
    with open(path, "w") as f:
        f.writelines(f"# {k}={v}\n" for k, v in meta.items())
        f.write(",".join(cols) + "\n")
        n = len(values[0])
        for i in range(n):
            row = [f"{values[0][i]:.7f}", f"{values[1][i]:.9f}"]
            row += [fmt_value(c[i], style) for c in values[2:]]
            f.write(",".join(row) + "\n")


# --- the cases -----------------------------------------------------------------------------------
# name: (sensors, accepted top-1 names, trajectory of real/holdout, what it does)
CASES = {
    "nominal": (["hall4", "axis2"], ["no_gap"], "ramp", "the nominal instrument"),
    "encoder_zero": (
        ["hall4", "axis2"],
        ["zero_offset"],
        "ramp",
        "the encoder's zero 20..120 deg off",
    ),
    "plate_offset": (
        ["hall4", "axis2"],
        ["offset"],
        "ramp",
        "one element's offset, 2..5 % of the peak",
    ),
    "plate_gain": (
        ["hall4", "axis2"],
        ["gain_mismatch"],
        "ramp",
        "one element's sensitivity 2..5 %",
    ),
    "placement": (
        ["hall4", "axis2"],
        ["phase_error"],
        "ramp",
        "one element 1..3 deg off its place",
    ),
    "ring_shift": (
        ["hall4"],
        ["gain_mismatch", "phase_error"],
        "ramp",
        "the plate ring displaced 0.3..0.6 mm in its plane",
    ),
    "air_gap": (["hall4", "axis2"], ["amplitude"], "ramp", "the magnet 0.3..0.6 mm further away"),
    # x - a x^3 on a unit sine is (1 - 3a/4) sin t - (a/4) sin 3t: a 3rd harmonic and a common
    # scale, both in the vocabulary (the angle the IP computes sees the scale through its regions)
    "nonlinearity": (
        ["hall4", "axis2"],
        ["harmonic", "amplitude"],
        "ramp",
        "front end x - a x^3, a = 3..6 %",
    ),
    "adc": (
        ["hall4", "axis2"],
        ["quantization"],
        "ramp",
        "an ADC of 7..9 bits over a range 1.05..1.4 x the peak (not a power of two)",
    ),
    "excess_noise": (["hall4", "axis2"], ["excess_noise"], "ramp", "3..5 x the designer's noise"),
    "rc_filter": (["hall4", "axis2"], ["common_delay"], "ramp", "one RC low-pass on every channel"),
    "mux": (["hall4", "axis2"], ["channel_skew"], "ramp", "one ADC converts the channels in turn"),
    "skew_constant": (
        ["hall4", "axis2"],
        ["zero_offset", "common_delay"],
        "constant",
        "every channel sampled 2..6 ms late at one constant speed",
    ),
    "skew_diff_constant": (
        ["axis2"],
        ["phase_error"],
        "constant",
        "the sin channel sampled 1..3 ms after the cos one at one constant speed",
    ),
    # The ring sees the magnet's centre move on a circle: the field's linear part adds the same
    # constant to every plate (no angle), its cubic part a constant angle (zero_offset) and a 3rd
    # spatial harmonic seen alike from every plate (a 4th-order angle error: harmonic), and the
    # plates' mean distance grows with e^2: the amplitude, the larger here (e/R = 0.05..0.2).
    "runout": (
        ["hall4"],
        ["amplitude", "zero_offset", "harmonic"],
        "constant",
        "the magnet 0.1..0.3 mm off the shaft axis, one constant speed",
    ),
    "saturation": (
        ["hall4", "axis2"],
        ["saturation"],
        "ramp",
        "the front end clips at 80..92 % of the peak",
    ),
}


def make_case(seed, index, scen, sensor):
    rng = np.random.default_rng([seed, index])
    g = nominal(rng, sensor)
    nch = 4 if sensor == "hall4" else 2
    g["nominal_peak"] = float(np.max(np.abs(field(g, np.linspace(0, 2 * np.pi, 256)))))
    sim = dict(g)
    p = {}
    one = int(rng.integers(nch))
    if scen == "encoder_zero":
        g["encoder_zero"] = rng.choice([-1, 1]) * math.radians(rng.uniform(20, 120))
        p["encoder_zero_deg"] = math.degrees(g["encoder_zero"])
    elif scen == "plate_offset":
        g["offset_T"] = [0.0] * 4
        g["offset_T"][one] = rng.choice([-1, 1]) * rng.uniform(0.02, 0.05) * g["nominal_peak"]
        p["offset_mT"] = g["offset_T"][one] * 1e3
    elif scen == "plate_gain":
        g["sensitivity"] = [1.0] * 4
        g["sensitivity"][one] = 1 + rng.choice([-1, 1]) * rng.uniform(0.02, 0.05)
        p["sensitivity"] = g["sensitivity"][one]
    elif scen == "placement":
        g["plate_angle"] = [0.0] * 4
        g["plate_angle"][one] = rng.choice([-1, 1]) * math.radians(rng.uniform(1, 3))
        p["angle_deg"] = math.degrees(g["plate_angle"][one])
    elif scen == "ring_shift":
        d = rng.uniform(0.3, 0.6) * MM
        a = rng.uniform(0, 2 * math.pi)
        g["ring_dx"], g["ring_dy"] = d * math.cos(a), d * math.sin(a)
        p["shift_mm"], p["dir_deg"] = d / MM, math.degrees(a)
    elif scen == "air_gap":
        g["gap"] += rng.uniform(0.3, 0.6) * MM
        p["gap_mm"] = g["gap"] / MM
    elif scen == "nonlinearity":
        g["cubic"] = rng.uniform(0.03, 0.06)
        p["cubic"] = g["cubic"]
    elif scen == "adc":
        g["adc_bits"] = int(rng.integers(7, 10))
        unit = 1e3 if g["unit"] == "mT" else g["volts_per_T"]
        g["adc_range"] = round(g["nominal_peak"] * unit * rng.uniform(1.05, 1.4), 3)
        p["bits"], p["range"] = g["adc_bits"], g["adc_range"]
    elif scen == "excess_noise":
        g["noise_scale"] = rng.uniform(3, 5)
        p["noise_scale"] = g["noise_scale"]
    elif scen == "rc_filter":
        g["rc_s"] = rng.uniform(0.5, 2.0) * 1e-3
        p["rc_ms"] = g["rc_s"] * 1e3
    elif scen == "mux":
        slot = rng.uniform(0.5, 1.5) * 1e-3
        order = rng.permutation(nch)
        g["delay_diff_s"] = [0.0] * 4
        for k in range(nch):
            g["delay_diff_s"][k] = -slot * order[k]  # a later slot: sampled after the time stamp
        p["slot_ms"] = slot * 1e3
    elif scen == "skew_constant":
        g["delay_common_s"] = rng.uniform(2, 6) * 1e-3
        p["delay_ms"] = g["delay_common_s"] * 1e3
    elif scen == "skew_diff_constant":
        g["delay_diff_s"] = [-rng.uniform(1, 3) * 1e-3, 0.0, 0.0, 0.0]
        p["skew_ms"] = -g["delay_diff_s"][0] * 1e3
    elif scen == "runout":
        g["ecc"] = rng.uniform(0.1, 0.3) * MM
        g["ecc_phase"] = rng.uniform(0, 2 * math.pi)
        p["ecc_mm"] = g["ecc"] / MM
    elif scen == "saturation":
        g["clip_T"] = rng.uniform(0.80, 0.92) * g["nominal_peak"]
        p["clip_share"] = g["clip_T"] / g["nominal_peak"]
    return sim, g, p, rng


def generate(args):
    os.makedirs(args.dir, exist_ok=True)
    only = set(args.only.split(",")) if args.only else None
    index = []
    i = 0
    for scen, (sensors, truth, kind, why) in CASES.items():
        for sensor in sensors:
            for _k in range(args.per_case):
                i += 1
                label = f"{scen}/{sensor}"
                if only and scen not in only and label not in only:
                    continue
                sim, real, p, rng = make_case(args.seed, i, scen, sensor)
                name = f"{i:03d}_{scen}_{sensor}"
                meta = {"p": 1, "instrument": "magpylib", "unit": real["unit"]}
                files = {}
                for role, g, traj in (
                    ("sim", sim, "constant"),
                    ("real", real, kind),
                    ("holdout", real, kind),
                ):
                    cols, vals = record(g, rng, traj)
                    path = os.path.join(args.dir, f"{name}_{role}.csv")
                    write_csv(path, cols, vals, "repr" if role == "sim" else real["print"], meta)
                    files[role] = os.path.basename(path)
                index.append(
                    {
                        "name": name,
                        "label": label,
                        "truth": truth,
                        "why": why,
                        "params": p,
                        "unit": real["unit"],
                        "print": real["print"],
                        **files,
                    }
                )
    with open(os.path.join(args.dir, "cases.json"), "w") as f:
        json.dump(index, f, indent=1)
    print(f"{len(index)} cases in {args.dir}")


def diagnose_one(anglecore, d, c):
    """`anglecore diagnose --json` of one case of a bench folder (its sim, real and holdout
    files); {"error": ...} when the command fails."""
    cmd = [anglecore, "diagnose", "--json", "-"]
    for role in ("sim", "real", "holdout"):
        cmd += [f"--{role}", os.path.join(d, c[role])]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        return {"error": r.stderr.strip()}
    return json.loads(r.stdout)


def diagnose_all(anglecore, d, jobs):
    """The cases of a bench folder (its cases.json) and their diagnoses, `jobs` at a time (the
    scoring of this bench and of scripts/mount_gaps.py)."""
    with open(os.path.join(d, "cases.json")) as f:
        cases = json.load(f)
    with concurrent.futures.ThreadPoolExecutor(jobs) as ex:
        return cases, list(ex.map(lambda c: diagnose_one(anglecore, d, c), cases))


def score(args):
    cases, results = diagnose_all(args.anglecore, args.dir, args.jobs)
    rows = {}
    shrinks = []
    correct = 0
    wrong = []
    for c, j in zip(cases, results):
        c["truth"] = CASES[c["label"].split("/")[0]][1]  # this script's physics, not a stale copy
        if "error" in j:
            top1, named, shrink = "error", [], None
        else:
            named = j.get("named", [])
            top1 = named[0] if j["verdict"] == "explained" and named else j["verdict"]
            hb, ha = j["holdout"]["before_deg"], j["holdout"]["after_deg"]
            shrink = 1 - ha / hb if hb > 0 else 0.0
        # top-1 among the effects the physics gives, and nothing named beside them (e.g. a
        # spurious offset beside a run-out's amplitude and zero offset)
        ok = top1 in c["truth"] and all(e in c["truth"] for e in named)
        correct += ok
        if c["truth"] != ["no_gap"] and shrink is not None:
            shrinks.append(shrink)
        r = rows.setdefault(c["label"], [0, 0, []])
        r[0] += 1
        r[1] += ok
        r[2].append(shrink if shrink is not None else float("nan"))
        if not ok:
            wrong.append(
                f"{c['name']}: expected {'/'.join(c['truth'])}, got {'+'.join(named) or top1}"
                + (f" ({j['error']})" if "error" in j else "")
            )
        if args.verbose:
            print(
                f"{c['name']:32s} {c['unit']:2s} {c['print']:6s} -> {'+'.join(named) or top1:40s} "
                f"{'ok' if ok else 'WRONG'} shrink "
                f"{shrink if shrink is not None else float('nan'):.3f}"
            )
    print(f"{'case':24s} {'n':>3s} {'top-1':>6s} {'median shrink':>14s}")
    for label, (n, ok, sh) in rows.items():
        print(f"{label:24s} {n:3d} {100 * ok / n:5.0f}% {100 * float(np.nanmedian(sh)):13.1f}%")
    top1 = correct / len(cases)
    med = float(np.median(shrinks)) if shrinks else 0.0
    print(f"top-1 correct: {100 * top1:.1f} % of {len(cases)} recordings")
    print(f"median holdout shrink over the effect cases: {100 * med:.1f} %")
    for w in wrong:
        print("  wrong:", w)
    return 0 if top1 >= args.min_top1 and med >= args.min_shrink else 1


def main():
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    sub = ap.add_subparsers(dest="cmd", required=True)
    g = sub.add_parser("generate")
    g.add_argument("dir")
    g.add_argument("--per-case", type=int, default=3)
    g.add_argument("--seed", type=int, default=1)
    g.add_argument("--only", default="")
    s = sub.add_parser("score")
    s.add_argument("dir")
    s.add_argument("--anglecore", required=True)
    s.add_argument("--jobs", type=int, default=2)
    s.add_argument("--min-top1", type=float, default=0.95)
    s.add_argument("--min-shrink", type=float, default=0.8)
    s.add_argument("--verbose", action="store_true")
    c = sub.add_parser("check")
    c.add_argument("--anglecore", required=True)
    c.add_argument(
        "--only", default="nominal,encoder_zero,plate_offset,adc,skew_constant,skew_diff_constant"
    )
    c.add_argument("--seed", type=int, default=1)
    c.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    if a.cmd == "generate":
        generate(a)
        return 0
    if a.cmd == "check":
        import tempfile

        with tempfile.TemporaryDirectory() as d:
            a.dir, a.per_case = d, 1
            generate(a)
            a.min_top1, a.min_shrink, a.verbose = 1.0, 0.8, True
            return score(a)
    return score(a)


if __name__ == "__main__":
    sys.exit(main())
