# SPDX-License-Identifier: MIT
"""The package against the `anglecore` command on the same inputs: recordings, register words,
bit-accurate angles and statistics identical; input errors as ValueError/TypeError."""

import csv
import json
import math
import subprocess
import sys

import anglecore as ac
import numpy as np
import pytest
from conftest import ROOT


def test_simulate_equals_cli_recording(paper):
    for name, seed in (("cal", 11), ("val", 12)):
        ours = ac.simulate("paper", samples=3600, seed=seed)
        theirs = ac.read_recording(paper / f"{name}.csv")
        assert set(ours.columns) == set(theirs.columns)
        for k in ours.columns:  # the CSV holds %.17g: the same doubles
            np.testing.assert_array_equal(ours.columns[k], theirs.columns[k], err_msg=k)
        assert ours.meta == theirs.meta


def test_recording_roundtrip_and_arrays(tmp_path):
    theta = np.linspace(0, 2 * np.pi, 100, endpoint=False)
    s = np.sin(theta)
    rec = ac.Recording(theta_ref=theta, sin=s, cos=np.cos(theta), meta={"p": 2})
    assert rec.sin is s and rec.theta_ref is theta  # the caller's arrays, not copies
    assert len(rec) == 100 and rec.periodicity == 2
    assert ac.Recording(sin=[0.0, 1.0], cos=[1.0, 0.0]).sin.dtype == np.float64
    rec.write(tmp_path / "r.csv")
    back = ac.read_recording(tmp_path / "r.csv")
    assert back.channels == 2
    for k in ("theta_ref", "sin", "cos"):
        np.testing.assert_array_equal(back.columns[k], rec.columns[k])
        assert not back.columns[k].flags["OWNDATA"]  # the C++ vector's memory, not a copy


OPTION_SETS = [
    ({}, []),
    ({"degree": 5, "regions": 8, "xcenter": True}, ["--degree", 5, "--regions", 8, "--xcenter"]),
    (
        {"correction": "poly2d", "degree": 2, "fourier": 3, "zero_word": True},
        ["--correction", "poly2d", "--degree", 2, "--fourier", 3, "--zero-word"],
    ),
    (
        {"angle_w": 18, "zero_offset": 0, "coef_frac": 14, "iterations": 14, "in_w": 18},
        ["--angle-w", 18, "--zero-offset", 0, "--coef-frac", 14, "--iterations", 14, "--in-w", 18],
    ),
    (
        {
            "correction": "none",
            "fourier": 4,
            "fourier_iterations": 10,
            "fourier_guard": 3,
            "in_scale": 2048.0,
            "periodicity": 1,
        },
        [
            "--correction",
            "none",
            "--fourier",
            4,
            "--fourier-iterations",
            10,
            "--fourier-guard",
            3,
            "--in-scale",
            2048,
            "--periodicity",
            1,
        ],
    ),
    # The self-calibration: theta_ref is in the file but not used by the fit.
    (
        {"reference": "none", "selfcal_harmonics": 8},
        ["--reference", "none", "--selfcal-harmonics", 8],
    ),
]


@pytest.mark.parametrize("opts,flags", OPTION_SETS, ids=[str(o) for o, _ in OPTION_SETS])
def test_calibrate_and_estimate_equal_cli(paper, cli, tmp_path, opts, flags):
    hexfile, angles = tmp_path / "regs.hex", tmp_path / "angles.csv"
    cal_json = cli.json("calibrate", "--in", paper / "cal.csv", "--out", hexfile, *flags)
    img = ac.calibrate(ac.read_recording(paper / "cal.csv"), **opts)
    theirs = ac.read_image(hexfile)
    np.testing.assert_array_equal(img.words, theirs.words)
    assert img.words.dtype == np.uint64 and len(img.words) == cal_json["words"]
    assert img.report == cal_json
    # The header equals the file's but for the command line that made it.
    h1, h2 = dict(img.header), dict(theirs.header)
    assert h1.pop("command").startswith("python anglecore.calibrate(")
    assert h2.pop("command").startswith("anglecore calibrate")
    assert h1 == h2

    val = ac.read_recording(paper / "val.csv")
    for engine in ("fixed", "float"):
        j = cli.json(
            "estimate",
            "--regs",
            hexfile,
            "--in",
            paper / "val.csv",
            "--engine",
            engine,
            "--out",
            angles,
        )
        res = ac.estimate(img, val, engine=engine)
        # every statistic, the zero offset, the flagged count, the observer's track and
        # velocity_error_rpm
        assert res.report == j
        assert set(j) >= {"track", "velocity_error_rpm"}
        with open(angles) as f:
            rows = list(csv.DictReader(f))
        # The CLI writes %.9f: our doubles print the same text, sample for sample.
        assert [f"{a:.9f}" for a in res.angle] == [r["angle_rad"] for r in rows]
        assert [f"{a:.9f}" for a in res.uncorrected] == [r["uncorrected_rad"] for r in rows]
        assert res.flags.tolist() == [int(r["flags"]) for r in rows]
        assert res.region.tolist() == [int(r["region"]) for r in rows]
        assert_drive_columns(res, rows)


