#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Synthesis reports for AngleCore: writes synth/reports/ (see synth/README.md) for every line of the
# build registry rtl/configs.txt with a synthesis flow, a family or a device of the devices table
# synth/devices.toml (the registry's header states the rules; scripts/registry.py applies them):
#   a family (generic, ice40, xilinx, ...)  Yosys area of the line's module with its parameters, the
#                           family's synthesis command (`synth -flatten`, `synth_ice40`,
#                           `synth_xilinx -family xc7`, ...): reports <family>_<name>.txt
#   a device (hx8k, up5k, ...)  the module in the device's pin wrapper (synth/*.v), synthesized for
#                           its family and placed and routed by its nextpnr (HX8K ct256, UP5K sg48,
#                           ...): <family>_<name><suffix>.txt, nextpnr_<name><suffix>.log (suffix _pnr
#                           on the HX8K, _up5k on the UP5K)
# the summary table synth/reports/summary.md (scripts/synth_summary.py) and the datasheet
# synth/reports/datasheet.md (scripts/datasheet.py).
# usage: scripts/synth.sh [-j N] [-d NAME[,NAME...]] [-f FLOW[,FLOW...]]
#   -j N  runs N Yosys/nextpnr jobs in parallel (default 1)
#   -d    only these registry lines (default: every line with a synthesis flow)
#   -f    only these of their flows (families and devices of synth/devices.toml, or pnr and
#         pnr_up5k, the names of hx8k and up5k before the table; default all of each line's)
#   The reports of what runs are replaced, the others kept, and the summary is rebuilt from every
#   report present. Example: -d serial (the serial core: area on three targets and placed, ~1 minute).
#   A device whose place-and-route program is not installed stops the run before it starts (exit 2).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=1
only=""
flows=""
while [ $# -gt 0 ]; do
  case $1 in
    -j)
      jobs=${2:?-j needs a number}
      shift 2
      ;;
    -d)
      only=${2:?-d needs registry names}
      shift 2
      ;;
    -f)
      flows=${2:?-f needs flow names}
      shift 2
      ;;
    *)
      echo "usage: scripts/synth.sh [-j N] [-d NAME[,NAME...]] [-f FLOW[,FLOW...]]" >&2
      exit 2
      ;;
  esac
done
syn=$root/synth
build=$syn/build
rep=$syn/reports
mkdir -p "$build" "$rep"
registry() { python3 "$root/scripts/registry.py" --root "$root" "$@"; }

rtl_reads=""
while read -r f; do
  [[ $f =~ \.v$ ]] && rtl_reads+="read_verilog -sv $root/rtl/$f"$'\n'
done <"$root/rtl/files.f"

# The runs (scripts/registry.py synth-tasks), tab-separated: Yosys runs (family, design, report,
# netlist to place or '-', top module, the synth/ file defining it or '-', the family's synthesis
# command, writing that netlist, the registry line's parameters, set on the top by chparam),
# netlists first; then the
# placements (device, design, log, the device's short name).
plan=$(registry synth-tasks ${only:+--names "$only"} ${flows:+--flows "$flows"}) || exit 2
if [ -z "$plan" ]; then
  echo "scripts/synth.sh: no synthesis flow (${flows:-a family or device of the devices table}) on ${only:-any registry line}" >&2
  exit 2
fi
declare -A SCRIPT OUT NETLIST LOG SHORT
netlists=()
places=()
tasks=()
while IFS=$'\t' read -r kind target d out net top src synth params; do
  [ -n "$kind" ] || continue
  if [ "$kind" = place ]; then
    # (the fields after the design: log, short name)
    LOG["$target:$d"]=$out
    SHORT[$target]=$net
    places+=("run_pnr $target $d")
    continue
  fi
  reads=$rtl_reads
  # (synth/acore_cordic16.v includes synth/acore_cordic16_atan.vh, written from the model by
  # acore_gen_tables and checked by the CTest gen_tables_current; the pin wrappers include the
  # datapath parameters' declaration and pass-on list of rtl/, generated alike.)
  [ "$src" = - ] || reads+="read_verilog -sv -I$syn -I$root/rtl $src"$'\n'
  if [ -n "$params" ]; then
    chp=chparam
    for p in $params; do chp+=" -set ${p%%=*} ${p#*=}"; done
    reads+="$chp $top"
  fi
  k=$target:$d
  OUT[$k]=$out
  NETLIST[$k]=$net
  SCRIPT[$k]=$(sed -e "s|@TOP@|$top|g" -e "s|@SYNTH@|$synth|g" -e "s|@OUT@|$out|g" \
    "$syn/synth.ys.in" | awk -v r="$reads" '{ if ($0 == "@READ@") print r; else print }')
  if [ "$net" = - ]; then tasks+=("run_yosys $target $d"); else netlists+=("run_yosys $target $d"); fi
