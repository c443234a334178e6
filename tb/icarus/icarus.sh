#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Icarus Verilog runs of the registry lines with the `icarus` flow (rtl/configs.txt) on
# model-generated vectors (two frames): tb/icarus/acore_tb_icarus.v around acore_top (its FOLD) and
# acore_serial_top, tb/icarus/acore_apb_tb_icarus.v around the APB shell (its SERIAL). The benches are
# written for the default widths: a line that sets another parameter is refused.
# usage: icarus.sh GEN_VECTORS_BINARY SOURCE_DIR WORK_DIR
# ACORE_ICARUS_SAMPLES="N0 N1": samples of frames 0 and 1 (default "1001 501": half of frame 0
# paper samples, a turn at 0.72 degree steps, half random and extreme codes. Icarus runs the
# pipelined top at about 150 samples a second; this bench is for X and reset behaviour, the
# Verilator co-sims run far more samples of every build. "2001 1001" takes twice as long, the
# generator's own defaults, "7501 2501", six times).
set -euo pipefail
gen=$1
src=$2
work=$3
mkdir -p "$work"
files=()
while read -r f; do [[ $f =~ \.v$ ]] && files+=("$src/rtl/$f"); done <"$src/rtl/files.f"
mapfile -t lines < <(python3 "$src/scripts/registry.py" --root "$src" lines --flow icarus)
[ ${#lines[@]} -gt 0 ] || {
  echo "icarus.sh: no registry line has the icarus flow"
  exit 1
}
variants=()
for line in "${lines[@]}"; do
  read -r name module _flows params <<<"$line"
  case $module in
    acore_top)
      bench=acore_tb_icarus
      args=(-P "$bench.SERIAL=0")
      ;;
    acore_serial_top)
      bench=acore_tb_icarus
      args=(-P "$bench.SERIAL=1")
      ;;
    acore_apb)
      bench=acore_apb_tb_icarus
      args=()
      ;;
    *)
      echo "icarus.sh: $name: no Icarus bench for module $module"
      exit 1
      ;;
  esac
  for p in $params; do
    case ${p%%=*} in
      SERIAL | FOLD) args+=(-P "$bench.$p") ;;
      *)
        echo "icarus.sh: $name: the bench runs the default widths only ($p)"
        exit 1
        ;;
    esac
  done
  # -I: the modules include rtl/acore_derived.vh and the shell rtl/acore_apb_regs.vh.
  iverilog -g2012 -Wall -Wno-timescale -I "$src/rtl" "${args[@]}" -o "$work/$name.vvp" \
    -s "$bench" "${files[@]}" "$src/tb/icarus/$bench.v"
  variants+=("$name")
done
# The two frames run side by side (each runs every variant in turn): the simulations are
# independent, and Icarus uses one core.
read -r -a samples <<<"${ACORE_ICARUS_SAMPLES:-1001 501}"
run_frame() {
  local frame=$1 v
  mkdir -p "$work/frame$frame"
  "$gen" "$work/frame$frame" "$frame" "${samples[$frame]}"
  for v in "${variants[@]}"; do
    # The bench reads its vectors from the current directory (VEC_DIR = ".").
    (cd "$work/frame$frame" && vvp -n "../$v.vvp" >"log_$v.txt" 2>&1) || true
  done
}
run_frame 0 &
run_frame 1 &
wait
status=0
for frame in 0 1; do
  for v in "${variants[@]}"; do
    echo "$v frame $frame: $(tail -1 "$work/frame$frame/log_$v.txt")"
    grep -q '^PASS$' "$work/frame$frame/log_$v.txt" || {
      tail -5 "$work/frame$frame/log_$v.txt"
      status=1
    }
  done
done
exit $status