def assert_drive_columns(res, rows):
    """The observer's outputs equal the command's --out columns, as the command prints them."""
    assert res.turns.tolist() == [int(r["turns"]) for r in rows]
    assert [f"{a:.9f}" for a in res.angle_comp] == [r["angle_comp_rad"] for r in rows]
    assert res.lot.tolist() == [int(r["lot"]) for r in rows]
    if "velocity_rpm" in rows[0]:
        assert [f"{v:.6f}" for v in res.velocity] == [r["velocity_rpm"] for r in rows]
    else:
        assert res.velocity is None


def ripple_lag_rpm(code: int, fs: float, ripple_rpm: float, ripple_hz: float) -> float:
    """The amplitude of the observer's velocity error on a sinusoidal speed ripple, from the
    continuous type-II loop it approximates: the velocity is the integrator's state, whose transfer
    from the true velocity is wn^2 / (s^2 + 2 zeta wn s + wn^2), zeta = 1/sqrt(2), wn = 2^-(k+1/2)
    rad/sample (model/ip/stages/tracker.hpp); the error is ripple x |1 - that|."""
    wn, s = 2.0 ** -(code + 0.5), 2j * np.pi * ripple_hz / fs
    return ripple_rpm * abs(1 - wn**2 / (s**2 + np.sqrt(2) * wn * s + wn**2))


@pytest.mark.parametrize(
    "kw,flags",
    [
        ({}, []),
        (
            {"track_bandwidth": 100, "track_lead": 2.5, "track_lot": 200},
            ["--track-bandwidth", 100, "--track-lead", 2.5, "--track-lot", 200],
        ),
        (
            {"track_bandwidth": 3000, "track_lead": 10},
            ["--track-bandwidth", 3000, "--track-lead", 10],
        ),
    ],
)
def test_drive_outputs_equal_cli(cli, tmp_path, kw, flags):
    """velocity, turns, angle_comp and lot with the observer's settings equal `estimate --out`, on
    a speed profile (p = 2: electrical turns, mechanical rpm), and follow the profile's speed."""
    rec = tmp_path / "rip.csv"
    cli(
        "simulate",
        "--scenario",
        "ideal",
        "--samples",
        2048,
        "--seed",
        1,
        "--out",
        tmp_path / "c.csv",
    )
    cli("calibrate", "--in", tmp_path / "c.csv", "--out", tmp_path / "r.hex", "--zero-offset", 0)
    cli(
        "simulate",
        "--scenario",
        "ideal",
        "--profile",
        "ripple",
        "--speed-rpm",
        3000,
        "--ripple",
        0.02,
        "--ripple-hz",
        40,
        "--sample-rate",
        100000,
        "--samples",
        20000,
        "--seed",
        2,
        "--out",
        rec,
    )
    angles = tmp_path / "a.csv"
    j = cli.json("estimate", "--regs", tmp_path / "r.hex", "--in", rec, "--out", angles, *flags)
    with open(angles) as f:
        rows = list(csv.DictReader(f))
    img = ac.read_image(tmp_path / "r.hex")
    r = ac.read_recording(rec)
    for uncorrected in (True, False):  # the per-sample and the batch path
        res = ac.estimate(img, r, uncorrected=uncorrected, **kw)
        if uncorrected:
            assert res.report == j
        assert res.track == j["track"] and res.velocity_error_rpm == j["velocity_error_rpm"]
        assert_drive_columns(res, rows)
    # An independent expectation: the profile's closed-form speed after the loop has settled.
    t = r.t[5000:]
    want = 3000 * (1 + 0.02 * np.sin(2 * np.pi * 40 * t))
    lag = ripple_lag_rpm(res.track["code"], 1e5, 60, 40)  # 19.5, 70.7 and 2.4 rpm here
    # The discrete loop departs from the continuous one by O(wn T) (a few % at these codes); the
    # estimator adds its own share, at most velocity_error_rpm's max_abs (measured: 19.45, 70.62
    # and 4.28 rpm, the last with 3.0 rpm of the estimator's at 2.9 kHz).
    worst = np.max(np.abs(res.velocity[5000:] - want))
    assert abs(worst - lag) <= 0.05 * lag + res.velocity_error_rpm["max_abs"] + 0.2
    assert res.track["lot_threshold"] == kw.get("track_lot", 4096)
    assert res.track["lead_samples"] == kw.get("track_lead", 0)
    assert not ac.estimate(img, r, track=False).report.keys() & {"track", "velocity_error_rpm"}


