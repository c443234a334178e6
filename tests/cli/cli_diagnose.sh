#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `anglecore diagnose` and `anglecore diagnose-bench` through the CLI: exit codes (0 ok, 2 bad
# usage/input, 1 a failed check), the docs/contracts.md, command line JSON fields, and bad input: channel
# sets that differ, too few samples, less than one turn, no theta_ref; and a real recording whose
# every channel is constant.
# usage: cli_diagnose.sh ANGLECORE SOURCE_DIR
set -u
bin=$1
# shellcheck source=lib_cli.sh
source "$(dirname "$0")/lib_cli.sh"

# A two-channel sensor model (sim: constant speed) and the same sensor with an extra offset on sin
# (real, holdout: a speed ramp through a reversal, a temperature ramp).
scenario() { # scenario TRAJECTORY EFFECTS
  cat <<JSON
{"channels": 2, "sigma_indep": 0.002,
 "sensor": [{"amplitude": 1, "offset": 0.01, "AF": [0, 0.01], "BF": [0, 0, 0.01]}, {"amplitude": 1.02}],
 "trajectory": $1, "temperature": {"enabled": true, "start_C": 20, "end_C": 60}, "effects": $2}
JSON
}
scenario '{"kind": "constant", "turns": 3, "sample_rate_hz": 4000}' '[]' >"$tmp/sim.json"
scenario '{"kind": "ramp", "speed_rps": 4, "speed_end_rps": -6, "sample_rate_hz": 4000}' \
  '[{"effect": "offset", "offset_sin": 0.03}]' >"$tmp/real.json"
scenario '{"kind": "constant", "turns": 0.5, "sample_rate_hz": 4000}' '[]' >"$tmp/part.json"
check sim 0 "$bin" simulate --config "$tmp/sim.json" --samples 8000 --seed 1 --out "$tmp/sim.csv"
check real 0 "$bin" simulate --config "$tmp/real.json" --samples 8000 --seed 2 --out "$tmp/real.csv"
check hold 0 "$bin" simulate --config "$tmp/real.json" --samples 8000 --seed 3 --out "$tmp/hold.csv"

check help 0 "$bin" diagnose --help
check good 0 "$bin" diagnose --sim "$tmp/sim.csv" --real "$tmp/real.csv" --holdout "$tmp/hold.csv" --json "$tmp/d.json"
expect_text verdict "$tmp/out" "verdict: explained"
expect_text named "$tmp/d.json" '"effect": "offset"'
for f in gap holdout before_deg after_deg where stage domain channels angle_harmonics ranking effect params explained; do
  expect_text "json-$f" "$tmp/d.json" "\"$f\""
done
# The offset is named first and recovered (0.03 on sin).
first=$(grep -m1 '"effect"' "$tmp/d.json" | tr -d ' ",' | cut -d: -f2)
expect_eq first-effect "$first" offset

# The vocabulary through files: a constant angle shift written in the scenario (zero_offset) is
# named zero_offset, not a delay or hysteresis (the ramp changes speed and reverses).
scenario '{"kind": "ramp", "speed_rps": 4, "speed_end_rps": -6, "sample_rate_hz": 4000}' \
  '[{"effect": "zero_offset", "zero_rad": 0.02}]' >"$tmp/zero.json"
check zero-sim 0 "$bin" simulate --config "$tmp/zero.json" --samples 8000 --seed 4 --out "$tmp/zero.csv"
check zero 0 "$bin" diagnose --sim "$tmp/sim.csv" --real "$tmp/zero.csv" --json "$tmp/z.json"
first=$(grep -m1 '"effect"' "$tmp/z.json" | tr -d ' ",' | cut -d: -f2)
expect_eq zero-first "$first" zero_offset

# Bad input, exit 2 with a message that says what is wrong.
scenario '{"kind": "constant", "turns": 3}' '[{"effect": "amplitude", "scale": 0}]' >"$tmp/bad-scale.json"
check bad-scale 2 "$bin" simulate --config "$tmp/bad-scale.json" --samples 100 --out "$tmp/x.csv"
expect_text bad-scale-msg "$tmp/err" "effects[0]"
scenario '{"kind": "constant", "turns": 3}' '[{"effect": "channel_skew", "tau_c1": 1e-4}]' >"$tmp/bad-tau.json"
check bad-tau 2 "$bin" simulate --config "$tmp/bad-tau.json" --samples 100 --out "$tmp/x.csv"
expect_text bad-tau-msg "$tmp/err" "tau_sin, tau_cos"
check sim4 0 "$bin" simulate --scenario paper --samples 4096 --out "$tmp/sim4.csv"
check channels 2 "$bin" diagnose --sim "$tmp/sim4.csv" --real "$tmp/real.csv"
expect_text channels-msg "$tmp/err" "channel sets differ"
check few-sim 0 "$bin" simulate --config "$tmp/real.json" --samples 100 --out "$tmp/few.csv"
check few 2 "$bin" diagnose --sim "$tmp/sim.csv" --real "$tmp/few.csv"
expect_text few-msg "$tmp/err" "samples, at least"
check part-sim 0 "$bin" simulate --config "$tmp/part.json" --samples 8000 --out "$tmp/part.csv"
check part 2 "$bin" diagnose --sim "$tmp/sim.csv" --real "$tmp/part.csv"
expect_text part-msg "$tmp/err" "full turn"
awk -F, 'BEGIN { OFS = "," } /^#/ { print; next } { $2 = ""; sub(/,,/, ","); print }' "$tmp/real.csv" >"$tmp/noref.csv"
expect_text noref-header "$tmp/noref.csv" "t,sin,cos"
check noref 2 "$bin" diagnose --sim "$tmp/sim.csv" --real "$tmp/noref.csv"
expect_text noref-msg "$tmp/err" "theta_ref"
check noref-sim 2 "$bin" diagnose --sim "$tmp/noref.csv" --real "$tmp/real.csv"
awk -F, 'BEGIN { OFS = "," } /^#/ || /^t,/ { print; next } { $3 = "0.5"; $4 = "-0.25"; print }' "$tmp/real.csv" >"$tmp/flat.csv"
check flat 2 "$bin" diagnose --sim "$tmp/sim.csv" --real "$tmp/flat.csv"
expect_text flat-msg "$tmp/err" "constant"
check missing 2 "$bin" diagnose --sim "$tmp/nope.csv" --real "$tmp/real.csv"
check no-real 2 "$bin" diagnose --sim "$tmp/sim.csv"

# diagnose-bench: two cases of a small run, their recordings saved, the summary in JSON.
check bench 0 "$bin" diagnose-bench --per-effect 1 --samples 4000 --only 0 14 --save "$tmp/cases" --json "$tmp/b.json" --check
expect_text bench-met "$tmp/out" "all targets met"
expect_text bench-matrix "$tmp/out" "confusion matrix"
for f in confusion top1_accuracy median_holdout_shrink confident_wrong recovery; do expect_text "bench-$f" "$tmp/b.json" "\"$f\""; done
expect_eq bench-saved "$(ls "$tmp/cases" | wc -l | tr -d ' ')" 6
check bench-rerun 0 "$bin" diagnose --sim "$tmp/cases/case014_sim.csv" --real "$tmp/cases/case014_real.csv"
expect_text bench-none "$tmp/out" "verdict: no_gap"
check bench-zero 2 "$bin" diagnose-bench --per-effect 0
check bench-only 2 "$bin" diagnose-bench --per-effect 1 --only 16
check bench-samples 2 "$bin" diagnose-bench --samples 10

echo "$passes passed, $fails failed"
[ "$fails" -eq 0 ]
