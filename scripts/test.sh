#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Quick start 2: set up, build, and run every test through CTest (unit, CLI, lint, co-sim), then,
# when the run so far took less than ACORE_SANITIZE_BUDGET seconds (default 900), the unit, CLI
# and fuzz tests again under ASan + UBSan (scripts/sanitize.sh, CTest label sanitize).
# ACORE_SANITIZE_BUDGET=0 skips that second run; a large value always makes it. 900 s: the second
# run (its own build and 330 tests, about 8 minutes cold on 2 cores) then keeps the whole under 25.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
./scripts/build.sh
jobs=$(nproc 2>/dev/null || echo 2)
(cd build && ctest --output-on-failure -j"$jobs" --timeout 900)
elapsed=$(($(date +%s) - start))
budget=${ACORE_SANITIZE_BUDGET:-900}
if [ "$elapsed" -lt "$budget" ]; then
  echo "test.sh: main run took ${elapsed} s (< ${budget} s): the sanitizer run follows"
  ./scripts/sanitize.sh
else
  echo "test.sh: main run took ${elapsed} s (>= ACORE_SANITIZE_BUDGET=${budget} s): sanitizer run skipped (scripts/sanitize.sh runs it)"
fi
