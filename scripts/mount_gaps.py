#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Two mounting faults on a rig of its own: does the gap diagnosis name them?

A third generator, independent of the project's physics rig (model/lab/physics) and of
scripts/instrument_bench.py: here magpylib moves the magnet itself. A diametrically magnetized
cylinder sits on the shaft end, its centre a distance e off the rotation axis; each sample's shaft
angle becomes a step of the magnet's motion path (a rotation about the z axis through the origin,
magpylib's rotate_from_angax with an anchor), and the sensing elements are magpylib Sensors that
never move. Remanence follows the temperature, Br(T) = Br(25 C)·(1 + k·(T - 25 C)) with k of
NdFeB (about -0.12 %/K): the field is linear in the polarization, so each sample's field is the
one at Br(25 C) times that factor.

Scenarios (each with its truth: what the diagnosis may name; docs/diagnosis.md, "A third
generator", says why):

- nominal: the designer's rig, fresh noise, trajectory and temperature: no_gap;
- magnet_offaxis_hot (hall4, axis2): the magnet's centre 0.5-0.8 mm off the axis, turning with the
  shaft, while the temperature swings by 45-55 C. The sensors see a field off the nominal one by a
  fixed angle (zero_offset) and weaker (amplitude, which atan2 hardly sees); under a plate ring the
  offset also bends the field map into a 3rd spatial harmonic seen alike from every plate (a
  4th-order angle error: harmonic); the remanence's fall when hot scales every channel alike
  (drift with equal gains, if anything). Named: any of those, with zero_offset or harmonic;
- ring_shift (hall4): the ring of four Hall plates 0.25-0.35 mm off the shaft axis. Each plate sees
  the field at another radius and angle; opposite plates move oppositely, so the pairs c1 - c3,
  c2 - c4 change only at second order, in amplitude and phase (gain_mismatch, phase_error; their
  common part a constant angle, zero_offset).

    mount_gaps.py generate DIR [--per-case N] [--seed S] [--only NAME,...] [--pick I,...]
    mount_gaps.py score DIR --anglecore BUILD/anglecore [--jobs 2] [--verbose]
    mount_gaps.py check --anglecore BUILD/anglecore [--only ...] [--pick ...] [--per-case N]

`score` runs `anglecore diagnose --sim --real --holdout --json -` on every case and counts a case
right when its verdict is `explained`, every named effect is one its truth lists and, when the
truth has a `first`, one of them is among it (nominal: when the verdict is `no_gap`); it prints
each case's verdict, named effects, share of gap² explained and holdout shrink. Exit 1 when a case
is wrong (`check`: generate into a temporary folder, then score).
"""

import argparse
import json
import math
import os
import sys
import tempfile

import magpylib as magpy
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from instrument_bench import diagnose_all  # the same `anglecore diagnose` runs as that bench

MM = 1e-3
SAMPLES = 6000
TEMPCO_BR = -0.0012  # NdFeB remanence, 1/K


def draw_rig(rng, sensor):
    """The designer's rig: magnet, air gap, sensing elements and the instrument's noise."""
    return {
        "sensor": sensor,
        "d": rng.uniform(5.0, 8.0) * MM,  # magnet diameter
        "h": rng.uniform(2.0, 3.5) * MM,  # magnet height
        "br": rng.uniform(1.15, 1.35),  # T at 25 C
        "gap": rng.uniform(1.2, 2.2) * MM,  # sensing plane to the magnet's face
        "ring": rng.uniform(1.2, 2.0) * MM,  # Hall plate radius
        "e": 0.0,  # magnet centre off the rotation axis
        "e_dir": 0.0,  # its direction in the shaft frame, from the magnetization
        "ring_x": 0.0,  # the sensor (ring or pair) off the rotation axis
        "ring_y": 0.0,
        "noise": rng.uniform(0.0008, 0.0015),  # of the nominal peak
    }


def sensor_positions(g):
    if g["sensor"] == "hall4":
        # plate k at 90 - 90 k degrees: c1 at +y, c2 at +x, c3 at -y, c4 at -x
        return [
            (
                g["ring_x"] + g["ring"] * math.cos(math.pi / 2 * (1 - k)),
                g["ring_y"] + g["ring"] * math.sin(math.pi / 2 * (1 - k)),
                0.0,
            )
            for k in range(4)
        ]
    return [(g["ring_x"], g["ring_y"], 0.0)]


def fields(g, theta, temp):
    """Channels (T) at shaft angles theta and temperatures temp (arrays of one length)."""
    zc = g["gap"] + g["h"] / 2
    # At shaft angle 0 the magnetization points along +x: then c1 - c3 follows sin θ, c2 - c4 cos θ.
    mag = magpy.magnet.Cylinder(
        polarization=(g["br"], 0.0, 0.0),
        dimension=(g["d"], g["h"]),
        position=(
            g["e"] * math.cos(g["e_dir"]),
            g["e"] * math.sin(g["e_dir"]),
            zc,
        ),
    )
    mag.rotate_from_angax(np.degrees(theta), "z", anchor=(0, 0, 0), start=0)
    sens = [magpy.Sensor(position=p) for p in sensor_positions(g)]
    B = np.asarray(magpy.getB(mag, sens, squeeze=False))[0, :, :, 0, :]  # (path, sensors, 3)
    B = B[1:] if B.shape[0] == len(theta) + 1 else B  # the path's first step is the start pose
    scale = 1.0 + TEMPCO_BR * (np.asarray(temp) - 25.0)
    # hall4: every plate measures the field along -z (away from the magnet), so c1 - c3 follows
    # +sin θ; axis2: on the axis the in-plane field opposes the magnetization (cos θ, sin θ)
    hall = g["sensor"] == "hall4"
    ch = -B[:, :, 2].T if hall else np.stack([-B[:, 0, 1], -B[:, 0, 0]])
    return ch * scale


def trajectory(rng, kind, n):
    t = np.arange(n) / n * 2.0  # 2 s
    if kind == "constant":
        w = 2 * math.pi * rng.uniform(1.0, 2.5)
        theta = rng.uniform(0, 2 * math.pi) + w * t
    else:
        # a speed ramp from +w0 to -w1 (or the reverse): the direction changes once
        w0, w1 = 2 * math.pi * rng.uniform(3, 10), 2 * math.pi * rng.uniform(3, 10)
        s = rng.choice([-1, 1])
        w = s * (w0 - (w0 + w1) * t / t[-1])
        theta = rng.uniform(0, 2 * math.pi) + np.concatenate([[0], np.cumsum(w[:-1])]) * (
            t[1] - t[0]
        )
    return t, theta


def temperature(rng, kind, t, swing):
    if kind == "constant":
        return np.full_like(t, 25.0)
    start = rng.uniform(15, 30)
    up = rng.choice([-1, 1])
    lo, hi = start, start + swing
    return lo + (hi - lo) * (t / t[-1] if up > 0 else 1 - t / t[-1])


def record(g, rng, kind, swing, n=SAMPLES):
    t, theta = trajectory(rng, kind, n)
    temp = temperature(rng, kind, t, swing)
    x = fields(g, theta, temp)
    x = x / g["peak"] + rng.normal(0, g["noise"], x.shape)
    names = ["c1", "c2", "c3", "c4"] if g["sensor"] == "hall4" else ["sin", "cos"]
    cols = ["t", "theta_ref", *names, "temp"]
    return cols, [t, np.mod(theta, 2 * math.pi), *list(x), temp]


# name: (sensors, accepted named effects, the one that must come first (any of them), what it is)
CASES = {
    "nominal": (["hall4", "axis2"], ["no_gap"], [], "the designer's rig"),
    "magnet_offaxis_hot": (
        ["hall4", "axis2"],
        ["zero_offset", "harmonic", "amplitude", "drift"],
        ["zero_offset", "harmonic"],
        "the magnet 0.5-0.8 mm off the axis, turning with the shaft, 45-55 C swing",
    ),
    "ring_shift": (
        ["hall4"],
        ["gain_mismatch", "phase_error", "zero_offset"],
        [],
        "the plate ring 0.25-0.35 mm off the shaft axis",
    ),
}


def clean_angle_error_deg(nominal_rig, rig):
    """RMS of the angle the perturbed rig's pairs give, less the nominal rig's, without noise."""
    th = np.linspace(0, 2 * math.pi, 720, endpoint=False)
    hot = np.full_like(th, 25.0)

    def angle(x):
        return np.arctan2(x[0] - x[2], x[1] - x[3]) if len(x) == 4 else np.arctan2(x[0], x[1])

    e = np.angle(np.exp(1j * (angle(fields(rig, th, hot)) - angle(fields(nominal_rig, th, hot)))))
    return float(np.degrees(np.sqrt(np.mean(e**2))))


def make_case(seed, index, scen, sensor):
    rng = np.random.default_rng([seed, index, 17])
    g = draw_rig(rng, sensor)
    th = np.linspace(0, 2 * math.pi, 256, endpoint=False)
    g["peak"] = float(np.max(np.abs(fields(g, th, np.full_like(th, 25.0)))))
    sim = dict(g)
    p, swing = {}, 0.0
    if scen == "nominal":
        swing = rng.uniform(30, 60)
    elif scen == "magnet_offaxis_hot":
        g["e"] = rng.uniform(0.5, 0.8) * MM
        g["e_dir"] = rng.uniform(0, 2 * math.pi)
        swing = rng.uniform(45, 55)
        p = {"e_mm": g["e"] / MM, "e_dir_deg": math.degrees(g["e_dir"]), "swing_C": swing}
    elif scen == "ring_shift":
        swing = rng.uniform(30, 60)  # the temperature wanders as in the nominal case
        # A shift moves the pairs' angle only at second order, and along some directions of some
        # rigs hardly at all: drawn again until the clean angle error (no noise) is 0.05 deg RMS,
        # a gap the diagnosis can see (the noise's angle is 0.03-0.06 deg RMS).
        for _ in range(50):
            d, a = rng.uniform(0.25, 0.35) * MM, rng.uniform(0, 2 * math.pi)
            g["ring_x"], g["ring_y"] = d * math.cos(a), d * math.sin(a)
            if clean_angle_error_deg(sim, g) >= 0.05:
                break
        p = {"shift_mm": d / MM, "dir_deg": math.degrees(a)}
    return sim, g, p, swing, rng


def write_csv(path, cols, vals):
    with open(path, "w") as f:
        f.write("# p=1\n")
        f.write(",".join(cols) + "\n")
        f.writelines(",".join(f"{v:.9g}" for v in row) + "\n" for row in zip(*vals))


def generate(args):
    os.makedirs(args.dir, exist_ok=True)
    only = set(args.only.split(",")) if args.only else None
    pick = {int(k) for k in args.pick.split(",")} if args.pick else None
    index, i = [], 0
    for scen, (sensors, _truth, _first, why) in CASES.items():
        for sensor in sensors:
            for _ in range(args.per_case):
                i += 1
                label = f"{scen}/{sensor}"
                if only and scen not in only and label not in only:
                    continue
                if pick and i not in pick:
                    continue
                sim, real, p, swing, rng = make_case(args.seed, i, scen, sensor)
                name = f"{i:03d}_{scen}_{sensor}"
                files = {}
                for role, g, kind in (
                    ("sim", sim, "constant"),
                    ("real", real, "ramp"),
                    ("holdout", real, "ramp"),
                ):
                    cols, vals = record(g, rng, kind, swing)
                    if role == "sim":
                        cols, vals = cols[:-1], vals[:-1]  # the designer's model: no temperature
                    path = os.path.join(args.dir, f"{name}_{role}.csv")
                    write_csv(path, cols, vals)
                    files[role] = os.path.basename(path)
                index.append({"name": name, "label": label, "why": why, "params": p, **files})
    with open(os.path.join(args.dir, "cases.json"), "w") as f:
        json.dump(index, f, indent=1)
    print(f"{len(index)} cases in {args.dir}")


def score(args):
    cases, results = diagnose_all(args.anglecore, args.dir, args.jobs)
    wrong = 0
    for c, j in zip(cases, results):
        _sensors, truth, first, _why = CASES[c["label"].split("/")[0]]
        if "error" in j:
            ok, text = False, "error: " + j["error"]
        else:
            named = j.get("named", [])
            verdict = j["verdict"]
            if truth == ["no_gap"]:
                ok = verdict == "no_gap"
            else:
                ok = verdict == "explained" and named and all(e in truth for e in named)
                ok = ok and (not first or any(e in first for e in named))
            g, h = j["gap"], j["holdout"]
            expl = 1 - g["after_deg"] ** 2 / g["before_deg"] ** 2 if g["before_deg"] > 0 else 0
            shrink = 1 - h["after_deg"] / h["before_deg"] if h["before_deg"] > 0 else 0
            noise = j.get("gap", {}).get("noise_deg", float("nan"))
            text = (
                f"{verdict:11s} {'+'.join(named) or '-':44s} gap {g['before_deg']:.4f} deg"
                f" (noise {noise:.4f}) explained {100 * expl:5.1f} %"
                f" holdout shrink {100 * shrink:5.1f} %"
            )
            if args.verbose and verdict != "explained":
                top = j.get("ranking", [])[:3]
                text += " | " + ", ".join(f"{r['effect']} {100 * r['explained']:.0f}%" for r in top)
        wrong += not ok
        print(f"{c['name']:32s} {'ok   ' if ok else 'WRONG'} {text}")
    print(f"{len(cases) - wrong} of {len(cases)} right")
    return 0 if wrong == 0 else 1


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
    g.add_argument("--pick", default="", help="case numbers to keep (1-based, as in the names)")
    s = sub.add_parser("score")
    s.add_argument("dir")
    s.add_argument("--anglecore", required=True)
    s.add_argument("--jobs", type=int, default=2)
    s.add_argument("--verbose", action="store_true")
    c = sub.add_parser("check")
    c.add_argument("--anglecore", required=True)
    c.add_argument("--only", default="")
    c.add_argument("--pick", default="")
    c.add_argument("--per-case", type=int, default=1)
    c.add_argument("--seed", type=int, default=1)
    c.add_argument("--jobs", type=int, default=2)
    c.add_argument("--verbose", action="store_true")
    a = ap.parse_args()
    if a.cmd == "generate":
        generate(a)
        return 0
    if a.cmd == "check":
        with tempfile.TemporaryDirectory() as d:
            a.dir = d
            generate(a)
            return score(a)
    return score(a)


if __name__ == "__main__":
    sys.exit(main())
