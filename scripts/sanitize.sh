#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The unit, CLI and fuzz tests under AddressSanitizer + UBSan (CTest label sanitize): builds
# build-san/ (-DACORE_SANITIZE=ON, the model and the CLI without the Verilated RTL), then runs
#   ctest -L sanitize
# there. Any ASan or UBSan report stops its test (-fno-sanitize-recover=all) and fails it.
#   scripts/sanitize.sh [ctest arguments ...]     e.g. -R test_recording
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# -O1 -g1 (line tables): what ASan recommends, and the cheapest build whose reports name lines.
cmake -S . -B build-san -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DACORE_SANITIZE=ON \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1" -DACORE_WITH_RTL=OFF "${launcher[@]}" >/dev/null
cmake --build build-san -j"$jobs"
cd build-san
# Leaks are errors too; a report names the test and the source line.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest -L sanitize --output-on-failure -j"$jobs" --timeout 1800 "$@"
