#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Design-space sweep, hardware half: area and clock rate of every configuration a sweep shard
built.

usage: design_space_hw.py ROOT DIR SHARD [--jobs N]
  ROOT   the repository (rtl/files.f)
  DIR    the sweep directory: reads DIR/accuracy-<i>-of-<N>.jsonl (SHARD = "i/N"), writes
         DIR/hw-<i>-of-<N>.jsonl, one line per distinct configuration ("final_params"):
           {"final_params", "lut4", "dff", "carry", "bram", "fmax_mhz", "slowest", "stages": [...]}
         lut4/dff/carry/bram: Yosys synthesis of the whole acore_top with those parameters for the
         default device's family of synth/devices.toml (synth_ice40: its lut, ff, carry and bram
         cell classes); fmax_mhz: the slowest stage placed and routed alone on the default device,
         an HX8K (scripts/stage_fmax.py), the
         register file's host read-back port excluded (reported in "stages"); for a folded top
         (FOLD > 1, made to fit) the whole top placed and routed in the same kind of pin wrapper
         ("whole": {"lut4", "dff", "bram", "lcs", "fits", "fmax_mhz"}, "slowest": "acore_top").
         Configurations the serial core implements (1-D polynomial, no XCENTER, no Fourier stage,
         FOLD 1) also get "serial": {"lut4", "dff", "bram", "fmax_mhz", "cycles"} of
         rtl/acore_serial_top.v with the same parameters, placed and routed whole (it fits the
         HX8K); cycles = its CYCLES localparam as Verilator elaborates it
         (scripts/registry.py rtl_constants).
  Results are cached in DIR/cache/, so a rerun (or another shard on the same file system) only
  synthesizes what is new. Progress on stderr.