def test_drive_settings_refused_as_the_cli(cli, tmp_path):
    img = ac.calibrate(ac.simulate("ideal", samples=1024, seed=1), zero_offset=0)
    rec = ac.simulate("ideal", samples=256, seed=2)
    with pytest.raises(ValueError, match=r"--track-lead must be 0\.\.270\.9375 samples \(is 300\)"):
        ac.estimate(img, rec, track_lead=300)
    with pytest.raises(ValueError, match=r"--track-lot must be 0\.\.32767 angle LSBs"):
        ac.estimate(img, rec, track_lot=40000)
    with pytest.raises(ValueError, match="is outside"):
        ac.estimate(img, rec, track_bandwidth=1e9)
    no_t = ac.Recording(**{k: rec.columns[k] for k in ("theta_ref", "c1", "c2", "c3", "c4")})
    with pytest.raises(ValueError, match="--track-bandwidth needs the recording's t column"):
        ac.estimate(img, no_t, track_bandwidth=100)
    assert ac.estimate(img, no_t).velocity is None


def test_fixed_batch_equals_per_sample_model(paper):
    """The zero-copy batch path's angles are bit for bit those of the per-sample model (the one the
    CLI runs), compared as doubles."""
    img = ac.calibrate(ac.read_recording(paper / "cal.csv"), regions=8, degree=4)
    val = ac.read_recording(paper / "val.csv")
    fast = ac.estimate(img, val, engine="fixed", uncorrected=False)
    slow = ac._core.estimate_series(img._img, val._core(), "fixed")
    np.testing.assert_array_equal(fast.angle, slow[0])
    np.testing.assert_array_equal(fast.region, slow[2])
    np.testing.assert_array_equal(fast.flags, slow[3])
    np.testing.assert_array_equal(ac.estimate(img, val, engine="fixed").magnitude, slow[4])
    assert fast.uncorrected is None and "uncorrected_error_deg" not in fast.report


def test_magnitude_and_board_mag_agc(paper):
    """Estimate.magnitude (the CORDIC's, the RTL's mag_o) on the calibrated recording is near its
    nominal, the CORDIC gain times 2^S_F; board_mag_agc is the shift and 128 + 32 (S_F + 0.625 -
    log2 m) within the piecewise-linear logarithm's bound; the recording at half amplitude about
    the calibrated offsets halves MAG and adds 32 to AGC (the AS5047P's sense)."""
    img = ac.calibrate(ac.read_recording(paper / "cal.csv"))
    val = ac.read_recording(paper / "val.csv")
    res = ac.estimate(img, val, engine="fixed")
    assert ac.estimate(img, val, engine="fixed", uncorrected=False).magnitude is None
    m = res.magnitude
    assert m.dtype == np.int64 and len(m) == len(val)
    s_w, s_f, k = (int(img.header[f]) for f in ("s_w", "s_f", "iterations"))
    gain = math.prod(math.sqrt(1.0 + 2.0 ** (-2 * i)) for i in range(k))
    nominal = gain * 2.0**s_f
    assert abs(np.median(m) / nominal - 1) < 0.05
    mag, agc = ac.board_mag_agc(img, m)
    np.testing.assert_array_equal(mag, m >> (s_w - 13))
    exact = 128 + 32 * (s_f + 0.625 - np.log2(m))
    assert np.all(agc >= np.floor(exact)) and np.all(agc <= exact + 32 * 0.0861 + 1)
    assert abs(int(np.median(agc)) - 128) <= 2
    # Half the field: the channels halved (the paper scenario's offsets are zero, as calibrated),
    # on an image without correction (its polynomial adds the same terms at any amplitude, so the
    # corrected length would not halve exactly).
    assert max(abs(o) for o in img.report["offset"]) < 1e-6
    lin = ac.calibrate(ac.read_recording(paper / "cal.csv"), correction="none")
    full = ac.estimate(lin, val, engine="fixed", track=False)
    cols = {n: val.columns[n] / 2 for n in val.channel_names}
    half = ac.estimate(lin, ac.Recording(**cols), engine="fixed", track=False)
    fmag, fagc = ac.board_mag_agc(lin, full.magnitude)
    hmag, hagc = ac.board_mag_agc(lin, half.magnitude)
    assert np.all(np.abs(half.magnitude - full.magnitude / 2) <= 0.002 * full.magnitude)
    assert np.all(np.abs(hmag.astype(int) - fmag / 2) <= 0.002 * fmag + 1)
    assert np.median(hagc.astype(int) - fagc) == 32 and np.all(
        np.abs(hagc.astype(int) - fagc - 32) <= 1
    )
    assert ac.board_mag_agc(img, [0])[1][0] == 255


