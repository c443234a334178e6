#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Quick start 1: set up, build, and run the main job on the built-in paper scenario.
# Writes out/demo/ (report.md, plots, register image, recordings). Extra arguments go to
# `anglecore demo` (see `build/anglecore demo --help`).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh anglecore
exec ./build/anglecore demo "$@"
