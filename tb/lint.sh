#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# verilator --lint-only -Wall over rtl/: every module in rtl/files.f as the top (default
# parameters), with the waivers of rtl/verilator.vlt; the top in every named configuration of
# rtl/configs.txt; the 16-bit normalizing CORDIC of rtl/cordic16.cfg;
# the serial core in every rtl/serial_*.cfg; the APB shell around the serial core (in its default
# and every rtl/serial_*.cfg), around the pipelined top (default) and around the named
# configurations' tops. Exit 1 on any warning.
set -euo pipefail
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root/rtl"
mapfile -t files < <(grep -v '^#' files.f | grep '\.v$')
fail=0
run() {
  local name=$1; shift
  if out=$(verilator --lint-only -Wall verilator.vlt "${files[@]}" "$@" 2>&1); then
    echo "lint ok:   $name"
  else
    echo "lint FAIL: $name"; echo "$out"; fail=1
  fi
}
for f in "${files[@]}"; do
  m=$(basename "$f" .v)
  run "$m" --top-module "$m"
done
while read -r name module flows params; do
  [ "$module" = acore_top ] && [[ ",$flows," == *",lint,"* ]] || continue
  gargs=()
  for p in $params; do gargs+=("-G$p"); done
  run "acore_top config $name" --top-module acore_top "${gargs[@]}"
  # The APB shell wraps the top at FOLD = 1 only (its FOLD_must_be_1 rule): folded configurations
  # are linted as the top alone.
  [ "$name" = default ] || [[ " $params " == *" FOLD="* ]] || run "acore_apb config $name" --top-module acore_apb "${gargs[@]}"
done < <(grep -E '^[a-z]' configs.txt)
mapfile -t c16 < <(grep -E '^[A-Z_]+=' cordic16.cfg | sed 's/^/-G/')
run "acore_cordic cordic16.cfg" --top-module acore_cordic "${c16[@]}"
run "acore_apb SERIAL=1" --top-module acore_apb -GSERIAL=1
for cfg in serial_*.cfg; do
  mapfile -t sargs < <(grep -E '^[A-Z_]+=' "$cfg" | sed 's/^/-G/')
  run "acore_serial_top $cfg" --top-module acore_serial_top "${sargs[@]}"
  run "acore_apb SERIAL=1 $cfg" --top-module acore_apb -GSERIAL=1 "${sargs[@]}"
done
exit $fail
