#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The design-space sweep (accuracy half and merge step) through the CLI: two shards together give
# exactly the rows of the unsharded run, the merge refuses a missing shard, the sweep's figures
# agree with calibrate + estimate on the same recordings (a second path through the code), and bad
# grids / shards exit 2 naming the problem.
# usage: cli_sweep.sh ANGLECORE SOURCE_DIR
set -u
bin=$1
src=$2
# shellcheck source=lib_cli.sh
source "$(dirname "$0")/lib_cli.sh"

check sweep-all 0 "$bin" sweep --quick --out "$tmp/all" --jobs 2
check sweep-shard0 0 "$bin" sweep --quick --out "$tmp/sh" --shard 0/2
check sweep-shard1 0 "$bin" sweep --quick --out "$tmp/sh" --shard 1/2 --jobs 2
# Same rows (without the wall time), whichever way the points were split.
rows() { cat "$@" | /usr/bin/python3 -c '
import json, sys
for r in sorted((json.loads(l) for l in sys.stdin), key=lambda r: r["index"]):
    r.pop("seconds"); print(json.dumps(r, sort_keys=True))'; }
expect_eq shards-equal-whole "$(rows "$tmp"/sh/accuracy-*.jsonl)" "$(rows "$tmp"/all/accuracy-0-of-1.jsonl)"
check merge 0 /usr/bin/python3 "$src/scripts/design_space_report.py" "$tmp/sh"
expect_text table-row "$tmp/sh/design_space.md" '`DEGREE=5 REGIONS=8` | 116 |'
expect_text targets "$tmp/sh/design_space.md" "≤ 104 words"
rm "$tmp/sh/accuracy-1-of-2.jsonl"
check merge-missing-shard 1 /usr/bin/python3 "$src/scripts/design_space_report.py" "$tmp/sh"
expect_text merge-names-shard "$tmp/err" "shards [1] of 2 are missing"

# The sweep's DEGREE=3 point against calibrate + estimate of the same scenario (paper-noiseless):
# the sweep validates at other angles than it calibrates, estimate here on the calibration angles of
# a 4096-sample turn, so compare loosely: both must show the paper budget's ~0.52 deg RMS.
check simulate 0 "$bin" simulate --scenario paper-noiseless --samples 8192 --seed 1 --out "$tmp/cal.csv"
check calibrate 0 "$bin" calibrate --in "$tmp/cal.csv" --out "$tmp/regs.hex"
check estimate 0 "$bin" estimate --regs "$tmp/regs.hex" --in "$tmp/cal.csv" --engine fixed --json "$tmp/fx.json"
/usr/bin/python3 - "$tmp/all/accuracy-0-of-1.jsonl" "$tmp/fx.json" <<'PY' || {
import json, sys
rows = [json.loads(l) for l in open(sys.argv[1])]
sweep = next(r for r in rows if r["params"] == "DEGREE=3 REGIONS=4")["accuracy"]["paper-noiseless"]["fixed"]
est = json.load(open(sys.argv[2]))["error_deg"]
assert abs(sweep["rms"] - est["rms"]) < 0.01 * est["rms"] + 0.002, (sweep, est)
assert abs(sweep["max_abs"] - est["max_abs"]) < 0.05 * est["max_abs"], (sweep, est)
PY
  echo "FAIL sweep-vs-estimate"
  fails=$((fails + 1))
}

# Bad usage: exit 2 and a message naming the problem.
check bad-shard 2 "$bin" sweep --quick --out "$tmp/x" --shard 2/2
expect_text bad-shard-msg "$tmp/err" "--shard '2/2'"
echo '[{"DEGREE": [3, "x"]}]' >"$tmp/g1.json"
check bad-grid-value 2 "$bin" sweep --grid "$tmp/g1.json" --out "$tmp/x"
expect_text bad-grid-value-msg "$tmp/err" "sub-grid 0 field DEGREE"
echo '[{"DEGREE": [9]}]' >"$tmp/g2.json"
check bad-grid-config 2 "$bin" sweep --grid "$tmp/g2.json" --out "$tmp/x"
expect_text bad-grid-config-msg "$tmp/err" "degree=9 must be 1..7"
echo '[{"NOPE": [1]}]' >"$tmp/g3.json"
check bad-grid-name 2 "$bin" sweep --grid "$tmp/g3.json" --out "$tmp/x"
expect_text bad-grid-name-msg "$tmp/err" "RTL parameter 'NOPE' is unknown"
echo '[{"DEGREE": [3]' >"$tmp/g4.json"
check bad-grid-json 2 "$bin" sweep --grid "$tmp/g4.json" --out "$tmp/x"
expect_text bad-grid-json-msg "$tmp/err" "g4.json:1: not valid JSON"
echo "$passes passed, $fails failed"
[ "$fails" -eq 0 ]
