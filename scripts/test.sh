#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Quick start 2: set up, build, and run every test through CTest (unit, CLI, lint, co-sim), then,
# when the run so far took less than ACORE_SANITIZE_BUDGET seconds (default 800), the unit, CLI
# and fuzz tests again under ASan + UBSan (scripts/sanitize.sh, CTest label sanitize).
# ACORE_SANITIZE_BUDGET=0 skips that second run; a large value always makes it. 800 s because the
# second run (its own cold build and 357 tests) takes about 0.78 times the main run: 903 s after a
# 1162 s main run on 2 cores; after at most 800 s the whole stays under 25 minutes.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
./scripts/build.sh
jobs=$(nproc 2>/dev/null || echo 2)
(cd build && ctest --output-on-failure -j"$jobs" --timeout 900)
elapsed=$(($(date +%s) - start))
budget=${ACORE_SANITIZE_BUDGET:-800}
if [ "$elapsed" -lt "$budget" ]; then
  echo "test.sh: main run took ${elapsed} s (< ${budget} s): the sanitizer run follows"
  ./scripts/sanitize.sh
else
  echo "test.sh: main run took ${elapsed} s (>= ACORE_SANITIZE_BUDGET=${budget} s): sanitizer run skipped (scripts/sanitize.sh runs it)"
fi
