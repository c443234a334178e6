#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Self-calibration through the CLI (docs/calibration.md, self-calibration): `calibrate --reference
# none` on a simulated recording with a slow speed change (the image says zero_reference=none,
# `estimate` judges about the mean and says so, within 1.5x the reference calibration), on a real
# TDK ring without t (equally spaced samples), and every refusal with its reason (exit 2).
# usage: cli_selfcal.sh ANGLECORE SOURCE_DIR
set -u
bin=$1
src=$2
# shellcheck source=lib_cli.sh
source "$(dirname "$0")/lib_cli.sh"
jget() { /usr/bin/python3 -c "import json, sys; d = json.load(open(sys.argv[1]))
for k in sys.argv[2].split('.'): d = d[k]
print(d)" "$1" "$2"; }
within() { /usr/bin/python3 -c "import sys; a, b, f = map(float, sys.argv[1:]); sys.exit(0 if a <= f * b else 1)" "$@"; }

# A TMR-like sensor over 3 turns with a random slow +-10 % speed change; a second seed to validate.
check sim_cal 0 "$bin" simulate --scenario tmr --turns 3.05 --speed-drift 10 --samples 6246 --seed 3 --out "$tmp/cal.csv"
check sim_val 0 "$bin" simulate --scenario tmr --turns 3.05 --speed-drift 10 --samples 6246 --seed 4 --out "$tmp/val.csv"
check self_cal 0 "$bin" calibrate --reference none --in "$tmp/cal.csv" --out "$tmp/self.hex" --json "$tmp/self.json"
expect_text header_zero_reference "$tmp/self.hex" "// acore: zero_reference=none"
expect_eq json_reference "$(jget "$tmp/self.json" reference)" none
expect_eq json_zero_reference "$(jget "$tmp/self.json" zero_reference)" none
expect_eq json_about_mean "$(jget "$tmp/self.json" fit_error_deg.about_mean)" True
check json_profile 0 jget "$tmp/self.json" self_calibration.speed_profile.order
check json_confidence 0 jget "$tmp/self.json" self_calibration.confidence
check ref_cal 0 "$bin" calibrate --in "$tmp/cal.csv" --out "$tmp/ref.hex"
check est_self 0 "$bin" estimate --regs "$tmp/self.hex" --in "$tmp/val.csv" --json "$tmp/es.json"
expect_text est_says_about_mean "$tmp/out" "errors are about their mean"
expect_eq est_json_about_mean "$(jget "$tmp/es.json" about_mean)" True
check est_ref 0 "$bin" estimate --regs "$tmp/ref.hex" --in "$tmp/val.csv" --json "$tmp/er.json"
expect_eq est_ref_not_about_mean "$(jget "$tmp/er.json" about_mean)" False
check ratio_rms 0 within "$(jget "$tmp/es.json" error_deg.rms)" "$(jget "$tmp/er.json" error_deg.rms)" 1.5
check ratio_max 0 within "$(jget "$tmp/es.json" error_deg.max_abs)" "$(jget "$tmp/er.json" error_deg.max_abs)" 1.5

# A real ring without t: equally spaced samples assumed, and said.
check tdk 0 "$bin" calibrate --reference none --in "$src/tests/data/tdk-tas2141-tmr/rise_r08.csv" --out "$tmp/tdk.hex" --json "$tmp/tdk.json"
expect_eq tdk_uniform "$(jget "$tmp/tdk.json" self_calibration.uniform_time)" True
expect_text tdk_assumed "$tmp/out" "assumed: no t column: the samples are taken as equally spaced in time"

# Refusals, exit 2 with the reason.
check short_sim 0 "$bin" simulate --scenario tmr --turns 0.8 --samples 2000 --out "$tmp/short.csv"
check short 2 "$bin" calibrate --reference none --in "$tmp/short.csv" --out "$tmp/x.hex"
expect_text short_why "$tmp/err" "at least one full turn is needed"
cat >"$tmp/rev.json" <<'JSON'
{"channels": 2, "sigma_indep": 0.002, "trajectory": {"kind": "reversal", "sweep_turns": 1.5, "cycles": 1.5}}
JSON
check rev_sim 0 "$bin" simulate --config "$tmp/rev.json" --samples 8192 --out "$tmp/rev.csv"
check reversal 2 "$bin" calibrate --reference none --in "$tmp/rev.csv" --out "$tmp/x.hex"
expect_text reversal_why "$tmp/err" "the shaft turns back"
cat >"$tmp/rip.json" <<'JSON'
{"channels": 2, "sigma_indep": 0.002, "sensor": [{"offset": 0.012}, {"offset": -0.018, "amplitude": 1.035}],
 "trajectory": {"kind": "constant", "turns": 3.05, "speed_ripple_pct": 10, "speed_ripple_cycles": 1.4, "speed_seed": 21}}
JSON
check rip_sim 0 "$bin" simulate --config "$tmp/rip.json" --samples 6246 --seed 21 --out "$tmp/rip.csv"
check ripple 2 "$bin" calibrate --reference none --in "$tmp/rip.csv" --out "$tmp/x.hex"
expect_text ripple_why "$tmp/err" "a speed variation it cannot separate from the sensor's error"
/usr/bin/python3 - "$tmp/cal.csv" "$tmp/badt.csv" <<'PY'
import sys
lines = open(sys.argv[1]).read().splitlines()
rows = [i for i, l in enumerate(lines) if l and not l.startswith("#")]
names = lines[rows[0]].split(",")
ti = names.index("t")
a = lines[rows[101]].split(","); b = lines[rows[100]].split(",")
a[ti] = b[ti]
lines[rows[101]] = ",".join(a)
open(sys.argv[2], "w").write("\n".join(lines) + "\n")
PY
check bad_t 2 "$bin" calibrate --reference none --in "$tmp/badt.csv" --out "$tmp/x.hex"
expect_text bad_t_why "$tmp/err" "column t does not increase at sample 100"
check zero_given 2 "$bin" calibrate --reference none --zero-offset 10 --in "$tmp/cal.csv" --out "$tmp/x.hex"
expect_text zero_given_why "$tmp/err" "the zero is unknown"
check bad_reference 2 "$bin" calibrate --reference encoder --in "$tmp/cal.csv" --out "$tmp/x.hex"

echo "$passes passed, $fails failed"
[ "$fails" -eq 0 ]
