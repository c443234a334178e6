# SPDX-License-Identifier: MIT
"""Options of the cocotb benches (tb/cocotb/test_benches.py; docs/cocotb.md)."""


def pytest_addoption(parser):
    g = parser.getgroup("anglecore cocotb benches")
    g.addoption("--sim", default="icarus", help="simulator: icarus or verilator")
    g.addoption("--samples", type=int, default=0, help="samples a bench streams (0: its default)")
    g.addoption("--samples-scale", type=int, default=1, help="times each bench's default samples")
    g.addoption("--seed", type=int, default=1, help="stimulus, gaps and stalls")
    g.addoption("--build-dir", default="", help="where the simulators build (build/cocotb)")
