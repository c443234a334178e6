#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `anglecore diagnose-bench --physics` through the CLI: progress on stderr, the summary and every
# case in JSON, --save recordings that `anglecore diagnose` reruns, --check, and bad usage (exit 2).
# usage: cli_diagnose_physics.sh ANGLECORE SOURCE_DIR
set -u
bin=$1
# shellcheck source=lib_cli.sh
source "$(dirname "$0")/lib_cli.sh"

check help 0 "$bin" diagnose-bench --help
expect_text help-physics "$tmp/out" "--physics"
# Case 7 is placement_c1/hall4 (a Hall plate moved on the ring: phase_error), case 19
# stray_axial/hall4 (a uniform axial field: it cancels in c1 - c3, no_gap), case 29 mux/hall4 (one
# ADC converting the plates in a random slot order: channel_skew), case 32 encoder_zero/tmr2 (the
# reference encoder's zero 20-180 degrees off: zero_offset).
check physics 0 "$bin" diagnose-bench --physics --per-effect 1 --samples 4000 --only 7 19 29 32 \
  --save "$tmp/cases" --json "$tmp/p.json" --check
expect_text physics-met "$tmp/out" "all targets met"
expect_text physics-matrix "$tmp/out" "stray_axial/hall4"
expect_text physics-progress "$tmp/err" "placement_c1/hall4 (phase_error)"
expect_text physics-progress2 "$tmp/err" "[  4/4]"
expect_text physics-mux "$tmp/err" "mux/hall4 (channel_skew) 4ch -> channel_skew"
expect_text physics-encoder-zero "$tmp/err" "encoder_zero/tmr2 (zero_offset) 2ch -> zero_offset"
for f in confusion rows columns top1_accuracy median_holdout_shrink '"case"' '"expected"' moved_on_ring_deg stray_mT; do
  expect_text "physics-json-$f" "$tmp/p.json" "$f"
done
expect_eq physics-saved "$(ls "$tmp/cases" | wc -l | tr -d ' ')" 12
expect_text physics-csv "$tmp/cases/case019_real.csv" "t,theta_ref,c1,c2,c3,c4,temp"
check physics-rerun 0 "$bin" diagnose --sim "$tmp/cases/case019_sim.csv" --real "$tmp/cases/case019_real.csv"
expect_text physics-nogap "$tmp/out" "verdict: no_gap"
check physics-rerun-named 0 "$bin" diagnose --sim "$tmp/cases/case007_sim.csv" \
  --real "$tmp/cases/case007_real.csv" --holdout "$tmp/cases/case007_holdout.csv"
expect_text physics-named "$tmp/out" "phase_error"
# JSON alone on stdout with --json -.
check physics-stdout 0 "$bin" diagnose-bench --physics --per-effect 1 --samples 3000 --only 19 --quiet --json -
expect_text physics-stdout-json "$tmp/out" '"recordings": 1'

check physics-only 2 "$bin" diagnose-bench --physics --per-effect 1 --only 999
expect_text physics-only-msg "$tmp/err" "--only 999"
check physics-samples 2 "$bin" diagnose-bench --physics --samples 100
check physics-zero 2 "$bin" diagnose-bench --physics --per-effect 0

echo "$passes passed, $fails failed"
[ "$fails" -eq 0 ]
