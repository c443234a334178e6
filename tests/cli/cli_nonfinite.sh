#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# NaN and infinity, spelled every way a file or a flag can carry them, through every subcommand
# that reads input: each is refused with exit 2 and a message naming the file, line and field (a
# parser that lets one through would otherwise report "error RMS nan" and exit 0).
# usage: cli_nonfinite.sh ANGLECORE SOURCE_DIR
set -u
bin=$1
# shellcheck source=lib_cli.sh
source "$(dirname "$0")/lib_cli.sh"

check simulate-4 0 "$bin" simulate --scenario paper --samples 1024 --seed 1 --out "$tmp/cal.csv"
check simulate-2 0 "$bin" simulate --scenario tmr --samples 1024 --seed 1 --out "$tmp/tmr.csv"
check calibrate 0 "$bin" calibrate --in "$tmp/cal.csv" --out "$tmp/regs.hex"
# put FILE_IN COLUMN VALUE FILE_OUT: VALUE in COLUMN of the 8th data row (line 8 + header lines).
put() {
  awk -F, -v col="$2" -v val="$3" 'BEGIN { OFS = "," }
    /^#/ { print; next }
    !hdr { for (i = 1; i <= NF; ++i) if ($i == col) c = i; hdr = 1; print; next }
    { if (++row == 8) { $c = val; line = NR } print }
    END { print line > "/dev/stderr" }' "$1" >"$4" 2>"$4.line"
}
n=0
for value in nan NaN -nan inf -Inf INF infinity 1e999 -1e999; do
  for col in t theta_ref c1 c2 c3 c4; do
    n=$((n + 1))
    put "$tmp/cal.csv" "$col" "$value" "$tmp/bad$n.csv"
    line=$(cat "$tmp/bad$n.csv.line")
    check "estimate-$col-$value" 2 "$bin" estimate --regs "$tmp/regs.hex" --in "$tmp/bad$n.csv" --engine fixed
    expect_text "estimate-$col-$value-msg" "$tmp/err" "bad$n.csv:$line: column '$col'"
  done
done
# Every subcommand that reads a recording, each input position, two- and four-channel files.
put "$tmp/cal.csv" c3 nan "$tmp/c3.csv"
put "$tmp/tmr.csv" cos inf "$tmp/cos.csv"
put "$tmp/cal.csv" theta_ref -inf "$tmp/ref.csv"
subs=("calibrate --out $tmp/x.hex --in" "estimate --regs $tmp/regs.hex --engine float --in"
  "diagnose --sim $tmp/cal.csv --real" "diagnose --real $tmp/cal.csv --sim"
  "diagnose --sim $tmp/cal.csv --real $tmp/cal.csv --holdout")
# cosim exists only in a build with the Verilated RTL.
have_cosim=0
"$bin" --help | grep -qw cosim && have_cosim=1
[ "$have_cosim" = 1 ] && subs+=("cosim --regs $tmp/regs.hex --in")
for sub in "${subs[@]}"; do
  name=${sub%% *}
  # shellcheck disable=SC2086
  check "$name-c3-nan" 2 "$bin" $sub "$tmp/c3.csv"
  expect_text "$name-c3-nan-msg" "$tmp/err" "c3.csv:$(cat "$tmp/c3.csv.line"): column 'c3'"
  # shellcheck disable=SC2086
  check "$name-theta_ref-inf" 2 "$bin" $sub "$tmp/ref.csv"
  expect_text "$name-theta_ref-inf-msg" "$tmp/err" "column 'theta_ref'"
done
check calibrate-cos-inf 2 "$bin" calibrate --in "$tmp/cos.csv" --out "$tmp/x.hex"
expect_text calibrate-cos-inf-msg "$tmp/err" "cos.csv:$(cat "$tmp/cos.csv.line"): column 'cos'"
# Register image header values (the crc32 line covers the words, not the header).
for key in in_scale zero_offset_rad; do
  for value in nan inf -inf 1e999; do
    sed -e "s/^\/\/ acore: $key=.*/\/\/ acore: $key=$value/" "$tmp/regs.hex" >"$tmp/img.hex"
    grep -q "acore: $key=" "$tmp/img.hex" || echo "// acore: $key=$value" >>"$tmp/img.hex"
    check "image-$key-$value" 2 "$bin" estimate --regs "$tmp/img.hex" --in "$tmp/cal.csv"
    expect_text "image-$key-$value-msg" "$tmp/err" "header field '$key'"
  done
done
# JSON inputs: JSON has no NaN literal; an overflowing number is how infinity arrives.
echo '{"p": 1, "A0": 1e999}' >"$tmp/spec.json"
check harmonics-inf 2 "$bin" harmonics --spec "$tmp/spec.json"
expect_text harmonics-inf-msg "$tmp/err" "spec.json:1: not valid JSON: [json.exception.out_of_range.406] number overflow parsing '1e999'"
echo '{"p": 1, "A0": NaN}' >"$tmp/spec.json"
check harmonics-nan 2 "$bin" harmonics --spec "$tmp/spec.json"
echo '[{"DEGREE": [1e999]}]' >"$tmp/grid.json"
check sweep-inf 2 "$bin" sweep --grid "$tmp/grid.json" --list
expect_text sweep-inf-msg "$tmp/err" "grid.json:1: not valid JSON"
"$bin" simulate --scenario paper --dump-config "$tmp/scn.json" >/dev/null
sed -e '0,/"amplitude": 1.0/s//"amplitude": 1e999/' "$tmp/scn.json" >"$tmp/scn_inf.json"
check simulate-config-inf 2 "$bin" simulate --config "$tmp/scn_inf.json" --samples 64 --out "$tmp/s.csv"
expect_text simulate-config-inf-msg "$tmp/err" "scn_inf.json:$(grep -n 1e999 "$tmp/scn_inf.json" | cut -d: -f1): not valid JSON"
# Numeric flags.
check calibrate-in-scale-nan 2 "$bin" calibrate --in "$tmp/cal.csv" --out "$tmp/x.hex" --in-scale nan
check calibrate-in-scale-inf 2 "$bin" calibrate --in "$tmp/cal.csv" --out "$tmp/x.hex" --in-scale inf
check calibrate-zero-offset-nan 2 "$bin" calibrate --in "$tmp/cal.csv" --out "$tmp/x.hex" --zero-offset nan
check calibrate-zero-offset-inf 2 "$bin" calibrate --in "$tmp/cal.csv" --out "$tmp/x.hex" --zero-offset inf
check estimate-track-bandwidth-nan 2 "$bin" estimate --regs "$tmp/regs.hex" --in "$tmp/cal.csv" --track-bandwidth nan
check estimate-track-lead-inf 2 "$bin" estimate --regs "$tmp/regs.hex" --in "$tmp/cal.csv" --track-lead inf
check simulate-speed-nan 2 "$bin" simulate --scenario paper --profile ramp --speed-rpm nan --out "$tmp/s.csv"
expect_text simulate-speed-nan-msg "$tmp/err" "not a finite number"
[ "$have_cosim" = 1 ] && check cosim-backpressure-nan 2 "$bin" cosim --regs "$tmp/regs.hex" --in "$tmp/cal.csv" --backpressure nan
echo "$passes passed, $fails failed ($n recordings with a non-finite value)"
[ "$fails" -eq 0 ]