usage: design_space_hw.py one ROOT ACCURACY.jsonl DEVICE SEED OUT.json
  one job of the workflow (workflow/Snakefile): the one point of ACCURACY.jsonl on DEVICE (a device
  of synth/devices.toml: its family's synthesis, its place-and-route program) with placement seed
  SEED; writes OUT.json (the line above, plus "index" and "seed"; cache beside it)
usage: design_space_hw.py merge OUT_DIR RESULT.json ...
  joins the jobs of one device into OUT_DIR/hw-0-of-1.jsonl (per configuration the seed with the
  highest Fmax, every seed's Fmax in "fmax_by_seed")
"""

import concurrent.futures
import hashlib
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import registry


def rtl_files(root):
    return [os.path.join(root, "rtl", f) for f in registry.rtl_files(root)]


def synth_area(root, params, device=None):
    fam = registry.device(root, device).family
    chp = " ".join(f"-chparam {k} {v}" for k, v in (p.split("=", 1) for p in params.split()))
    with tempfile.TemporaryDirectory(prefix="acore_area_") as tmp:
        stat = os.path.join(tmp, "stat.txt")
        r = subprocess.run(
            [
                "yosys",
                "-q",
                "-l",
                os.path.join(tmp, "log"),
                "-p",
                (
                    f"read_verilog -sv {' '.join(rtl_files(root))}; hierarchy -top acore_top "
                    f"{chp}; {fam.yosys_command('acore_top')}; tee -q -o {stat} stat"
                ),
            ],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )
        if r.returncode != 0 or not os.path.exists(stat):
            raise RuntimeError(f"yosys {fam.synth} failed for " + params)
        c = registry.cells(stat)
    return {
        "lut4": fam.count(c, ["lut"]),
        "dff": fam.count(c, ["ff"]),
        "carry": fam.count(c, ["carry"]),
        "bram": fam.count(c, ["bram"]),
    }


def measure(root, cache, params, device=None, seed=None):
    dev = registry.device(root, device).name
    # Placement options of stage_fmax.py: the device, and the seed when not the table's.
    opts = ["--device", dev] + (["--seed", str(seed)] if seed is not None else [])
    key = hashlib.sha1(
        (
            params
            + "|"
            + dev
            + ("" if seed is None else f"|seed {seed}")
            + "|"
            + "".join(open(f).read() for f in rtl_files(root))
        ).encode()
    ).hexdigest()[:16]
    path = os.path.join(cache, f"top-{key}.json")
    if os.path.exists(path):
        return json.load(open(path))
    res = {"final_params": params, "device": dev}
    if seed is not None:
        res["seed"] = seed
    res.update(synth_area(root, params, dev))
    p = dict(kv.split("=", 1) for kv in params.split())
    if int(p.get("FOLD", 1)) > 1:
        # A folded top is made to fit: place and route it whole.
        out = subprocess.run(
            [
                sys.executable,
                os.path.join(HERE, "stage_fmax.py"),
                *opts,
                "--whole",
                "acore_top",
                root,
                os.path.join(cache, "whole"),
                *params.split(),
            ],
            capture_output=True,
            text=True,
        )
        if out.returncode != 0:
            raise RuntimeError(
                "stage_fmax.py --whole acore_top failed for " + params + ": " + out.stderr.strip()
            )
        wh = json.loads(out.stdout)
        res["whole"] = wh
        res["fmax_mhz"] = wh.get("fmax_mhz")
        res["slowest"] = "acore_top" if wh.get("fmax_mhz") else None
        res["all_stages_fit"] = bool(wh.get("fits"))
        res["stages"] = []
        write_atomic(path, res)
        return res
    out = subprocess.run(
        [
            sys.executable,
            os.path.join(HERE, "stage_fmax.py"),
            *opts,
            root,
            os.path.join(cache, "stages"),
            *params.split(),
        ],
        capture_output=True,
        text=True,
    )
    if out.returncode != 0:
        raise RuntimeError("stage_fmax.py failed for " + params + ": " + out.stderr.strip())
    st = json.loads(out.stdout)
    datapath = [
        s for s in st["stages"] if s.get("module") != "acore_coef_regfile" and s.get("fmax_mhz")
    ]
    slow = min(datapath, key=lambda s: s["fmax_mhz"]) if datapath else None
    res["fmax_mhz"] = slow["fmax_mhz"] if slow else None
    res["slowest"] = slow["module"] if slow else None
    res["all_stages_fit"] = st["all_fit"]
    res["stages"] = st["stages"]
    if (
        int(p.get("CORRECTION", 0)) == 0
        and int(p.get("XCENTER", 0)) == 0
        and int(p.get("FOURIER_K", 0)) == 0
    ):
        # The serial core has the pipelined top's parameters but those of the correction modes
        # and FOLD.
        serial = [
            (k, int(v))
            for k, v in p.items()
            if k in registry.rtl_parameters(root, "acore_serial_top")
        ]
        serial_params = [f"{k}={v}" for k, v in serial]
        out = subprocess.run(
            [
                sys.executable,
                os.path.join(HERE, "stage_fmax.py"),
                *opts,
                "--whole",
                "acore_serial_top",
                root,
                os.path.join(cache, "serial"),
                *serial_params,
            ],
            capture_output=True,
            text=True,
        )
        if out.returncode != 0:
            raise RuntimeError(
                "stage_fmax.py --whole acore_serial_top failed for "
                + params
                + ": "
                + out.stderr.strip()
            )
        sr = json.loads(out.stdout)
        sr["cycles"] = registry.rtl_constants(root, "acore_serial_top", serial)["CYCLES"]
        res["serial"] = sr
    write_atomic(path, res)
    return res


def write_atomic(path, obj):
    """A result appears whole or not at all (the jobs of a sweep share the cache)."""
    tmp = f"{path}.{os.getpid()}.tmp"
    with open(tmp, "w") as f:
        json.dump(obj, f)
    os.replace(tmp, path)


def one(root, acc, device, seed, out):
    """One job of the design-space workflow (workflow/Snakefile): the configuration of the one
    point of an accuracy file on one device with one seed, written to OUT (its own report)."""
    rows = [json.loads(l) for l in open(acc) if l.strip()]
    if len(rows) != 1:
        sys.exit(f"design_space_hw.py: {acc}: {len(rows)} points, expected one")
    r = rows[0]
    params = r.get("final_params")
    if not params:  # calibration failed: nothing to synthesize (the report says why)
        res = {"index": r.get("index"), "error": r.get("error", "no final_params")}
    else:
        cache = os.path.join(os.path.dirname(os.path.abspath(out)), "cache")
        os.makedirs(os.path.join(cache, "stages"), exist_ok=True)
        res = dict(measure(root, cache, params, device, seed), index=r.get("index"))
        res["seed"] = seed
    write_atomic(out, res)


def merge(out_dir, files):
    """The workflow's per-device join: every job's result of one device into
    OUT_DIR/hw-0-of-1.jsonl, one line per configuration, the seed with the highest Fmax (every
    seed's in "fmax_by_seed"; placement seeds move nextpnr's Fmax by a few MHz)."""
    best = {}
    for f in files:
        r = json.load(open(f))
        if "error" in r or not r.get("final_params"):
            continue
        p = r["final_params"]
        b = best.setdefault(p, dict(r, fmax_by_seed={}))
        b["fmax_by_seed"][str(r.get("seed"))] = r.get("fmax_mhz")
        if (r.get("fmax_mhz") or 0) > (b.get("fmax_mhz") or 0):
            best[p] = dict(r, fmax_by_seed=b["fmax_by_seed"])
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "hw-0-of-1.jsonl"), "w") as f:
        for r in best.values():
            f.write(json.dumps(r) + "\n")


def main():
    args = sys.argv[1:]
    if args[:1] == ["one"] and len(args) == 6:
        one(args[1], args[2], args[3], int(args[4]), args[5])
        return
    if args[:1] == ["merge"] and len(args) >= 2:
        merge(args[1], args[2:])
        return
    jobs = 1
    if "--jobs" in args:
        i = args.index("--jobs")
        jobs = int(args[i + 1])
        del args[i : i + 2]
    if len(args) != 3:
        sys.exit(__doc__)
    root, d, shard = args
    i, n = shard.split("/")
    acc = os.path.join(d, f"accuracy-{i}-of-{n}.jsonl")
    if not os.path.exists(acc):
        sys.exit(
            f"design_space_hw.py: {acc}: not found (run anglecore sweep --shard {shard} first)"
        )
    configs = []
    for line in open(acc):
        p = json.loads(line).get("final_params")
        if p and p not in configs:
            configs.append(p)
    cache = os.path.join(d, "cache")
    os.makedirs(os.path.join(cache, "stages"), exist_ok=True)
    out_path = os.path.join(d, f"hw-{i}-of-{n}.jsonl")
    t0 = time.time()
    done = 0
    with (
        open(out_path, "w") as out,
        concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool,
    ):
        futs = {pool.submit(measure, root, cache, p): p for p in configs}
        for fut in concurrent.futures.as_completed(futs):
            done += 1
            try:
                r = fut.result()
                out.write(json.dumps(r) + "\n")
                out.flush()
                print(
                    f"[{done}/{len(configs)}] {futs[fut]}: {r['lut4']} LUT4, {r['fmax_mhz']} MHz "
                    f"({time.time() - t0:.0f} s)",
                    file=sys.stderr,
                )
            except Exception as e:  # noqa: BLE001
                # One failed configuration must not lose the others.
                print(f"[{done}/{len(configs)}] {futs[fut]}: FAILED: {e}", file=sys.stderr)
                out.write(json.dumps({"final_params": futs[fut], "error": str(e)}) + "\n")


if __name__ == "__main__":
    main()