done <<<"$plan"
# No stale reports or netlists of what runs now.
rm -f "$build/failed"
for k in "${!OUT[@]}"; do
  rm -f "${OUT[$k]}"
  [ "${NETLIST[$k]}" = - ] || rm -f "${NETLIST[$k]}"
done
for k in "${!LOG[@]}"; do rm -f "${LOG[$k]}"; done
rm -f "$rep/summary.md"

run_yosys() { # run_yosys FAMILY DESIGN
  local flow=$1 d=$2
  local ys=$build/${flow}_$d.ys log=$build/${flow}_$d.log
  printf '%s\n' "${SCRIPT["$flow:$d"]}" >"$ys"
  if ! yosys -q -l "$log" -s "$ys" >/dev/null 2>&1; then
    echo "yosys $flow $d: FAILED: $(grep -m1 'ERROR' "$log" || true) (see $log)"
    touch "$build/failed"
    return 1
  fi
  # A multiply driven net means the netlist is not the simulated design: fail loudly.
  if grep -q "conflicting drivers" "$log"; then
    echo "yosys $flow $d: FAILED: conflicting drivers (see $log)"
    touch "$build/failed"
    return 1
  fi
  echo "yosys $flow $d: done"
}
run_pnr() { # run_pnr DEVICE DESIGN
  local dev=$1 d=$2 log=${LOG["$1:$2"]} cmd
  # The device's nextpnr command: pins from its first constraint file that places every port of the
  # netlist (the whole tops in their wrappers on the HX8K: acore_hx8k_ct256.pcf; the board top:
  # acore_board_hx8k_ct256.pcf), unconstrained otherwise (the stage and shell wrappers, the 16-bit
  # CORDIC, everything on the UP5K).
  local rc=0
  cmd=$(registry pnr-command "$dev" "$d" 2>&1) || rc=$?
  if [ "$rc" = 3 ]; then
    # More ports than the package's free pins: a measurement, as a design larger than the device.
    echo "place $dev $d: does not fit the ${SHORT[$dev]}'s pins (${cmd#registry: })"
    return 0
  fi
  if [ "$rc" != 0 ]; then
    echo "place $dev $d: skipped ($cmd)"
    touch "$build/failed"
    return 1
  fi
  mapfile -t cmd <<<"$cmd"
  if ! "${cmd[@]}" >/dev/null 2>&1; then
    # A design larger than the device is a measurement (the summary says "does not fit"), not a failure.
    if awk '/Info:[ \t]+[A-Z_0-9]+:[ \t]+[0-9]+\/[ \t]*[0-9]+/ { split($3, u, "/"); if (u[1] + 0 > $4 + 0) over = 1 }
            END { exit !over }' "$log"; then
      echo "${cmd[0]} $d: does not fit the ${SHORT[$dev]} (utilisation in ${log#"$root"/})"
      return 0
    fi
    echo "${cmd[0]} $d: failed (see ${log#"$root"/})"
    touch "$build/failed"
    return 1
  fi
  echo "${cmd[0]} $d: done"
}
parallel() { # parallel COMMAND...: each argument one command line, at most $jobs at once
  local running=0 t
  for t in "$@"; do
    $t &
    running=$((running + 1))
    if [ "$running" -ge "$jobs" ]; then
      wait -n || true
      running=$((running - 1))
    fi
  done
  wait || true
}

# The netlists to place first (nextpnr needs them), then everything else.
parallel "${netlists[@]}"
parallel "${places[@]}" "${tasks[@]}"

python3 "$root/scripts/synth_summary.py" "$root" >"$rep/summary.md"
echo "wrote $rep/summary.md"
# The datasheet, from every report present (scripts/datasheet.py: one line per device and
# configuration).
python3 "$root/scripts/datasheet.py" --root "$root" --out "$rep/datasheet.md"
echo "wrote $rep/datasheet.md"
if [ -e "$build/failed" ]; then
  echo "scripts/synth.sh: some runs failed (see above)" >&2
  exit 1
fi