def test_harmonics_equals_cli(cli, tmp_path):
    spec = json.loads((ROOT / "tests" / "data" / "kuntz_eq33.json").read_text())
    spec["terms"].append({"n": 3, "A": 0.01, "theta": 0.2, "B": 0.008, "psi": -0.4})
    (tmp_path / "spec.json").write_text(json.dumps(spec))
    ours = ac.harmonics(spec)
    assert ours == cli.json("harmonics", "--spec", tmp_path / "spec.json")
    assert ac.harmonics(tmp_path / "spec.json") == ours
    assert "attribution" not in ours


def test_harmonics_attribution_equals_cli(cli, tmp_path):
    """harmonics(attribute=True) is `harmonics --attribute`: the same JSON; and every significant
    order is attributed, among its causes, to the signal harmonic of the spec that makes it (Kuntz:
    a harmonic n gives orders |n - p| and n + p; the spec has n = 3 and 9, p = 2)."""
    spec = json.loads((ROOT / "tests" / "data" / "kuntz_eq33.json").read_text())
    (tmp_path / "spec.json").write_text(json.dumps(spec))
    ours = ac.harmonics(spec, attribute=True)
    assert ours == cli.json("harmonics", "--spec", tmp_path / "spec.json", "--attribute")
    assert ac.harmonics(tmp_path / "spec.json", attribute=True) == ours
    assert {k: v for k, v in ours.items() if k != "attribution"} == ac.harmonics(spec)
    p, given = spec["p"], {t["n"] for t in spec["terms"]}
    made = {k: n for n in given for k in (abs(n - p), n + p)}
    orders = [o["order"] for o in ours["attribution"]]
    assert sorted(orders) == sorted(made)
    for o in ours["attribution"]:
        named = {c["signal_order"] for c in o["causes"] if c["kind"] == "harmonic"}
        assert made[o["order"]] in named, o


def test_diagnose_equals_cli(cli, tmp_path):
    sim = ac.simulate("paper-noiseless", samples=2048, seed=3)
    real = ac.simulate("paper", samples=2048, seed=4)
    sim.write(tmp_path / "sim.csv")
    real.write(tmp_path / "real.csv")
    ours = ac.diagnose(sim, real)
    assert ours == cli.json(
        "diagnose", "--sim", tmp_path / "sim.csv", "--real", tmp_path / "real.csv"
    )
    assert ours["verdict"] in ("explained", "unexplained", "no_gap")


