#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The design-space workflow (workflow/Snakefile) under test.

usage: workflow.py dry ROOT ANGLECORE WORKDIR
  CTest design_space_graph (default run, seconds): `snakemake -n` of the full default grid on every
  device of synth/devices.toml with two seeds; the job count must be what the grid gives, counted
  independently: P accuracy jobs (`anglecore sweep --list`: P points), P x devices x seeds hardware
  jobs, one join per device, the report and `all`. A grid file the sweep refuses must stop the
  workflow before any job (non-zero exit, the sweep's message).
usage: workflow.py small ROOT ANGLECORE WORKDIR [--cores N]
  CTest design_space_small (configuration Long, label design_space): the real run of a small grid
  (workflow/small_grid.json: the uncorrected top folded by 8) on the iCE40 HX8K and the ECP5
  LFE5U-25F, seed 1, `--cores 2`: every job's report exists, every device's table has the point with
  its clock rate, and the page joins them.
Exit 1 when a check fails, 2 on bad usage.
"""

import json
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
import devices

SMALL_DEVICES = ["hx8k", "lfe5u25"]


def snakemake(root):
    return os.path.join(root, ".venv", "bin", "snakemake")


def run(root, anglecore, workdir, extra, config):
    cmd = [
        snakemake(root),
        "-s",
        os.path.join(root, "workflow", "Snakefile"),
        "--directory",
        workdir,
        "--config",
        f"anglecore={anglecore}",
        f"out={os.path.join(workdir, 'out')}",
        *config,
        *extra,
    ]
    return subprocess.run(cmd, capture_output=True, text=True)


def dry(root, anglecore, workdir):
    fails = []
    points = subprocess.run([anglecore, "sweep", "--list"], capture_output=True, text=True)
    p = len([l for l in points.stdout.splitlines() if l.strip()])
    ndev = len(devices.load(root).devices)
    seeds = 2
    r = run(root, anglecore, workdir, ["-n", "--quiet", "rules"], ["devices=all", "seeds=1,2"])
    m = re.search(r"^total\s+(\d+)\s*$", r.stdout + r.stderr, re.MULTILINE)
    want = p + p * ndev * seeds + ndev + 2
    if r.returncode != 0 or not m:
        fails.append(f"snakemake -n failed ({r.returncode}): {(r.stdout + r.stderr)[-2000:]}")
    elif int(m.group(1)) != want:
        fails.append(
            f"snakemake -n: {m.group(1)} jobs, expected {want} ({p} points, {ndev} devices, "
            f"{seeds} seeds)"
        )
    else:
        print(f"full grid: {m.group(1)} jobs ({p} points x {ndev} devices x {seeds} seeds)")
    bad = os.path.join(workdir, "bad_grid.json")
    with open(bad, "w") as f:
        f.write('[{"DEGREE": [42]}]')
    r = run(root, anglecore, workdir, ["-n"], [f"grid={bad}"])
    if r.returncode == 0:
        fails.append("a grid the sweep refuses (DEGREE=42) did not stop the workflow")
    r = run(root, anglecore, workdir, ["-n"], ["devices=nosuch"])
    if r.returncode == 0 or "nosuch" not in r.stdout + r.stderr:
        fails.append("an unknown device did not stop the workflow with its name")
    return fails


def small(root, anglecore, workdir, cores):
    fails = []
    t = devices.load(root)
    # The HX8K and the ECP5: the small grid's folded top keeps its memories in block RAM, which
    # the GW1N-9's pair of tools does not place yet (docs/synthesis.md "The devices table").
    devs = SMALL_DEVICES
    t0 = time.time()
    r = run(
        root,
        anglecore,
        workdir,
        ["--cores", str(cores)],
        ["grid=workflow/small_grid.json", f"devices={','.join(devs)}", "seeds=1"],
    )
    took = time.time() - t0
    if r.returncode != 0:
        return [f"snakemake failed ({r.returncode}): {(r.stdout + r.stderr)[-3000:]}"]
    out = os.path.join(workdir, "out")
    for d in devs:
        hw = os.path.join(out, "hw", d, "seed1", "0.json")
        res = json.load(open(hw)) if os.path.exists(hw) else {}
        if not res.get("fmax_mhz") or res.get("device") != d:
            fails.append(f"{hw}: no clock rate on {d}: {res}")
        md = os.path.join(out, d, "design_space.md")
        if not os.path.exists(md) or "`CORRECTION=2 FOLD=8`" not in open(md).read():
            fails.append(f"{md}: no row of the point")
    page = os.path.join(out, "design_space.md")
    text = open(page).read() if os.path.exists(page) else ""
    for d in devs:
        if f"## {t.devices[d].title}" not in text:
            fails.append(f"{page}: no section of {d}")
    print(f"small grid on {', '.join(devs)}: {took:.0f} s with --cores {cores}")
    return fails


def main(argv):
    if len(argv) < 4 or argv[0] not in ("dry", "small"):
        print(__doc__, file=sys.stderr)
        return 2
    mode, root, anglecore, workdir = argv[0], *map(os.path.abspath, argv[1:4])
    cores = int(argv[5]) if argv[4:5] == ["--cores"] and len(argv) > 5 else 2
    os.makedirs(workdir, exist_ok=True)
    fails = (
        dry(root, anglecore, workdir) if mode == "dry" else small(root, anglecore, workdir, cores)
    )
    for f in fails:
        print(f"FAIL: {f}")
    print(f"{0 if fails else 1} passed, {1 if fails else 0} failed")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
