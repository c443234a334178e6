# SPDX-License-Identifier: MIT
"""Shared fixtures: the `anglecore` command the package is compared with (ACORE_CLI, set by CTest;
else build/anglecore) and a runner that returns its --json output."""

import json
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(os.environ.get("ACORE_SOURCE_DIR", Path(__file__).resolve().parents[2]))


@pytest.fixture(scope="session")
def cli():
    exe = Path(os.environ.get("ACORE_CLI", ROOT / "build" / "anglecore"))
    assert exe.is_file(), f"{exe}: build the CLI first (cmake --build build --target anglecore)"

    def run(*args, expect=0):
        p = subprocess.run([str(exe), *map(str, args)], capture_output=True, text=True)
        assert p.returncode == expect, p.stderr
        return p

    def run_json(*args):
        return json.loads(run(*args, "--json", "-").stdout)

    run.json = run_json
    return run


@pytest.fixture(scope="session")
def paper(tmp_path_factory, cli):
    """The paper scenario's calibration (seed 11) and validation (seed 12) recordings, 3600 samples,
    written by the CLI."""
    d = tmp_path_factory.mktemp("paper")
    for name, seed in (("cal", 11), ("val", 12)):
        cli(
            "simulate",
            "--scenario",
            "paper",
            "--samples",
            3600,
            "--seed",
            seed,
            "--out",
            d / f"{name}.csv",
        )
    return d
