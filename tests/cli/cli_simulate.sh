#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `anglecore simulate` through the CLI: exit codes (0 ok, 2 bad usage/input), the recording it writes
# (docs/contracts.md, recording file columns and metadata), the JSON summary, --list, --config, --channels, bad configs.
# usage: cli_simulate.sh ANGLECORE SOURCE_DIR
set -u
bin=$1
# shellcheck source=lib_cli.sh
source "$(dirname "$0")/lib_cli.sh"

check help 0 "$bin" simulate --help
expect_text help-scenario "$tmp/out" "--scenario"
check list 0 "$bin" simulate --list
for s in paper paper-indep paper-noiseless ideal tmr; do expect_text "list-$s" "$tmp/out" "$s"; done

# The paper scenario: metadata, header, row count, summary figures (docs/contracts.md, paper scenario).
check paper 0 "$bin" simulate --scenario paper --samples 4096 --seed 7 --out "$tmp/paper.csv" --json "$tmp/paper.json"
expect_text meta-scenario "$tmp/paper.csv" "# scenario=paper"
expect_text meta-seed "$tmp/paper.csv" "# seed=7"
expect_text meta-p "$tmp/paper.csv" "# p=1"
expect_text header "$tmp/paper.csv" "t,theta_ref,c1,c2,c3,c4"
expect_eq rows "$(grep -vc '^#' "$tmp/paper.csv")" 4097
expect_text summary-rms "$tmp/out" "RMS 8.537"
for f in scenario samples seed channels uncorrected_error_deg rms max_abs mean; do
  expect_text "json-$f" "$tmp/paper.json" "\"$f\""
done
# Same seed, same file; another seed, another file.
check paper-again 0 "$bin" simulate --scenario paper --samples 4096 --seed 7 --out "$tmp/paper2.csv"
if cmp -s "$tmp/paper.csv" "$tmp/paper2.csv"; then passes=$((passes + 1)); else
  echo "FAIL deterministic: same seed, different files"
  fails=$((fails + 1))
fi
check paper-seed8 0 "$bin" simulate --scenario paper --samples 4096 --seed 8 --out "$tmp/paper3.csv"
if cmp -s "$tmp/paper.csv" "$tmp/paper3.csv"; then
  echo "FAIL seed: seeds 7 and 8 gave the same file"
  fails=$((fails + 1))
else passes=$((passes + 1)); fi

# Two channels, JSON to stdout, and a config written by --dump-config read back.
check two-channel 0 "$bin" simulate --scenario paper --channels 2 --samples 100 --out "$tmp/two.csv" --json -
expect_text two-header "$tmp/two.csv" "t,theta_ref,sin,cos"
expect_text two-json-stdout "$tmp/out" "\"channels\": 2"
check tmr 0 "$bin" simulate --scenario tmr --samples 512 --out "$tmp/tmr.csv"
expect_text tmr-header "$tmp/tmr.csv" "sin,cos"
check dump 0 "$bin" simulate --scenario paper --dump-config "$tmp/paper_cfg.json"
expect_text dump-field "$tmp/paper_cfg.json" "\"sigma_common\""
check config 0 "$bin" simulate --config "$tmp/paper_cfg.json" --samples 4096 --seed 7 --out "$tmp/cfg.csv"
expect_eq config-same-data "$(grep -v '^#' "$tmp/cfg.csv" | md5sum)" "$(grep -v '^#' "$tmp/paper.csv" | md5sum)"
cat >"$tmp/effects.json" <<'JSON'
{"name": "bench", "trajectory": {"kind": "reversal", "sample_rate_hz": 1000, "cycles": 2},
 "temperature": {"enabled": true, "start_C": 20, "end_C": 60},
 "effects": [{"effect": "hysteresis", "h_rad": 0.01}, {"effect": "drift", "offset_per_C_c1": 0.001},
             {"effect": "quantization", "bits": 12, "full_scale": 2}]}
JSON
check effects 0 "$bin" simulate --config "$tmp/effects.json" --samples 2000 --out "$tmp/eff.csv"
expect_text effects-temp "$tmp/eff.csv" "c4,temp"
expect_text effects-meta "$tmp/eff.csv" "# effects=hysteresis;drift;quantization"

# Bad usage and bad input: exit 2 with a message naming the problem.
check no-scenario 2 "$bin" simulate --samples 10 --out "$tmp/x.csv"
check both 2 "$bin" simulate --scenario paper --config "$tmp/paper_cfg.json" --out "$tmp/x.csv"
check no-out 2 "$bin" simulate --scenario paper
check unknown-scenario 2 "$bin" simulate --scenario nope --out "$tmp/x.csv"
expect_text unknown-scenario-list "$tmp/err" "paper-noiseless"
check zero-samples 2 "$bin" simulate --scenario paper --samples 0 --out "$tmp/x.csv"
check bad-channels 2 "$bin" simulate --scenario paper --channels 3 --out "$tmp/x.csv"
check missing-config 2 "$bin" simulate --config "$tmp/none.json" --out "$tmp/x.csv"
echo '{"trajectory": {"kind": "spin"}}' >"$tmp/bad.json"
check bad-config 2 "$bin" simulate --config "$tmp/bad.json" --out "$tmp/x.csv"
expect_text bad-config-field "$tmp/err" "bad.json: field 'trajectory.kind'"
echo '{"effects": [{"effect": "offset", "offset_c9": 1}]}' >"$tmp/bad2.json"
check bad-effect 2 "$bin" simulate --config "$tmp/bad2.json" --out "$tmp/x.csv"
expect_text bad-effect-field "$tmp/err" "effects[0]"
echo '{"p": ' >"$tmp/bad3.json"
check bad-json 2 "$bin" simulate --config "$tmp/bad3.json" --out "$tmp/x.csv"
check unwritable 2 "$bin" simulate --scenario ideal --samples 10 --out "$tmp/no/such/dir/x.csv"

echo "cli_simulate: $passes passed, $fails failed"
[ "$fails" -eq 0 ]
