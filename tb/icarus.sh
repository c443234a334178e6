#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Icarus Verilog run of tb/acore_tb_icarus.v on model-generated vectors (two frames), for the
# pipelined top, the top folded to 4 clocks a sample (FOLD=4) and the serial core (SERIAL=1), and of
# tb/acore_apb_tb_icarus.v (the APB shell around each top) on the same vectors.
# usage: icarus.sh GEN_VECTORS_BINARY SOURCE_DIR WORK_DIR
set -euo pipefail
gen=$1
src=$2
work=$3
mkdir -p "$work"
files=()
while read -r f; do [[ $f =~ \.v$ ]] && files+=("$src/rtl/$f"); done <"$src/rtl/files.f"
# variant name -> bench and its parameters
declare -A bench=([top]=acore_tb_icarus [fold4]=acore_tb_icarus [serial]=acore_tb_icarus
                  [apb_top]=acore_apb_tb_icarus [apb_serial]=acore_apb_tb_icarus)
declare -A params=([top]="-P acore_tb_icarus.SERIAL=0" [fold4]="-P acore_tb_icarus.SERIAL=0 -P acore_tb_icarus.FOLD=4"
                   [serial]="-P acore_tb_icarus.SERIAL=1" [apb_top]="-P acore_apb_tb_icarus.SERIAL=0"
                   [apb_serial]="-P acore_apb_tb_icarus.SERIAL=1")
variants=(top fold4 serial apb_top apb_serial)
for v in "${variants[@]}"; do
  # shellcheck disable=SC2086
  iverilog -g2012 -Wall -Wno-timescale ${params[$v]} -o "$work/$v.vvp" \
    -s "${bench[$v]}" "${files[@]}" "$src/tb/${bench[$v]}.v"
done
status=0
for frame in 0 1; do
  mkdir -p "$work/frame$frame"
  "$gen" "$work/frame$frame" "$frame"
  for v in "${variants[@]}"; do
    # The bench reads its vectors from the current directory (VEC_DIR = ".").
    (cd "$work/frame$frame" && vvp -n ../$v.vvp >log_$v.txt 2>&1) || true
    tail -3 "$work/frame$frame/log_$v.txt"
    grep -q '^PASS$' "$work/frame$frame/log_$v.txt" || status=1
  done
done
exit $status