def test_simulate_config_dict_equals_cli_and_physics(cli, tmp_path):
    cfg = ac.scenario_config("paper", channels=2)
    cfg["effects"] = [{"effect": "offset", "offset_sin": 0.03}]
    (tmp_path / "s.json").write_text(json.dumps(cfg))
    cli(
        "simulate",
        "--config",
        tmp_path / "s.json",
        "--samples",
        500,
        "--seed",
        5,
        "--out",
        tmp_path / "s.csv",
    )
    theirs = ac.read_recording(tmp_path / "s.csv")
    for ours in (ac.simulate(cfg, samples=500, seed=5), ac.simulate(tmp_path / "s.json", 500, 5)):
        assert set(ours.columns) == set(theirs.columns) == {"t", "theta_ref", "sin", "cos"}
        for k in ours.columns:
            np.testing.assert_array_equal(ours.columns[k], theirs.columns[k], err_msg=k)
    plain = ac.simulate(ac.scenario_config("paper", channels=2), samples=500, seed=5)
    assert np.mean(theirs.sin - plain.sin) == pytest.approx(0.03, abs=1e-12)
    names = [s["name"] for s in ac.physics_scenarios()]
    case = ac.simulate_physics(names[0], samples=512, seed=1)
    assert len(case["real"]) == 512 and case["real"].meta["scenario"] == "physics"


def test_input_errors_are_value_errors_with_the_cli_message(cli, tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("theta_ref,sin,cos\n0,0,1\n0.1,zz,1\n")
    p = cli("estimate", "--regs", "none.hex", "--in", bad, expect=2)
    with pytest.raises(ValueError) as e:
        ac.read_recording(bad)
    p = cli("calibrate", "--in", bad, "--out", tmp_path / "x.hex", expect=2)
    assert p.stderr.strip() == f"anglecore: error: {e.value}"
    rec = ac.simulate("paper", samples=512, seed=1)
    with pytest.raises(ValueError, match=r"--degree 9: not in 1\.\.7"):
        ac.calibrate(rec, degree=9)
    with pytest.raises(ValueError, match="--xcenter needs --regions 8"):
        ac.calibrate(rec, xcenter=True)
    with pytest.raises(ValueError, match="neither 'auto' nor an angle"):
        ac.calibrate(rec, zero_offset="north")
    with pytest.raises(TypeError, match="unknown option 'degrees'"):
        ac.calibrate(rec, degrees=3)
    with pytest.raises(ValueError, match="unknown scenario 'no-such-scenario'"):
        ac.simulate("no-such-scenario")
    img = ac.calibrate(rec)
    with pytest.raises(ValueError, match="is not one of float, fixed"):
        ac.estimate(img, rec, engine="analog")


def test_wrong_types_and_shapes():
    n = np.zeros(8)
    with pytest.raises(TypeError, match="float64"):
        ac.Recording(sin=np.zeros(8, dtype=np.int32), cos=n, theta_ref=n)
    with pytest.raises(ValueError, match="1-D"):
        ac.Recording(sin=np.zeros((4, 2)), cos=n, theta_ref=n)
    with pytest.raises(ValueError, match="differ in length"):
        ac.Recording(sin=np.zeros(7), cos=n, theta_ref=n)
    with pytest.raises(ValueError, match=r"c1\.\.c4"):
        ac.Recording(c1=n, c2=n, theta_ref=n)
    with pytest.raises(TypeError):
        ac.estimate("regs.hex", ac.Recording(sin=n, cos=n))
    with pytest.raises(TypeError):
        ac.calibrate({"sin": n})
    # The extension itself refuses a wrong dtype rather than reading it as doubles.
    img = ac.calibrate(ac.simulate("paper", samples=512, seed=1))
    with pytest.raises(TypeError):
        ac._core.estimate_fixed_batch(img._img, 2, [np.zeros(4, np.float32)] * 2, None, 1)


def test_example_reproduces_the_demo_table(cli, tmp_path):
    demo = cli.json("demo", "--no-rtl", "--no-plots", "--no-sweep", "--out", tmp_path / "demo")
    png = tmp_path / "error.png"
    out = subprocess.run(
        [sys.executable, str(ROOT / "docs" / "python_example.py"), str(png)],
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    rows = {
        line[2:38].strip(): [float(v) for v in line[38:].split()]
        for line in out.splitlines()
        if line.startswith("  ours")
    }
    assert len(rows) == 5
    for name, got in rows.items():
        s = demo["table3"][name]
        want = [s["rms"], s["max_abs"], s["mean"]]
        # Bit-accurate rows print the demo's numbers; the float row runs the image's dequantized
        # coefficients (as `estimate --engine float`), the demo the unquantized ones.
        tol = 2e-3 if "float" in name else 6e-4
        assert got == pytest.approx(want, abs=tol), name
    assert png.stat().st_size > 10000
