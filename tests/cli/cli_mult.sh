#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Hardware multipliers through the CLI (docs/datapath.md "Hardware multipliers (MULT)"):
# `calibrate --mult 1` writes the header key mult=1 (and without it none), the fixed-point engine
# follows the image's rule (the same words read with the other rule give other angles, the same
# accuracy), the serial core runs such an image on its MULT = 1 build (serial_mult, long-sim: where
# it is not built the engine names it and exits 2), and bad values are refused with exit 2.
# usage: cli_mult.sh ANGLECORE SOURCE_DIR
set -u
bin=$1
# shellcheck source=lib_cli.sh
source "$(dirname "$0")/lib_cli.sh"

# rms IN.json: the corrected RMS of an `estimate --json` file.
rms() { /usr/bin/python3 -c "import json, sys; print(json.load(open(sys.argv[1]))['error_deg']['rms'])" "$1"; }
# within A B FACTOR: A <= FACTOR * B
within() { /usr/bin/python3 -c "import sys; a, b, f = map(float, sys.argv[1:]); sys.exit(0 if a <= f * b else 1)" "$@"; }

check simulate-cal 0 "$bin" simulate --scenario paper --samples 4096 --seed 1 --out "$tmp/cal.csv"
check simulate-val 0 "$bin" simulate --scenario paper --samples 4096 --seed 2 --out "$tmp/val.csv"
check calibrate-0 0 "$bin" calibrate --in "$tmp/cal.csv" --out "$tmp/m0.hex"
check calibrate-1 0 "$bin" calibrate --in "$tmp/cal.csv" --out "$tmp/m1.hex" --mult 1 --json "$tmp/m1.json"
expect_text header-mult1 "$tmp/m1.hex" "// acore: mult=1"
expect_text json-mult1 "$tmp/m1.json" '"mult": 1'
if grep -q "mult=" "$tmp/m0.hex"; then
  echo "FAIL header-mult0: an image with MULT = 0 names the key"
  fails=$((fails + 1))
else passes=$((passes + 1)); fi

check estimate-0 0 "$bin" estimate --regs "$tmp/m0.hex" --in "$tmp/val.csv" --json "$tmp/e0.json" --out "$tmp/e0.csv"
check estimate-1 0 "$bin" estimate --regs "$tmp/m1.hex" --in "$tmp/val.csv" --json "$tmp/e1.json" --out "$tmp/e1.csv"
# The same words read with the shift-add rule (the key removed): other angles, so the rule counts.
grep -v "// acore: mult=1" "$tmp/m1.hex" | grep -v "crc32=" >"$tmp/m1as0.hex"
check estimate-1-as-0 0 "$bin" estimate --regs "$tmp/m1as0.hex" --in "$tmp/val.csv" --out "$tmp/e10.csv"
if cmp -s "$tmp/e1.csv" "$tmp/e10.csv"; then
  echo "FAIL rule-counts: the hardware product's rule gives the shift-add rule's angles"
  fails=$((fails + 1))
else passes=$((passes + 1)); fi
# Both rules reach the paper's accuracy alike (within 10 % of each other).
if within "$(rms "$tmp/e1.json")" "$(rms "$tmp/e0.json")" 1.1 && within "$(rms "$tmp/e0.json")" "$(rms "$tmp/e1.json")" 1.1; then
  passes=$((passes + 1))
else
  echo "FAIL accuracy: MULT=1 RMS $(rms "$tmp/e1.json") vs MULT=0 $(rms "$tmp/e0.json")"
  fails=$((fails + 1))
fi

# Bad input: the option's range, the header's value (named by file and field).
check bad-option 2 "$bin" calibrate --in "$tmp/cal.csv" --out "$tmp/x.hex" --mult 2
sed 's|// acore: mult=1|// acore: mult=2|' "$tmp/m1.hex" >"$tmp/bad.hex"
check bad-header 2 "$bin" estimate --regs "$tmp/bad.hex" --in "$tmp/val.csv"
expect_text bad-header-msg "$tmp/err" "mult=2 must be 0 or 1"
expect_text bad-header-where "$tmp/err" "bad.hex"
# The serial core with the hardware product (registry line serial_mult): the fixed engine's angles
# where the build exists, else exit 2 naming the build (a default build Verilates no long-sim line).
if [ "${ACORE_WITH_RTL:-OFF}" = ON ]; then
  if "$bin" estimate --regs "$tmp/m1.hex" --in "$tmp/val.csv" --engine rtl-serial --out "$tmp/s1.csv" \
    2>"$tmp/err"; then
    if cmp -s "$tmp/e1.csv" "$tmp/s1.csv"; then passes=$((passes + 1)); else
      echo "FAIL serial-mult: the serial core's MULT = 1 angles differ from the fixed engine's"
      fails=$((fails + 1))
    fi
  else
    check serial-mult-unbuilt 2 "$bin" estimate --regs "$tmp/m1.hex" --in "$tmp/val.csv" --engine rtl-serial
    expect_text serial-mult-unbuilt-msg "$tmp/err" "serial_mult"
  fi
fi
echo "$passes passed, $fails failed"
[ "$fails" -eq 0 ]
