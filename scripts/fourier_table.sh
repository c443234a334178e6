#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The Fourier-correction table of docs/accuracy.md (docs/reports/fourier_table.md): noise-free paper scenario, calibrated on one
# recording (4096 samples) and measured on a separate validation recording (5003 samples, so every
# validation angle lies between calibration angles), float and bit-accurate engines, for polynomial
# degree 0 (no polynomial: --correction none) and 1..3 (4 regions) against the harmonics K. Prints a
# Markdown table.
#   scripts/fourier_table.sh [build/anglecore] [out dir]   (about a minute)
set -euo pipefail
bin=${1:-build/anglecore}
out=${2:-out/fourier_table}
mkdir -p "$out"
"$bin" simulate --scenario paper-noiseless --samples 4096 --seed 1 --out "$out/cal.csv" >/dev/null
"$bin" simulate --scenario paper-noiseless --samples 5003 --seed 2 --out "$out/val.csv" >/dev/null
field() { /usr/bin/python3 -c "import json,sys; j=json.load(open(sys.argv[1])); print('%.4f' % j['error_deg'][sys.argv[2]])" "$@"; }
echo "| degree | K | words | float RMS ° | float max ° | bit-accurate RMS ° | bit-accurate max ° |"
echo "|---|---|---|---|---|---|---|"
for degree in 0 1 2 3; do
  for k in ${FOURIER_TABLE_K:-0 4 8 13 16 20 21}; do
    args=(--degree "$degree")
    [ "$degree" = 0 ] && args=(--correction none)
    [ "$k" != 0 ] && args+=(--fourier "$k")
    img="$out/d${degree}_k$k.hex"
    "$bin" calibrate --in "$out/cal.csv" --out "$img" "${args[@]}" --json "$out/d${degree}_k$k.cal.json" >/dev/null
    "$bin" estimate --regs "$img" --in "$out/val.csv" --engine float --json "$out/d${degree}_k$k.float.json" >/dev/null
    "$bin" estimate --regs "$img" --in "$out/val.csv" --engine fixed --json "$out/d${degree}_k$k.fixed.json" >/dev/null
    words=$(/usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['words'])" "$out/d${degree}_k$k.cal.json")
    echo "| $degree | $k | $words | $(field "$out/d${degree}_k$k.float.json" rms) | $(field "$out/d${degree}_k$k.float.json" max_abs)" \
      "| $(field "$out/d${degree}_k$k.fixed.json" rms) | $(field "$out/d${degree}_k$k.fixed.json" max_abs) |"
  done
done
