#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks that every model unit has its unit test, in the mirrored folder, registered in the build.

A unit is a .hpp/.cpp pair (or a lone .hpp or .cpp) in a folder of model/ip or model/lab, named by
its basename: model/ip/stages/cordic.{hpp,cpp} is the unit "cordic", and its test is
tests/ip/stages/test_cordic.cpp (tests/<library>/<folder>/ mirrors model/<library>/<folder>/).
Fails (exit 1) when a unit has no test there, when a test file lies in a folder that mirrors no
model folder, when a test file is not listed in ACORE_UNIT_TESTS of tests/CMakeLists.txt (or a
listed test has no file), or when a unit listed below as an exception has a test file after all
(the exception is stale: remove it). A folder may hold tests beyond its units' (a property that
spans units, e.g. test_zero_offset in ip/calibration). The RTL engine (model/rtlsim) is tested by
the co-sim benches of tb/, not here.
usage: check_unit_tests.py [ROOT]
"""

import os
import re
import sys

ROOT = os.path.abspath(
    sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
)
MODEL_DIRS = ["model/ip", "model/lab"]

# Units without a test file of their own, and why. Keep this list short and every reason true.
EXCEPTIONS = {
    "errors": "core/errors.hpp declares the two exception types and nothing else: no behaviour "
    "to test; the exit statuses they select are asserted by every CLI test",
}


def units():
    """unit name -> (mirrored folder 'ip/stages', [its files])."""
    found = {}
    for top in MODEL_DIRS:
        for dp, dn, fn in os.walk(os.path.join(ROOT, top)):
            dn[:] = [d for d in dn if not d.startswith(".")]
            for f in fn:
                stem, ext = os.path.splitext(f)
                if ext in (".hpp", ".cpp"):
                    rel = os.path.relpath(os.path.join(dp, f), ROOT)
                    folder = os.path.relpath(dp, os.path.join(ROOT, "model"))
                    found.setdefault(stem, (folder, []))[1].append(rel)
    return found


def registered():
    with open(os.path.join(ROOT, "tests/CMakeLists.txt")) as f:
        text = re.sub(r"#[^\n]*", "", f.read())
    m = re.search(r"set\(\s*ACORE_UNIT_TESTS\s+([^)]*)\)", text)
    if not m:
        sys.exit("check_unit_tests: tests/CMakeLists.txt has no set(ACORE_UNIT_TESTS ...) list")
    return m.group(1).split()


def test_files():
    """'ip/stages/test_cordic' for every test_*.cpp below tests/ip and tests/lab."""
    out = set()
    for top in MODEL_DIRS:
        lib = os.path.basename(top)
        for dp, _dn, fn in os.walk(os.path.join(ROOT, "tests", lib)):
            for f in fn:
                if f.startswith("test_") and f.endswith(".cpp"):
                    out.add(os.path.relpath(os.path.join(dp, f), os.path.join(ROOT, "tests"))[:-4])
    return out


def main():
    errors = []
    found = units()
    listed = registered()
    tests = test_files()
    model_folders = {folder for folder, _ in found.values()}
    for unit in sorted(found):
        folder, files = found[unit]
        name = f"{folder}/test_{unit}"
        where = ", ".join(sorted(files))
        if unit in EXCEPTIONS:
            if name in tests:
                errors.append(
                    f"{unit}: tests/{name}.cpp exists, remove the stale exception in "
                    f"tests/lint/check_unit_tests.py"
                )
            continue
        if name not in tests:
            errors.append(f"{unit} ({where}): no tests/{name}.cpp")
    for name in sorted(tests):
        if os.path.dirname(name) not in model_folders:
            errors.append(
                f"tests/{name}.cpp: tests/{os.path.dirname(name)}/ mirrors no folder of model/"
            )
    for name in sorted(tests - set(listed)):
        errors.append(f"tests/{name}.cpp is not listed in ACORE_UNIT_TESTS of tests/CMakeLists.txt")
    for name in sorted(set(listed) - tests):
        errors.append(f"ACORE_UNIT_TESTS lists {name}, but tests/{name}.cpp does not exist")
    for unit in sorted(set(EXCEPTIONS) - set(found)):
        errors.append(f"exception '{unit}' names no model unit: remove it")
    for e in errors:
        print("check_unit_tests:", e)
    tested = len([u for u in found if u not in EXCEPTIONS])
    print(
        f"check_unit_tests: {len(found)} units, {tested} with a registered test, "
        f"{len(EXCEPTIONS)} exceptions ({', '.join(sorted(EXCEPTIONS))}); "
        f"{len(errors)} problem(s)"
    )
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
