#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Icarus Verilog run of tb/acore_tb_icarus.v on model-generated vectors (two frames), for the
# pipelined top and for the serial core (SERIAL=1), and of tb/acore_apb_tb_icarus.v (the APB shell
# around each top) on the same vectors.
# usage: icarus.sh GEN_VECTORS_BINARY SOURCE_DIR WORK_DIR
set -euo pipefail
gen=$1
src=$2
work=$3
mkdir -p "$work"
files=()
while read -r f; do [[ $f =~ \.v$ ]] && files+=("$src/rtl/$f"); done <"$src/rtl/files.f"
for serial in 0 1; do
  iverilog -g2012 -Wall -Wno-timescale -P acore_tb_icarus.SERIAL=$serial -o "$work/acore_tb_icarus_$serial.vvp" \
    -s acore_tb_icarus "${files[@]}" "$src/tb/acore_tb_icarus.v"
  iverilog -g2012 -Wall -Wno-timescale -P acore_apb_tb_icarus.SERIAL=$serial -o "$work/acore_apb_tb_icarus_$serial.vvp" \
    -s acore_apb_tb_icarus "${files[@]}" "$src/tb/acore_apb_tb_icarus.v"
done
status=0
for frame in 0 1; do
  mkdir -p "$work/frame$frame"
  "$gen" "$work/frame$frame" "$frame"
  for serial in 0 1; do
    # The bench reads its vectors from the current directory (VEC_DIR = ".").
    (cd "$work/frame$frame" && vvp -n ../acore_tb_icarus_$serial.vvp >log_$serial.txt 2>&1) || true
    tail -3 "$work/frame$frame/log_$serial.txt"
    grep -q '^PASS$' "$work/frame$frame/log_$serial.txt" || status=1
    (cd "$work/frame$frame" && vvp -n ../acore_apb_tb_icarus_$serial.vvp >log_apb_$serial.txt 2>&1) || true
    tail -3 "$work/frame$frame/log_apb_$serial.txt"
    grep -q '^PASS$' "$work/frame$frame/log_apb_$serial.txt" || status=1
  done
done
exit $status
