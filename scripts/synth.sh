#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Synthesis reports for AngleCore: writes synth/reports/ (see synth/README.md).
#   generic `synth` cell counts, `synth_ice40` LUT4/DFF/carry/BRAM + nextpnr-ice40 Fmax on an HX8K
#   (ct256), `synth_xilinx` (xc7) LUT/FF/DSP/RAM, for the pipelined top and its stages, the serial
#   core and the 16-bit CORDIC alone, and the summary table synth/reports/summary.md.
# usage: scripts/synth.sh [-j N] [-d DESIGN[,DESIGN...]]
#   -j N  runs N Yosys/nextpnr jobs in parallel (default 1)
#   -d    only these designs (default all: top top_pnr scaler_pnr region_pnr poly_pnr poly2d_pnr
#         poly2d1_pnr cordic_top_pnr cordic16 cordic16_bus serial serial_pnr fourier fourier_pnr
#         top_fold2 top_fold4 top_fold8 top_fold2_pnr top_fold4_pnr top_fold8_pnr apb_serial apb_serial_pnr
#         apb_top apb_none_pnr); their old reports are replaced, the others kept, and the summary is
#         rebuilt from every report present. Example: -d serial,serial_pnr
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=1
only=""
while [ $# -gt 0 ]; do
  case $1 in
    -j) jobs=${2:?-j needs a number}; shift 2 ;;
    -d) only=${2:?-d needs design names}; shift 2 ;;
    *) echo "usage: scripts/synth.sh [-j N] [-d DESIGN[,DESIGN...]]" >&2; exit 2 ;;
  esac
done
syn=$root/synth
build=$syn/build
rep=$syn/reports
mkdir -p "$build" "$rep"
freq=150  # nextpnr target clock, MHz (Fmax is reported whether or not it is met)

# The 16-bit CORDIC configuration (its arctangent table is synth/acore_cordic16_atan.vh, written
# from the model by acore_gen_tables).
declare -A C16
while IFS='=' read -r k v; do [[ $k =~ ^[A-Z_]+$ ]] && C16[$k]=$v; done <"$root/rtl/cordic16.cfg"

rtl_reads=""
while read -r f; do
  [[ $f =~ \.v$ ]] && rtl_reads+="read_verilog -sv $root/rtl/$f"$'\n'
done <"$root/rtl/files.f"

# design name -> top module, extra reads (and chparam), flows (generic, xilinx, ice40, pnr)
declare -A TOP READ FLOWS
TOP[top]=acore_top;                 READ[top]="$rtl_reads"
TOP[top_pnr]=acore_top_pinwrap;     READ[top_pnr]="$rtl_reads"$'\n'"read_verilog -sv $syn/acore_top_pinwrap.v"
stage_reads="$rtl_reads"$'\n'"read_verilog -sv $syn/acore_stage_pinwrap.v"
TOP[scaler_pnr]=acore_scaler_pinwrap;      READ[scaler_pnr]="$stage_reads"
TOP[poly_pnr]=acore_poly_pinwrap;          READ[poly_pnr]="$stage_reads"
TOP[region_pnr]=acore_region_pinwrap;      READ[region_pnr]="$stage_reads"
TOP[cordic_top_pnr]=acore_cordic_top_pinwrap; READ[cordic_top_pnr]="$stage_reads"
TOP[cordic16]=acore_cordic16;       READ[cordic16]="read_verilog -sv -I$syn $root/rtl/acore_check.v $root/rtl/acore_cordic.v $syn/acore_cordic16.v"
c16_chparam="chparam"
for k in IN_W G Z_W ANGLE_W K AT_W NORM SPLIT; do c16_chparam+=" -set $k ${C16[$k]}"; done
TOP[cordic16_bus]=acore_cordic;     READ[cordic16_bus]="read_verilog -sv $root/rtl/acore_check.v $root/rtl/acore_cordic.v"$'\n'"$c16_chparam acore_cordic"
TOP[poly2d_pnr]=acore_poly2d_pinwrap;      READ[poly2d_pnr]="$stage_reads"
TOP[poly2d1_pnr]=acore_poly2d_pinwrap;     READ[poly2d1_pnr]="$stage_reads"$'\n'"chparam -set DEGREE 1 acore_poly2d_pinwrap"
TOP[serial]=acore_serial_top;       READ[serial]="$rtl_reads"
TOP[serial_pnr]=acore_serial_top_pinwrap; READ[serial_pnr]="$rtl_reads"$'\n'"read_verilog -sv $syn/acore_serial_top_pinwrap.v"
# The Fourier correction with 21 harmonics (area), and 4 of them placed in a pin wrapper (Fmax).
TOP[fourier]=acore_fourier_correct; READ[fourier]="$rtl_reads"$'\n'"chparam -set K 21 -set M 12 acore_fourier_correct"
TOP[fourier_pnr]=acore_fourier_pinwrap; READ[fourier_pnr]="$stage_reads"
# The top folded to FOLD = 2, 4, 8 clocks a sample (default configuration): area, and the whole top
# placed and routed in the pin wrapper.
for n in 2 4 8; do
  TOP[top_fold$n]=acore_top;            READ[top_fold$n]="$rtl_reads"$'\n'"chparam -set FOLD $n acore_top"
  TOP[top_fold${n}_pnr]=acore_top_pinwrap
  READ[top_fold${n}_pnr]="$rtl_reads"$'\n'"read_verilog -sv $syn/acore_top_pinwrap.v"$'\n'"chparam -set FOLD $n acore_top_pinwrap"
