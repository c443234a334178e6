#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The build registry's grammar and the devices table, checked through their one reader.

  check_registry.py ROOT

Feeds scripts/registry.py registries with one malformed line each (a negative-value parameter, which
is legal, a duplicate name, an unknown flow, an unknown tag, a tag whose flow is missing, tags out
of place, a bad parameter, a name ending in a report suffix, ...) in a scratch copy of the
repository's registry files: each malformed one must stop `registry.py lines` and `registry.py
cmake` with exit 2 and the message naming rtl/configs.txt, the line and the field; the legal ones
must come out as written. Then a CMake configuration including cmake/AcoreRegistry.cmake must fail
on a malformed line with that message, and pass on a legal one with the values registry.py gave.
Malformed devices tables stop the reader with synth/devices.toml's line and field; a device's
wrapper, one pattern or a list of them, resolves to the first whose module synth/*.v defines.
Finally the table's capacities against the checked-in place-and-route logs (the tools' own device
databases): every log of a device reports its logic cells, block RAMs and hard multipliers out of
the capacity the table states. Exit 1 on any failure, listing each.
"""

import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(
    sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
)
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import registry

HEAD = "default acore_top sim,formal tags=demo,fast-sim\n"
# (registry text after the first line, what `registry.py lines` prints for it when legal or (line,
# message regex) when malformed)
CASES = [
    ("x acore_top sim,lint R_SHIFT=-1 SCALE_G=-1\n", "x acore_top sim,lint R_SHIFT=-1 SCALE_G=-1"),
    ("x acore_apb lint,pnr,pnr_up5k SERIAL=1\n", "x acore_apb lint,hx8k,up5k SERIAL=1"),
    ("x acore_fold_mul sim tags=test_fold_mul F=2\n", "x acore_fold_mul sim F=2"),
    (
        "x acore_top sim\ny acore_top lint\nx acore_top lint DEGREE=1\n",
        (4, r"name 'x': already on line 2"),
    ),
    (
        "x acore_top sim,pnr2\n",
        (2, r"flows: 'pnr2' is not a flow \(known: sim, lint, icarus, formal, generic"),
    ),
    ("x acore_top sim,hx8k,pnr\n", (2, r"flows: 'hx8k' named twice \(aliases included\)")),
    ("x acore_top sim tags=fast\n", (2, r"tags: 'fast' is not a tag \(known: demo, fast-sim")),
    ("x acore_top sim tags=long-proof\n", (2, r"tags: 'long-proof' needs the formal flow")),
    ("x acore_top lint tags=demo\n", (2, r"tags: 'demo' needs the sim flow")),
    ("x acore_top sim tags=demo,demo\n", (2, r"tags: 'demo' named twice")),
    (
        "x acore_fold_mul sim tags=test_nope\n",
        (2, r"tags: 'test_nope': no bench tb/\*/test_nope.cpp"),
    ),
    ("x acore_top sim DEGREE=1 tags=demo\n", (2, r"tags: 'tags=...' comes right after the flows")),
    ("x acore_top sim DEGREE=x\n", (2, r"parameter 'DEGREE=x' is not PARAM=integer")),
    ("x acore_top sim DEGREE=1 DEGREE=2\n", (2, r"parameter DEGREE set twice")),
    ("x acore_top sim degree=1\n", (2, r"parameter 'degree=1' is not PARAM=integer")),
    (
        "fold2_pnr acore_top sim\n",
        (2, r"name 'fold2_pnr': '_pnr' ends the placed designs' report names"),
    ),
    ("x_up5k acore_top sim\n", (2, r"name 'x_up5k': '_up5k' ends")),
    ("X acore_top sim\n", (2, r"name 'X': lower case letters")),
    ("x acore-top sim\n", (2, r"module 'acore-top' is not a Verilog module name")),
    ("x acore_top\n", (2, r"expected 'name module flows \[tags=T,...\] \[PARAM=value ...\]'")),
    (" x acore_top sim\n", (2, r"expected .* starting in column 1")),
]
FIRST_NOT_DEFAULT = (
    "poly acore_top sim\n",
    (1, r"the first line must be 'default acore_top FLOWS'"),
)
# (devices table edit: old text, new text, message regex)
DEVICE_CASES = [
    (
        'pnr_cell = "ICESTORM_LC"',
        'pnr_cel = "ICESTORM_LC"',
        r"synth/devices.toml:\d+: \[family.ice40\] has no field 'pnr_cell'",
    ),
    (
        'suffix = "_up5k"',
        'suffix = "_pnr"',
        r"synth/devices.toml:\d+: suffix '_pnr': also device hx8k's",
    ),
    (
        'default_device = "hx8k"',
        'default_device = "hx9k"',
        r"synth/devices.toml:\d+: default_device: 'hx9k' is not a device",
    ),
    (
        'family = "ecp5"',
        'family = "xilinx"',
        r"synth/devices.toml:\d+: family: 'xilinx' is not a family with a place",
    ),
    (
        '{ label = "LUT4", count = ["lut"] },\n  { label = "DFF"',
        '{ label = "LUT4", count = ["lut6"] },\n  { label = "DFF"',
        r"synth/devices.toml:\d+: columns: LUT4: 'lut6' is not a cell class of the family",
    ),
    (
        'aliases = ["pnr_up5k"]',
        'aliases = ["pnr"]',
        r"synth/devices.toml:\d+: aliases: 'pnr' is already an alias of device hx8k",
    ),
    (
        "dsp = 8, user_io = 39",
        "dsp = -8, user_io = 39",
        r"synth/devices.toml:\d+: capacity: dsp: expected a count >= 0",
    ),
    ("seed = 1", 'seed = "1"', r"synth/devices.toml:\d+: seed: expected int"),
    (
        'pins = ["52", "3",',
        'pins = ["52", "52",',
        r"synth/devices.toml:\d+: pins: 53 pins, repeated or more than the capacity's user_io",
    ),
    (
        'pins = ["52", "3", "11"',
        'pinz = ["52", "3", "11"',
        r"synth/devices.toml:\d+: \[device.gw1n9\] has no field 'pins'",
    ),
    (
        "constraint_line = 'IO_LOC \"{port}\" {pin};'",
        "constraint_line = 'IO_LOC {port} {pin};'",
        r"synth/devices.toml:\d+: constraint_line: 'IO_LOC \{port\} \{pin\};' must name",
    ),
    (
        'wrapper = ["{module}_sg48wrap", "{module}_pinwrap"]',
        'wrapper = ["{module}_sg48wrap", "acore_pinwrap"]',
        r"synth/devices.toml:\d+: wrapper: 'acore_pinwrap' must contain \{module\}",
    ),
    (
        'wrapper = ["{module}_sg48wrap", "{module}_pinwrap"]',
        "wrapper = []",
        r"synth/devices.toml:\d+: wrapper: an empty list",
    ),
    (
        'wrapper = ["{module}_sg48wrap", "{module}_pinwrap"]',
        'wrapper = ["{module}_sg48wrap", 2]',
        r"synth/devices.toml:\d+: wrapper: expected a list of strings",
    ),
    (
        'wrapper = "{module}_sg48wrap"',
        "wrapper = 1",
        r"synth/devices.toml:\d+: wrapper: expected str or list, got 1",
    ),
]
# (device, module, the wrapper it is placed in; None: as it is): a wrapper of one pattern (hx8k,
# up5k) and a list of them (gw1n9: the SG48 wrapper where synth/*.v has one, else the pin wrapper)
WRAPPER_CASES = [
    ("hx8k", "acore_board", "acore_board_pinwrap"),
    ("up5k", "acore_board", "acore_board_sg48wrap"),
    ("gw1n9", "acore_board", "acore_board_sg48wrap"),
    ("gw1n9", "acore_top", "acore_top_pinwrap"),
    ("gw1n9", "acore_serial_top", "acore_serial_top_pinwrap"),
    ("gw1n9", "acore_track", None),
]

fails = []


def scratch(tmp, registry_text, devices_text=None):
    """A scratch root holding what the reader reads: the registry, the devices table, the benches'
    names (bench tags) and, for CMake, the RTL file list, the readers and cmake/."""
    shutil.rmtree(tmp, ignore_errors=True)
    for d in ("rtl", "synth", "scripts", "cmake", "tb/blocks"):
        os.makedirs(os.path.join(tmp, d), exist_ok=True)
    open(os.path.join(tmp, "rtl", "configs.txt"), "w").write(registry_text)
    shutil.copy(os.path.join(ROOT, "rtl", "files.f"), os.path.join(tmp, "rtl"))
    dt = (
        devices_text
        if devices_text is not None
        else open(os.path.join(ROOT, "synth", "devices.toml")).read()
    )
    open(os.path.join(tmp, "synth", "devices.toml"), "w").write(dt)
    for pcf in glob.glob(os.path.join(ROOT, "synth", "*.pcf")):
        shutil.copy(pcf, os.path.join(tmp, "synth"))
    for f in ("registry.py", "devices.py"):
        shutil.copy(os.path.join(ROOT, "scripts", f), os.path.join(tmp, "scripts"))
    shutil.copy(os.path.join(ROOT, "cmake", "AcoreRegistry.cmake"), os.path.join(tmp, "cmake"))
    for b in glob.glob(os.path.join(ROOT, "tb", "*", "test_*.cpp")):
        open(os.path.join(tmp, "tb", "blocks", os.path.basename(b)), "w").close()


def run_registry(tmp, *args):
    return subprocess.run(
        [sys.executable, os.path.join(tmp, "scripts", "registry.py"), "--root", tmp, *args],
        capture_output=True,
        text=True,
    )


def expect_error(what, p, line, pattern, path="rtl/configs.txt"):
    where = f"{path}:{line}: " if line else ""
    if p.returncode != 2 or not re.search(re.escape(where) + pattern, p.stderr):
        fails.append(
            f"{what}: expected exit 2 and '{where}{pattern}', got exit {p.returncode}: "
            f"{p.stderr.strip()!r}"
        )


def check_lines(tmp):
    for body, bad in [*CASES, FIRST_NOT_DEFAULT]:
        text = body if (body, bad) == FIRST_NOT_DEFAULT else HEAD + body
        scratch(tmp, text)
        what = f"registry line {body.strip()!r}"
        for cmd in (["lines"], ["cmake", os.path.join(tmp, "out.cmake")]):
            p = run_registry(tmp, *cmd)
            if isinstance(bad, tuple):
                expect_error(f"{what} ({cmd[0]})", p, *bad)
            elif p.returncode != 0:
                fails.append(
                    f"{what} ({cmd[0]}): legal, but exit {p.returncode}: {p.stderr.strip()}"
                )
        if isinstance(bad, tuple):
            continue
        out = run_registry(tmp, "lines").stdout.splitlines()
        want = bad
        if out[-1:] != [want]:
            fails.append(f"{what}: `registry.py lines` gave {out[-1:]}, expected [{want!r}]")
        cm = (
            open(os.path.join(tmp, "out.cmake")).read()
            if os.path.exists(os.path.join(tmp, "out.cmake"))
            else ""
        )
        if "R_SHIFT" in body and 'set(ACORE_REG_PARAMS_x "R_SHIFT=-1;SCALE_G=-1")' not in cm:
            fails.append(f"{what}: the CMake file lacks the negative values:\n{cm}")
        if "test_fold_mul" in body and 'set(ACORE_REG_TAGGED_test_fold_mul "x")' not in cm:
            fails.append(f"{what}: the CMake file lacks the bench tag:\n{cm}")


def check_cmake(tmp):
    """A configuration including cmake/AcoreRegistry.cmake fails on a malformed line with the
    reader's message and passes on a legal one with its values."""
    cmake = shutil.which("cmake")
    if not cmake:
        fails.append("cmake not found")
        return
    for body, bad in (
        ("x acore_top sim tags=fast\n", (2, r"tags: 'fast' is not a tag")),
        ("x acore_top sim,lint R_SHIFT=-1\n", None),
    ):
        scratch(tmp, HEAD + body)
        open(os.path.join(tmp, "CMakeLists.txt"), "w").write(
            "cmake_minimum_required(VERSION 3.22)\nproject(registry_check NONE)\n"
            "include(cmake/AcoreRegistry.cmake)\n"
            'message(STATUS "params of x: ${ACORE_REG_PARAMS_x}; tagged demo: '
            '${ACORE_REG_TAGGED_demo}")\n'
        )
        p = subprocess.run(
            [cmake, "-S", tmp, "-B", os.path.join(tmp, "build")], capture_output=True, text=True
        )
        if bad:
            if p.returncode == 0 or not re.search(r"rtl/configs.txt:2: " + bad[1], p.stderr):
                fails.append(
                    f"cmake on {body.strip()!r}: expected a failed configuration naming "
                    f"rtl/configs.txt:2, got exit {p.returncode}:\n{p.stderr[-1500:]}"
                )
        elif p.returncode != 0 or "params of x: R_SHIFT=-1; tagged demo: default" not in p.stdout:
            fails.append(
                f"cmake on {body.strip()!r}: expected the line's values, got exit {p.returncode}:\n"
                f"{p.stdout[-1000:]}{p.stderr[-1000:]}"
            )


def check_devices(tmp):
    base = open(os.path.join(ROOT, "synth", "devices.toml")).read()
    for old, new, pattern in DEVICE_CASES:
        if old not in base:
            fails.append(f"devices case: '{old}' is not in synth/devices.toml (update the case)")
            continue
        scratch(tmp, HEAD, base.replace(old, new, 1))
        p = run_registry(tmp, "lines")
        if p.returncode != 2 or not re.search(pattern, p.stderr):
            fails.append(
                f"devices table with {new!r}: expected exit 2 and '{pattern}', got exit "
                f"{p.returncode}: {p.stderr.strip()!r}"
            )


def check_wrappers():
    for dev, module, want in WRAPPER_CASES:
        w, src = registry.pin_wrapper(ROOT, module, dev)
        if w != want or (src is None) != (want is None):
            fails.append(f"{module} on {dev}: wrapper {w} ({src}), expected {want}")


def check_capacities():
    """Every checked-in log of a device counts its logic cells, block RAMs and DSPs out of the
    table's capacity (nextpnr's device database against the datasheet's figures)."""
    table = registry.table(ROOT)
    seen = 0
    for d in registry.synth_designs(ROOT):
        for f in d.flows:
            dev = table.devices.get(f)
            log = registry.report(ROOT, f, d.name) if dev else None
            if not log or not os.path.exists(log):
                continue
            text = open(log).read()
            seen += 1
            if text.startswith("Info: not placed:"):
                # More ports than the package's free pins (scripts/registry.py pins_log): the pins
                # it counts are the table's.
                io = registry.pnr_count(log, "USER_IO")
                if not io or io[1] != len(dev.pins) or io[0] <= io[1]:
                    fails.append(
                        f"{os.path.relpath(log, ROOT)}: not placed, but USER_IO {io} is not more "
                        f"port bits than the {len(dev.pins)} pins of synth/devices.toml {dev.name}"
                    )
                continue
            if "Device utilisation" not in text and re.search(r"^ERROR: ", text, re.MULTILINE):
                # The program stopped before counting (the datasheet shows its error): no totals.
                continue
            for key, line in (
                ("logic_cells", dev.family.pnr_cell),
                ("bram_blocks", dev.family.pnr_bram),
                ("dsp", dev.family.pnr_dsp),
            ):
                totals = {int(t) for t in re.findall(rf"{re.escape(line)}:\s+\d+/\s*(\d+)", text)}
                want = {dev.capacity[key]} if dev.capacity[key] or totals else set()
                if totals != want:
                    fails.append(
                        f"{os.path.relpath(log, ROOT)}: {line} out of {sorted(totals)}, "
                        f"synth/devices.toml {dev.name} capacity {key} = {dev.capacity[key]}"
                    )
    if seen < 10:
        fails.append(f"only {seen} place-and-route logs found in synth/reports")
    return seen


def check_header():
    """The registry's header documents every tag the reader knows."""
    head = "".join(l for l in open(registry.registry_path(ROOT)) if l.startswith("#"))
    for t in [*list(registry.TAGS), "test_<bench>"]:
        if not re.search(r"^#\s+" + re.escape(t) + r"\s", head, re.MULTILINE):
            fails.append(f"rtl/configs.txt: the header does not document the tag {t}")


def main():
    with tempfile.TemporaryDirectory(prefix="acore_registry_") as tmp:
        work = os.path.join(tmp, "root")
        check_lines(work)
        check_cmake(work)
        check_devices(work)
    check_wrappers()
    logs = check_capacities()
    check_header()
    for f in fails:
        print("FAIL", f)
    n = len(CASES) + 1 + 2 + len(DEVICE_CASES)
    print(
        f"{n} registry and devices-table cases, {len(WRAPPER_CASES)} wrapper cases, {logs} "
        f"place-and-route logs against the capacities: {len(fails)} failure(s)"
    )
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
