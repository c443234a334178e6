#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The Fourier correction through the CLI: calibrate --fourier, the image header, the accuracy on the
# noise-free paper scenario (validation recording), bad usage.
# usage: cli_fourier.sh ANGLECORE SOURCE_DIR
set -u
bin=$1
src=$2
# shellcheck source=lib_cli.sh
source "$(dirname "$0")/lib_cli.sh"

check simulate-cal 0 "$bin" simulate --scenario paper-noiseless --samples 4096 --seed 1 --out "$tmp/cal.csv"
check simulate-val 0 "$bin" simulate --scenario paper-noiseless --samples 5003 --seed 2 --out "$tmp/val.csv"
check calibrate-k21 0 "$bin" calibrate --in "$tmp/cal.csv" --out "$tmp/f21.hex" --correction none --fourier 21 \
  --json "$tmp/cal.json"
expect_text header-k "$tmp/f21.hex" "// acore: fourier_k=21"
expect_text header-m "$tmp/f21.hex" "// acore: fourier_iterations=12"
expect_text last-word "$tmp/f21.hex" "fourier b_21"
expect_text json-fourier "$tmp/cal.json" '"fourier"'
check estimate-k21 0 "$bin" estimate --regs "$tmp/f21.hex" --in "$tmp/val.csv" --engine fixed --json "$tmp/fx.json"
# The Fourier correction's accuracy target, at most 64 words: RMS <= 0.10, max <= 0.35 deg.
/usr/bin/python3 - "$tmp/fx.json" "$tmp/cal.json" <<'PY' || {
import json, sys
e = json.load(open(sys.argv[1]))["error_deg"]
assert e["rms"] <= 0.10 and e["max_abs"] <= 0.35, e
assert json.load(open(sys.argv[2]))["words"] == 63
PY
  echo "FAIL accuracy"
  fails=$((fails + 1))
}
check calibrate-default 0 "$bin" calibrate --in "$tmp/cal.csv" --out "$tmp/plain.hex"
if grep -q fourier "$tmp/plain.hex"; then
  echo "FAIL plain-image: fourier keys without --fourier"
  fails=$((fails + 1))
else passes=$((passes + 1)); fi

check k-too-large 2 "$bin" calibrate --in "$tmp/cal.csv" --out "$tmp/x.hex" --fourier 40
check m-above-k 2 "$bin" calibrate --in "$tmp/cal.csv" --out "$tmp/x.hex" --fourier 4 --fourier-iterations 20
expect_text m-above-k-msg "$tmp/err" "fourier_iterations=20"
# An image whose header claims more harmonics than it has words.
sed 's/fourier_k=21/fourier_k=22/' "$tmp/f21.hex" >"$tmp/bad.hex"
check words-vs-header 2 "$bin" estimate --regs "$tmp/bad.hex" --in "$tmp/val.csv"
expect_text words-vs-header-msg "$tmp/err" "fourier_k=22"

echo "$passes passed, $fails failed"
[ "$fails" -eq 0 ]