done
# The APB register shell (rtl/acore_apb.v) around the serial core (area; placed in a wrapper that
# registers the APB signals) and around the default pipelined top (iCE40 area: it does not fit).
TOP[apb_serial]=acore_apb;          READ[apb_serial]="$rtl_reads"$'\n'"chparam -set SERIAL 1 acore_apb"
TOP[apb_serial_pnr]=acore_apb_pinwrap; READ[apb_serial_pnr]="$rtl_reads"$'\n'"read_verilog -sv $syn/acore_apb_pinwrap.v"
TOP[apb_top]=acore_apb;             READ[apb_top]="$rtl_reads"
# The shell around a pipelined top that fits (CORRECTION=2, no polynomial): is the shell on the
# critical path of a pipelined top?
TOP[apb_none_pnr]=acore_apb_pinwrap; READ[apb_none_pnr]="${READ[apb_serial_pnr]}"$'\n'"chparam -set SERIAL 0 -set CORRECTION 2 acore_apb_pinwrap"
for d in top cordic16 cordic16_bus serial fourier top_fold2 top_fold4 top_fold8 apb_serial; do FLOWS[$d]="generic xilinx ice40"; done
FLOWS[apb_top]="ice40"
for d in top_pnr scaler_pnr region_pnr poly_pnr poly2d_pnr poly2d1_pnr cordic_top_pnr serial_pnr fourier_pnr \
  top_fold2_pnr top_fold4_pnr top_fold8_pnr apb_serial_pnr apb_none_pnr; do
  FLOWS[$d]="ice40 pnr"
done
FLOWS[cordic16]="generic xilinx ice40 pnr"
all_designs=(top top_pnr scaler_pnr region_pnr poly_pnr poly2d_pnr poly2d1_pnr cordic_top_pnr cordic16 cordic16_bus serial
  serial_pnr fourier fourier_pnr top_fold2 top_fold4 top_fold8 top_fold2_pnr top_fold4_pnr top_fold8_pnr apb_serial
  apb_serial_pnr apb_top apb_none_pnr)
designs=("${all_designs[@]}")
if [ -n "$only" ]; then
  IFS=',' read -r -a designs <<<"$only"
  for d in "${designs[@]}"; do
    [ -n "${TOP[$d]:-}" ] || { echo "scripts/synth.sh: unknown design '$d' (known: ${all_designs[*]})" >&2; exit 2; }
  done
fi
# No stale reports of the designs run now.
for d in "${designs[@]}"; do
  rm -f "$rep/generic_$d.txt" "$rep/ice40_$d.txt" "$rep/xilinx_$d.txt" "$rep/nextpnr_$d.log"
done
rm -f "$rep/summary.md"

run_yosys() {  # run_yosys FLOW DESIGN
  local flow=$1 d=$2
  local ys=$build/${flow}_$d.ys
  sed -e "s|@TOP@|${TOP[$d]}|g" -e "s|@OUT@|$rep/${flow}_$d.txt|g" -e "s|@JSON@|$build/$d.json|g" \
    "$syn/$flow.ys.in" | awk -v r="${READ[$d]}" '{ if ($0 == "@READ@") print r; else print }' >"$ys"
  yosys -q -l "$build/${flow}_$d.log" -s "$ys" >/dev/null 2>&1
  # A multiply driven net means the netlist is not the simulated design: fail loudly.
  if grep -q "conflicting drivers" "$build/${flow}_$d.log"; then
    echo "yosys $flow $d: FAILED: conflicting drivers (see $build/${flow}_$d.log)"; return 1
  fi
  echo "yosys $flow $d: done"
}
run_pnr() {  # run_pnr DESIGN
  local d=$1
  # The pin-wrapped tops are placed with their pin constraints; the stage wrappers unconstrained.
  local pins=(--pcf-allow-unconstrained)
  case $d in top_pnr|serial_pnr|top_fold?_pnr) pins=(--pcf "$syn/acore_hx8k_ct256.pcf") ;; esac
  nextpnr-ice40 --hx8k --package ct256 --json "$build/$d.json" --asc "$build/$d.asc" --freq $freq \
    "${pins[@]}" --timing-allow-fail --seed 1 -l "$rep/nextpnr_$d.log" >/dev/null 2>&1 \
    || echo "nextpnr $d: failed (see synth/reports/nextpnr_$d.log)"
  echo "nextpnr $d: done"
}

tasks=()
pnr_designs=()
for d in "${designs[@]}"; do
  for f in ${FLOWS[$d]}; do
    case $f in
      pnr) pnr_designs+=("$d") ;;
      ice40) [[ " ${FLOWS[$d]} " == *" pnr "* ]] || tasks+=("run_yosys ice40 $d") ;;
      *) tasks+=("run_yosys $f $d") ;;
    esac
  done
done
export -f run_yosys run_pnr
# ice40 netlists for place and route first (nextpnr needs them), then everything else in parallel.
for d in "${pnr_designs[@]}"; do run_yosys ice40 "$d"; done
running=0
for d in "${pnr_designs[@]}"; do
  run_pnr "$d" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then wait -n; running=$((running - 1)); fi
done
wait
running=0
for t in "${tasks[@]}"; do
  $t &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then wait -n; running=$((running - 1)); fi
done
wait

python3 "$root/scripts/synth_summary.py" "$root" >"$rep/summary.md"
echo "wrote $rep/summary.md"
