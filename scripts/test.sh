#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Quick start 2: set up, build, and run every test through CTest (unit, CLI, lint, co-sim).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
jobs=$(nproc 2>/dev/null || echo 2)
cd build
ctest --output-on-failure -j"$jobs" --timeout 900
