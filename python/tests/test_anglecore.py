# SPDX-License-Identifier: MIT
"""The package against the `anglecore` command on the same inputs: recordings, register words,
bit-accurate angles and statistics identical; input errors as ValueError/TypeError."""

import csv
import json
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
        # The command also runs the tracking observer (track, velocity_error_rpm): the package
        # has no observer yet.
        for key in ("track", "velocity_error_rpm"):
            j.pop(key, None)
        assert res.report == j  # every statistic, the zero offset, the flagged count
        with open(angles) as f:
            rows = list(csv.DictReader(f))
        # The CLI writes %.9f: our doubles print the same text, sample for sample.
        assert [f"{a:.9f}" for a in res.angle] == [r["angle_rad"] for r in rows]
        assert [f"{a:.9f}" for a in res.uncorrected] == [r["uncorrected_rad"] for r in rows]
        assert res.flags.tolist() == [int(r["flags"]) for r in rows]
        assert res.region.tolist() == [int(r["region"]) for r in rows]


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
    assert fast.uncorrected is None and "uncorrected_error_deg" not in fast.report


def test_harmonics_equals_cli(cli, tmp_path):
    spec = json.loads((ROOT / "tests" / "data" / "kuntz_eq33.json").read_text())
    spec["terms"].append({"n": 3, "A": 0.01, "theta": 0.2, "B": 0.008, "psi": -0.4})
    (tmp_path / "spec.json").write_text(json.dumps(spec))
    ours = ac.harmonics(spec)
    assert ours == cli.json("harmonics", "--spec", tmp_path / "spec.json")
    assert ac.harmonics(tmp_path / "spec.json") == ours


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
