#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Synthesis reports for AngleCore: writes synth/reports/ (see synth/README.md) for every line of the
# build registry rtl/configs.txt with a synthesis flow (its header states the rules):
#   generic, xilinx, ice40  Yosys `synth` cell counts, `synth_ice40` LUT4/DFF/carry/BRAM,
#                           `synth_xilinx` (xc7) LUT/FF/DSP/RAM of the line's module with its
#                           parameters: reports <flow>_<name>.txt
#   pnr                     the module in its pin wrapper <module>_pinwrap (synth/*.v), synth_ice40 and
#                           nextpnr-ice40 on an HX8K (ct256): ice40_<name>_pnr.txt, nextpnr_<name>_pnr.log
#   pnr_up5k                the module in its SG48 wrapper <module>_sg48wrap (synth/*.v), synth_ice40 and
#                           nextpnr-ice40 on an iCE40 UP5K (sg48, pins unconstrained):
#                           ice40_<name>_up5k.txt, nextpnr_<name>_up5k.log
# and the summary table synth/reports/summary.md (scripts/synth_summary.py).
# usage: scripts/synth.sh [-j N] [-d NAME[,NAME...]] [-f FLOW[,FLOW...]]
#   -j N  runs N Yosys/nextpnr jobs in parallel (default 1)
#   -d    only these registry lines (default: every line with a synthesis flow)
#   -f    only these of their flows (generic, xilinx, ice40, pnr, pnr_up5k; default all of each line's)
#   The reports of what runs are replaced, the others kept, and the summary is rebuilt from every
#   report present. Example: -d serial (the serial core: area on three targets and placed, ~1 minute).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=1
only=""
flows=""
while [ $# -gt 0 ]; do
  case $1 in
    -j) jobs=${2:?-j needs a number}; shift 2 ;;
    -d) only=${2:?-d needs registry names}; shift 2 ;;
    -f) flows=${2:?-f needs flow names}; shift 2 ;;
    *) echo "usage: scripts/synth.sh [-j N] [-d NAME[,NAME...]] [-f FLOW[,FLOW...]]" >&2; exit 2 ;;
  esac
done
syn=$root/synth
build=$syn/build
rep=$syn/reports
mkdir -p "$build" "$rep"
freq=150  # nextpnr target clock, MHz (Fmax is reported whether or not it is met)
registry() { python3 "$root/scripts/registry.py" --root "$root" "$@"; }

rtl_reads=""
while read -r f; do
  [[ $f =~ \.v$ ]] && rtl_reads+="read_verilog -sv $root/rtl/$f"$'\n'
done <"$root/rtl/files.f"

