#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""\
estimate() of the Python package on 1 M samples from numpy against the C++ batch benchmark, in one
run, and their ratio (target: within 1.2x of BM_EstimateFixedBatch, the same work in C++).

    cmake --build build --target bench_estimator && .venv/bin/python scripts/bench_python.py

Prints the fastest of --reps runs (ms per 1 M samples; the minimum, as the machine may be shared) of
BM_FixedChain (the batch chain on ready codes), BM_EstimateFixedBatch (codes + chain + angles +
errors: what estimate runs) and of anglecore.estimate(img, rec, engine="fixed", uncorrected=False,
track=False) timed with time.perf_counter (without the tracking observer: the C++ benchmark runs
none).
"""

import argparse
import json
import statistics
import subprocess
import time
from pathlib import Path

import anglecore as ac

N = 1 << 20  # the benchmark's kSamples


def cpp_fastest(exe: Path, reps: int) -> dict:
    out = subprocess.run(
        [
            str(exe),
            "--benchmark_filter=BM_FixedChain$|BM_EstimateFixedBatch",
            "--benchmark_format=json",
            f"--benchmark_repetitions={reps}",
        ],
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    best: dict = {}
    for b in json.loads(out)["benchmarks"]:
        if b.get("run_type") == "iteration":
            best[b["run_name"]] = min(best.get(b["run_name"], float("inf")), b["real_time"])
    return best


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default=Path(__file__).resolve().parents[1] / "build", type=Path)
    ap.add_argument("--reps", default=7, type=int)
    a = ap.parse_args()
    rec = ac.simulate("paper-noiseless", samples=N, seed=1)
    img = ac.calibrate(rec)
    ac.estimate(img, rec, engine="fixed", uncorrected=False, track=False)  # warm-up
    times = []
    for _ in range(a.reps):
        t0 = time.perf_counter()
        res = ac.estimate(img, rec, engine="fixed", uncorrected=False, track=False)
        times.append((time.perf_counter() - t0) * 1e3)
    py = min(times)
    cpp = cpp_fastest(a.build / "tests" / "bench" / "bench_estimator", a.reps)
    print(
        f"samples {N}, fastest of {a.reps} runs each (ms; Python median "
        f"{statistics.median(times):.2f}):"
    )
    print(f"  C++ BM_FixedChain          {cpp['BM_FixedChain']:8.2f}  (batch chain on ready codes)")
    print(f"  C++ BM_EstimateFixedBatch  {cpp['BM_EstimateFixedBatch']:8.2f}  (estimate's work)")
    print(f"  Python anglecore.estimate  {py:8.2f}  (error RMS {res.error_deg['rms']:.4f} deg)")
    print(f"ratio Python / BM_EstimateFixedBatch = {py / cpp['BM_EstimateFixedBatch']:.3f}")
    print(f"ratio Python / BM_FixedChain         = {py / cpp['BM_FixedChain']:.3f}")


if __name__ == "__main__":
    main()
