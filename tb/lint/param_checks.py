#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Parameter rules of the RTL, checked against every tool and against the model.

  param_checks.py illegal [--root DIR] [--jobs N] [--tools all|rotate]
      Every row of tb/lint/illegal_params.txt (an illegal configuration and the rule it breaks) must
      stop Verilator (--lint-only -Wall), Icarus (iverilog elaboration) and Yosys (read_verilog -sv;
      hierarchy) with that rule's message (rtl/acore_check.v): Verilator names the rule's instance
      and the value, Icarus the instance and the value, Yosys the rule's text. Each top's defaults
      must pass all three (the control), and so must the APB shell's.
      --tools all (the default): every row through all three tools. --tools rotate: row k (from 0,
      in the table's order) through one tool, Verilator, Icarus and Yosys in turn, so that every
      rule's condition is checked and each tool stops on a third of the rows, for a third of the
      time (the default CTest run; the full matrix is the CTest configuration Long's).
  param_checks.py agree --validator BIN [--root DIR] [--jobs N] [--sets N] [--seed S]
      N random parameter sets around the limits (half for each top), each judged by
      `verilator --lint-only -Wall` and by the model's DatapathConfig::validate() for that top (BIN
      is build/tb/acore_validate_params): 0 accepted by the RTL but rejected by the model, 0 the
      other way, and both verdicts must occur (at least a quarter each).

Exit 0 when every check passes, 1 when one fails, 2 on bad usage or a malformed table row.
"""

import argparse
import concurrent.futures
import os
import random
import re
import subprocess
import sys

sys.path.insert(
    0,
    os.path.join(
        os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "scripts"
    ),
)
import registry
from registry import rtl_files

TOPS = ("acore_top", "acore_serial_top")
# The register shell around either top (rtl/acore_apb.v): its defaults are a control too.
SHELLS = ("acore_apb",)


class Usage(Exception):
    pass


def run(cmd, cwd):
    p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return p.returncode, p.stdout


def verilator(root, top, params):
    rtl = os.path.join(root, "rtl")
    return run(
        [
            "verilator",
            "--lint-only",
            "-Wall",
            "verilator.vlt",
            *rtl_files(root),
            "--top-module",
            top,
            *[f"-G{k}={v}" for k, v in params],
        ],
        rtl,
    )


def icarus(root, top, params):
    rtl = os.path.join(root, "rtl")
    return run(
        [
            "iverilog",
            "-g2012",
            "-o",
            os.devnull,
            "-s",
            top,
            *[f"-P{top}.{k}={v}" for k, v in params],
            *rtl_files(root),
        ],
        rtl,
    )


def yosys(root, top, params):
    rtl = os.path.join(root, "rtl")
    # Yosys reads no negative decimal here: a negative value as its 32-bit two's complement.
    chp = "".join(
        f" -chparam {k} {v if v >= 0 else f'32{chr(39)}h{v & 0xFFFFFFFF:x}'}" for k, v in params
    )
    return run(
        [
            "yosys",
            "-q",
            "-p",
            f"read_verilog -sv -defer {' '.join(rtl_files(root))}; hierarchy -top {top}{chp}",
        ],
        rtl,
    )


def rule_messages(root):
    """(module, rule instance) -> the MSG of that acore_check, from the RTL sources (with the files
    they include: the mode table's rules are generated into rtl/acore_mode_checks.vh)."""
    msgs = {}
    for f in rtl_files(root):
        text = registry.with_includes(os.path.join(root, "rtl", f))
        mod = re.search(r"^module (\w+)", text, re.MULTILINE).group(1)
        for m in re.finditer(r'\.MSG\("([^"]*)"\)\)\s*(\w+) \(\);', text):
            msgs[(mod, m.group(2))] = m.group(1)
    return msgs


def parse_params(tokens, where):
    out = []
    for t in tokens:
        m = re.fullmatch(r"([A-Z][A-Z0-9_]*)=(-?\d+)", t)
        if not m:
            raise Usage(f"{where}: '{t}' is not PARAM=integer")
        out.append((m.group(1), int(m.group(2))))
    return out


def read_table(path):
    rows = []
    for n, line in enumerate(open(path), 1):
        line = line.split("#", 1)[0].split()
        if not line:
            continue
        where = f"{path}:{n}"
        if len(line) < 4 or not re.fullmatch(r"acore_\w+", line[0]) or "." not in line[1]:
            raise Usage(f"{where}: expected 'TOP MODULE.RULE VALUE PARAM=v ...'")
        try:
            value = int(line[2])
        except ValueError:
            raise Usage(f"{where}: value '{line[2]}' is not an integer")
        rows.append((where, line[0], *line[1].split(".", 1), value, parse_params(line[3:], where)))
    return rows


# The three tools, by the name the messages use (check_legal runs every one, check_illegal those
# it is given).
TOOLS = {"verilator": verilator, "iverilog": icarus, "yosys": yosys}
TOOL_NAMES = tuple(TOOLS)


def check_illegal(root, row, msgs, tools=TOOL_NAMES):
    """Returns a list of failures (empty: every tool of `tools` stopped with the rule)."""
    where, top, module, rule, value, params = row
    msg = msgs.get((module, rule))
    if msg is None:
        return [f"{where}: no acore_check instance {rule} in module {module}"]
    fails = []
    desc = f"{where} ({top} {' '.join(f'{k}={v}' for k, v in params)}): {module}.{rule}"
    if "verilator" in tools:
        fails += verilator_stops(root, top, params, msg, value, rule, desc)
    if "iverilog" in tools:
        fails += icarus_stops(root, top, params, value, rule, desc)
    if "yosys" in tools:
        fails += yosys_stops(root, top, params, msg, desc)
    return fails


def verilator_stops(root, top, params, msg, value, rule, desc):
    rc, out = verilator(root, top, params)
    # %Warning-USERERROR: <file>: <MSG> (value V)\n ... : ... In instance <path>.<rule>
    found = re.search(
        r"USERERROR: [^\n]*: %s \(value %d\)\n[^\n]*In instance [\w.]*\b%s\n"
        % (re.escape(msg), value, re.escape(rule)),
        out,
    )
    if rc == 0 or not found:
        why = f"did not stop with '{msg} (value {value})'"
        return [f"{desc}: verilator (exit {rc}) {why}:\n{out[:1500]}"]
    return []


def icarus_stops(root, top, params, value, rule, desc):
    rc, out = icarus(root, top, params)
    if rc == 0 or not re.search(
        r"`[\w.\[\]]*\b%s\.failed\.value\[%d\]'" % (re.escape(rule), value), out
    ):
        why = f"did not stop in {rule}.failed.value[{value}]"
        return [f"{desc}: iverilog (exit {rc}) {why}:\n{out[:1500]}"]
    return []


def yosys_stops(root, top, params, msg, desc):
    rc, out = yosys(root, top, params)
    errors = re.findall(r"ERROR: (.*)", out)
    if rc == 0 or not errors or errors[0] != msg + ".":
        return [f"{desc}: yosys (exit {rc}) did not stop with '{msg}':\n{out[:1500]}"]
    return []


def check_legal(root, top):
    fails = []
    for name, tool in TOOLS.items():
        rc, out = tool(root, top, [])
        if rc != 0 or (name == "verilator" and "%Warning" in out):
            fails.append(f"{top} defaults: {name} rejected them (exit {rc}):\n{out[:1500]}")
    return fails


def named_configs(root):
    """The parameters of every acore_top line of the build registry (rtl/configs.txt)."""
    return [list(l.params) for l in registry.select(root, module="acore_top")]


def candidate_table(c):
    """Parameter -> values around its limits, given the current configuration c: the parameters
    the random sets move (each top moves those of them it has)."""
    return {
        "IN_W": [7, 8, 12, 16, 18, 24, 25],
        "REG_W": [c["IN_W"] + 1, c["IN_W"] + 2, 18, 20, 22, 30, 31],
        "S_W": [c["S_F"] + 1, c["S_F"] + 2, 18, 20, 30, 31],
        "S_F": [2, 3, 12, 14, 16],
        "R_SHIFT": [-1, 0, 9, 13, 30, 31],
        "SCALE_G": [-1, 0, 4, c["R_SHIFT"], c["R_SHIFT"] + 1],
        "CORRECTION": [-1, 0, 1, 2, 3],
        "DEGREE": [0, 1, 2, 3, 4, 5, 7, 8],
        "REGIONS": [2, 4, 6, 8, 16],
        "XCENTER": [0, 1, 2],
        "COEF_F": [0, 1, 12, 15, c["REG_W"] - 1, c["REG_W"]],
        "ACC_G": [-1, 0, 4, 7, c["S_F"] - c["COEF_F"] - 1, c["S_F"] - c["COEF_F"]],
        "ACC_I": [
            c["REG_W"] - c["COEF_F"],
            c["REG_W"] - c["COEF_F"] + 1,
            6,
            12,
            40 - c["COEF_F"] - c["ACC_G"],
            41 - c["COEF_F"] - c["ACC_G"],
        ],
        "K": [3, 4, 12, 16, 24, 25],
        "CORDIC_G": [-1, 0, 3, 8, 9],
        "Z_W": [c["ANGLE_W"] - 1, c["ANGLE_W"], 20, c["REG_W"] + 2, c["REG_W"] + 3],
        "ANGLE_W": [7, 8, 12, 16, 24, 25],
        "FOURIER_K": [-1, 0, 1, 8, 31, 32],
        "FOURIER_M": [3, 4, 12, c["K"], c["K"] + 1],
        "FOURIER_CF": [
            c["REG_W"] - 2,
            c["REG_W"] - 1,
            22,
            40 - c["FOURIER_G"],
            41 - c["FOURIER_G"],
        ],
        "FOURIER_W": [7, 8, 16, c["REG_W"], c["REG_W"] + 1],
        "FOURIER_G": [-1, 0, 2, 8, 9],
        "ZERO": [-1, 0, 1, 1, 2],
        "FOLD": [0, 1, 2, 3, 4, 8, 16, 32, 64],
        "MULT": [-1, 0, 0, 1, 1, 2],
    }


def candidates(p, c):
    return candidate_table(c)[p]


def rtl_defaults(root):
    """(defaults, {top: the parameters it moves}): the moved parameters' defaults as the RTL
    elaborates them (acore_top's header; the serial core must agree on the ones it has, since the
    model applies every set to one default configuration)."""
    top = registry.rtl_parameters(root, "acore_top")
    moved = list(candidate_table(top))
    missing = [p for p in moved if p not in top]
    if missing:
        raise Usage(
            f"acore_top has no parameter {', '.join(missing)} "
            "(tb/lint/param_checks.py candidate_table)"
        )
    defaults = {p: top[p] for p in moved}
    names = {}
    for t in TOPS:
        have = registry.rtl_parameters(root, t)
        names[t] = [p for p in moved if p in have]
        differ = [
            f"{p}={have[p]} (acore_top: {defaults[p]})" for p in names[t] if have[p] != defaults[p]
        ]
        if differ:
            raise Usage(f"{t}'s defaults differ from acore_top's: {', '.join(differ)}")
    return defaults, names


def random_sets(root, n, seed):
    """n (top, overrides) pairs: a named configuration (or the serial's defaults) with one to three
    parameters moved to values around their limits."""
    rng = random.Random(seed)
    bases = named_configs(root)
    defaults, top_names = rtl_defaults(root)
    sets = []
    for i in range(n):
        top = TOPS[i % 2]
        c = dict(defaults)
        names = top_names[top]
        if top == "acore_top":
            c.update(rng.choice(bases))
        for _ in range(rng.choice((1, 1, 2, 3))):
            p = rng.choice(names)
            c[p] = rng.choice(candidates(p, c))
        sets.append((top, [(k, c[k]) for k in names if c[k] != defaults[k]]))
    return sets


def agree(args):
    sets = random_sets(args.root, args.sets, args.seed)
    # One set a line, the top first: the model judges each for its top (validate(DatapathTop)).
    lines = "".join(" ".join([t] + [f"{k}={v}" for k, v in p]) + "\n" for t, p in sets)
    v = subprocess.run([args.validator], input=lines, stdout=subprocess.PIPE, text=True)
    if v.returncode != 0:
        print(f"param_checks: {args.validator} failed (exit {v.returncode})")
        return 1
    model = v.stdout.splitlines()
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as ex:
        rtl = list(ex.map(lambda s: verilator(args.root, s[0], s[1]), sets))
    fails = 0
    legal = 0
    for (top, params), m, (rc, out) in zip(sets, model, rtl):
        model_ok = m == "legal"
        rtl_ok = rc == 0
        legal += model_ok
        tag = "ok  " if model_ok == rtl_ok else "FAIL"
        what = "legal" if rtl_ok else "rejected"
        print(
            f"{tag} {top} {' '.join(f'{k}={v}' for k, v in params) or '(defaults)'}: "
            f"RTL {what}, model {m}"
        )
        if model_ok != rtl_ok:
            fails += 1
            print("     " + "\n     ".join(l for l in out.splitlines() if l.startswith("%"))[:1500])
    print(
        f"{len(sets)} random parameter sets: {legal} legal, {len(sets) - legal} illegal by the "
        f"model; {fails} disagreements"
    )
    if fails:
        return 1
    if min(legal, len(sets) - legal) < len(sets) // 4:
        print("param_checks: the random sets do not mix legal and illegal enough to test both ways")
        return 1
    return 0


def illegal(args):
    rows = read_table(os.path.join(args.root, "tb", "lint", "illegal_params.txt"))
    msgs = rule_messages(args.root)
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as ex:
        controls = list(ex.map(lambda t: check_legal(args.root, t), TOPS + SHELLS))
        tools = [
            TOOL_NAMES if args.tools == "all" else (TOOL_NAMES[k % len(TOOL_NAMES)],)
            for k in range(len(rows))
        ]
        results = list(
            ex.map(lambda rt: check_illegal(args.root, rt[0], msgs, rt[1]), zip(rows, tools))
        )
    fails = [f for c in controls for f in c]
    for row, t, r in zip(rows, tools, results):
        print(
            f"{'ok  ' if not r else 'FAIL'} {row[1]} {row[2]}.{row[3]} = {row[4]}: "
            f"{' '.join(f'{k}={v}' for k, v in row[5])} ({', '.join(t)})"
        )
        fails += r
    for f in fails:
        print(f)
    print(
        f"{len(rows)} illegal configurations, each rejected with its rule by "
        f"{'verilator, iverilog and yosys' if args.tools == 'all' else 'one tool in turn'}: "
        f"{len(rows) - sum(1 for r in results if r)} passed, "
        f"{sum(1 for r in results if r)} failed; defaults of {', '.join(TOPS + SHELLS)} accepted: "
        f"{'yes' if not any(controls) else 'NO'}"
    )
    return 1 if fails else 0


def main():
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("mode", choices=("illegal", "agree"))
    ap.add_argument(
        "--root",
        default=os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
    )
    ap.add_argument("--validator", help="build/tb/acore_validate_params (agree)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--tools", choices=("all", "rotate"), default="all")
    ap.add_argument("--sets", type=int, default=48)
    ap.add_argument("--seed", type=int, default=11)
    try:
        args = ap.parse_args()
    except SystemExit as e:
        return 0 if e.code == 0 else 2
    try:
        if args.mode == "agree":
            if not args.validator:
                raise Usage("agree needs --validator BIN")
            return agree(args)
        return illegal(args)
    except (Usage, registry.RegistryError) as e:
        print(f"param_checks: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
