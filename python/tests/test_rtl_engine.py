# SPDX-License-Identifier: MIT
"""engine="rtl" and "rtl-serial": the Verilated tops through the package equal `anglecore estimate
--engine rtl|rtl-serial` on the same image and recording, and are bit-exact to engine="fixed"; a
module that is not built raises RtlNotBuilt naming the command that builds it.

The modules come from the CMake build under test (CTest sets ACORE_RTL_DIR to its rtl/ folder and
ACORE_WITH_RTL to whether it makes them: OFF skips the runs, not the missing-module checks)."""

import csv
import os

import anglecore as ac
import numpy as np
import pytest

needs_modules = pytest.mark.skipif(
    os.environ.get("ACORE_WITH_RTL", "ON") == "OFF",
    reason="this build makes no RTL modules (ACORE_WITH_RTL=OFF)",
)


@pytest.fixture(scope="module")
def images(paper, cli, tmp_path_factory):
    """The CLI's images of the paper calibration: the default one and a self-calibration (its
    zero unknown: errors judged about their mean), both of the default configuration."""
    d = tmp_path_factory.mktemp("rtl")
    cli("calibrate", "--in", paper / "cal.csv", "--out", d / "regs.hex")
    cli("calibrate", "--in", paper / "cal.csv", "--out", d / "self.hex", "--reference", "none")
    return {"regs": d / "regs.hex", "self": d / "self.hex"}


def cli_estimate(cli, tmp_path, hexfile, rec, *flags):
    angles = tmp_path / "angles.csv"
    j = cli.json("estimate", "--regs", hexfile, "--in", rec, "--out", angles, *flags)
    with open(angles) as f:
        return j, list(csv.DictReader(f))


@needs_modules
@pytest.mark.parametrize("name", ["regs", "self"])
@pytest.mark.parametrize("engine,fold", [("rtl", 1), ("rtl-serial", 1), ("rtl", 2)])
def test_rtl_equals_cli_and_fixed(paper, cli, tmp_path, images, name, engine, fold):
    img = ac.read_image(images[name])
    val = ac.read_recording(paper / "val.csv")
    res = ac.estimate(img, val, engine=engine, fold=fold)
    j, rows = cli_estimate(
        cli,
        tmp_path,
        images[name],
        paper / "val.csv",
        "--engine",
        engine,
        *(["--fold", fold] if fold != 1 else []),
    )
    # every statistic, the fold, the zero offset, the flagged count, the observer's block
    assert res.report == j
    assert res.report["engine"] == engine and res.report["about_mean"] == (name == "self")
    assert [f"{a:.9f}" for a in res.angle] == [r["angle_rad"] for r in rows]
    assert res.flags.tolist() == [int(r["flags"]) for r in rows]
    assert res.region.tolist() == [int(r["region"]) for r in rows]
    assert [f"{v:.6f}" for v in res.velocity] == [r["velocity_rpm"] for r in rows]
    # Bit-exact to the bit-accurate model: the same angles as doubles, regions, flags, errors.
    fixed = ac.estimate(img, val, engine="fixed")
    for field in ("angle", "region", "flags", "error", "uncorrected", "uncorrected_error"):
        np.testing.assert_array_equal(getattr(res, field), getattr(fixed, field), err_msg=field)
    assert res.error_deg == fixed.error_deg


@needs_modules
def test_rtl_trace_and_options(paper, images, tmp_path):
    img = ac.read_image(images["regs"])
    rec = ac.simulate("paper", samples=300, seed=5)
    fst = tmp_path / "wave.fst"
    res = ac.estimate(img, rec, engine="rtl", trace=fst, uncorrected=False)
    assert fst.stat().st_size > 1000
    assert res.uncorrected is None and "uncorrected_error_deg" not in res.report
    np.testing.assert_array_equal(res.angle, ac.estimate(img, rec, engine="fixed").angle)


def test_rtl_module_missing_names_the_command(paper, images, tmp_path, monkeypatch):
    img = ac.read_image(images["regs"])
    rec = ac.simulate("paper", samples=64, seed=1)
    empty = tmp_path / "empty"
    empty.mkdir()
    for engine, module in (("rtl", "acore_rtl_default"), ("rtl-serial", "acore_rtl_serial")):
        with pytest.raises(ac.RtlNotBuilt) as e:
            ac.estimate(img, rec, engine=engine, rtl_dir=empty)
        msg = str(e.value)
        assert f"{empty}/{module}.so" in msg and "(the folder given)" in msg, msg
        assert "cmake --build " in msg and f"--target {module}`" in msg, msg
        assert "ACORE_RTL_DIR" in msg, msg
        assert isinstance(e.value, ValueError)  # an input error, as the command's exit 2
    monkeypatch.setenv("ACORE_RTL_DIR", str(empty))
    with pytest.raises(ac.RtlNotBuilt, match=r"\(\$ACORE_RTL_DIR\) does not exist"):
        ac.estimate(img, rec, engine="rtl", fold=4)


def test_engine_options_are_checked(images):
    img = ac.read_image(images["regs"])
    rec = ac.simulate("paper", samples=64, seed=1)
    with pytest.raises(ValueError, match="--fold applies to --engine rtl only"):
        ac.estimate(img, rec, engine="fixed", fold=2)
    with pytest.raises(ValueError, match="--fold applies to --engine rtl only"):
        ac.estimate(img, rec, engine="rtl-serial", fold=2)
    with pytest.raises(ValueError, match="RTL engines only"):
        ac.estimate(img, rec, engine="float", trace="x.fst")
    with pytest.raises(ValueError, match="is not one of float, fixed, rtl, rtl-serial"):
        ac.estimate(img, rec, engine="verilog")