# The designs (scripts/registry.py synth): design name, top module, the synth/ file defining it ('-':
# a module of rtl/files.f), flows, the registry line's parameters (set on the top by chparam).
plan=$(registry synth ${only:+--names "$only"} ${flows:+--flows "$flows"}) || exit 2
declare -A TOP READ FLOWS
designs=()
while read -r d top src fl params; do
  [ -n "$d" ] || continue
  designs+=("$d")
  TOP[$d]=$top
  READ[$d]=$rtl_reads
  # (synth/acore_cordic16.v includes synth/acore_cordic16_atan.vh, written from the model by
  # acore_gen_tables and checked by the CTest gen_tables_current; the pin wrappers include the
  # datapath parameters' declaration and pass-on list of rtl/, generated alike.)
  [ "$src" = - ] || READ[$d]+="read_verilog -sv -I$syn -I$root/rtl $src"$'\n'
  if [ -n "$params" ]; then
    chp=chparam
    for p in $params; do chp+=" -set ${p%%=*} ${p#*=}"; done
    READ[$d]+="$chp $top"
  fi
  FLOWS[$d]=${fl//,/ }
done <<<"$plan"
if [ ${#designs[@]} -eq 0 ]; then
  echo "scripts/synth.sh: no synthesis flow (${flows:-generic, xilinx, ice40, pnr}) on ${only:-any registry line}" >&2
  exit 2
fi
# No stale reports or netlists of what runs now.
rm -f "$build/failed"
for d in "${designs[@]}"; do
  for f in ${FLOWS[$d]}; do
    case $f in
      pnr | pnr_up5k) rm -f "$rep/ice40_$d.txt" "$rep/nextpnr_$d.log" "$build/$d.json" ;;
      *) rm -f "$rep/${f}_$d.txt" ;;
    esac
  done
done
rm -f "$rep/summary.md"

run_yosys() {  # run_yosys FLOW DESIGN
  local flow=$1 d=$2
  local ys=$build/${flow}_$d.ys log=$build/${flow}_$d.log
  sed -e "s|@TOP@|${TOP[$d]}|g" -e "s|@OUT@|$rep/${flow}_$d.txt|g" -e "s|@JSON@|$build/$d.json|g" \
    "$syn/$flow.ys.in" | awk -v r="${READ[$d]}" '{ if ($0 == "@READ@") print r; else print }' >"$ys"
  if ! yosys -q -l "$log" -s "$ys" >/dev/null 2>&1; then
    echo "yosys $flow $d: FAILED: $(grep -m1 'ERROR' "$log" || true) (see $log)"; touch "$build/failed"; return 1
  fi
  # A multiply driven net means the netlist is not the simulated design: fail loudly.
  if grep -q "conflicting drivers" "$log"; then
    echo "yosys $flow $d: FAILED: conflicting drivers (see $log)"; touch "$build/failed"; return 1
  fi
  echo "yosys $flow $d: done"
}
run_pnr() {  # run_pnr DESIGN [DEVICE]: DEVICE hx8k (default, ct256) or up5k (sg48)
  local d=$1 dev=${2:-hx8k} pcf
  [ -e "$build/$d.json" ] || { echo "nextpnr $d: skipped (no iCE40 netlist)"; return 1; }
  # Pin constraints where a PCF of synth/ places every port (the whole tops in their wrappers:
  # acore_hx8k_ct256.pcf; the board top: acore_board_hx8k_ct256.pcf); the stage and shell wrappers
  # and the 16-bit CORDIC are placed with their pins unconstrained, as is everything on the UP5K
  # (the PCFs are the HX8K board's).
  local pins=(--pcf-allow-unconstrained) device=(--hx8k --package ct256)
  if [ "$dev" = up5k ]; then
    device=(--up5k --package sg48)
  else
    for pcf in "$syn"/*.pcf; do
      if registry pcf-covers "$build/$d.json" "$pcf"; then pins=(--pcf "$pcf"); break; fi
    done
  fi
  if ! nextpnr-ice40 "${device[@]}" --json "$build/$d.json" --asc "$build/$d.asc" --freq $freq \
    "${pins[@]}" --timing-allow-fail --seed 1 -l "$rep/nextpnr_$d.log" >/dev/null 2>&1; then
    # A design larger than the device is a measurement (the summary says "does not fit"), not a failure.
    if awk '/Info:[ \t]+[A-Z_0-9]+:[ \t]+[0-9]+\/[ \t]*[0-9]+/ { split($3, u, "/"); if (u[1] + 0 > $4 + 0) over = 1 }
            END { exit !over }' "$rep/nextpnr_$d.log"; then
      echo "nextpnr $d: does not fit the ${dev^^} (utilisation in synth/reports/nextpnr_$d.log)"; return 0
    fi
    echo "nextpnr $d: failed (see synth/reports/nextpnr_$d.log)"; touch "$build/failed"; return 1
  fi
  echo "nextpnr $d: done"
}
parallel() {  # parallel COMMAND...: each argument one command line, at most $jobs at once
  local running=0 t
  for t in "$@"; do
    $t &
    running=$((running + 1))
    if [ "$running" -ge "$jobs" ]; then wait -n || true; running=$((running - 1)); fi
  done
  wait || true
}

# ice40 netlists for place and route first (nextpnr needs them), then everything else.
netlists=()
places=()
tasks=()
for d in "${designs[@]}"; do
  for f in ${FLOWS[$d]}; do
    case $f in
      pnr) netlists+=("run_yosys ice40 $d"); places+=("run_pnr $d") ;;
      pnr_up5k) netlists+=("run_yosys ice40 $d"); places+=("run_pnr $d up5k") ;;
      ice40) [[ " ${FLOWS[$d]} " == *" pnr "* ]] || tasks+=("run_yosys ice40 $d") ;;
      *) tasks+=("run_yosys $f $d") ;;
    esac
  done
done
parallel "${netlists[@]}"
parallel "${places[@]}" "${tasks[@]}"

python3 "$root/scripts/synth_summary.py" "$root" >"$rep/summary.md"
echo "wrote $rep/summary.md"
if [ -e "$build/failed" ]; then echo "scripts/synth.sh: some runs failed (see above)" >&2; exit 1; fi
