#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# verilator --lint-only -Wall over rtl/, with the waivers of rtl/verilator.vlt:
#   - every module of rtl/files.f as the top, at its default parameters;
#   - every line of the build registry rtl/configs.txt with the lint flow (its module, its
#     parameters; scripts/registry.py reads the registry);
#   - the APB register shell acore_apb around every linted acore_top line (its parameters) and
#     acore_serial_top line (SERIAL=1 and its parameters), unless a registry line lints that shell
#     configuration already. When the only warnings are parameter rules of the shell itself (a rule
#     instance of acore_apb, e.g. FOLD_must_be_1), the shell does not take that configuration: the
#     line says so ("lint n/a") and it is not a failure; the rule comes from the RTL, so the shell is
#     linted around every configuration it accepts.
# VERILATED (optional, comma-separated registry names): the lines a CMake build has Verilated
# already, with the same -Wall and waivers (cmake/AcoreRegistry.cmake's ACORE_VERILATOR_ARGS; a
# warning stops that build): they count as linted and are not run again (CTest rtl_lint passes them).
# Exit 1 on any other warning, 2 on a malformed registry.
# usage: lint.sh [ROOT [VERILATED]]
set -euo pipefail
root=${1:-$(cd "$(dirname "$0")/../.." && pwd)}
declare -A verilated
IFS=, read -r -a _v <<<"${2:-}"
for n in "${_v[@]}"; do verilated[$n]=1; done
lines=$(python3 "$root/scripts/registry.py" --root "$root" lines --flow lint) || exit 2
cd "$root/rtl"
mapfile -t files < <(grep -v '^#' files.f | grep '\.v$')
fail=0
out=""
# Each run reads its top's file and finds the modules below it in rtl/ (-y: every module is in a file
# of its name, which -Wall's DECLFILENAME enforces): the same hierarchy as with every file of
# files.f on the command line, without parsing the files it does not use.
lint() { out=$(verilator --lint-only -Wall verilator.vlt -y . "$@" 2>&1); }
run() { # run DESCRIPTION VERILATOR_ARGS...: status 1 on a failure
  local name=$1
  shift
  if lint "$@"; then echo "lint ok:   $name"; else
    echo "lint FAIL: $name"
    echo "$out"
    fail=1
    return 1
  fi
}
gargs() {
  local p
  for p in "$@"; do printf -- '-G%s\n' "$p"; done
}
key() {
  local m=$1
  shift
  printf '%s %s' "$m" "$(printf '%s\n' "$@" | sort | paste -sd' ')"
}
# The messages of $out when every warning in it is a parameter rule instantiated in acore_apb itself
# (nothing else printed as %Warning or %Error but Verilator's closing count).
shell_rules_only() {
  local warnings rules others
  warnings=$(grep -c '^%Warning' <<<"$out" || true)
  rules=$(grep -A1 '^%Warning-USERERROR' <<<"$out" | grep -cE 'In instance acore_apb\.[A-Za-z0-9_]+$' || true)
  others=$(grep '^%Error' <<<"$out" | grep -vc '^%Error: Exiting due to' || true)
  [ "$warnings" -gt 0 ] && [ "$warnings" -eq "$rules" ] && [ "$others" -eq 0 ] || return 1
  grep '^%Warning-USERERROR' <<<"$out" | sed -E 's/^%Warning-USERERROR: [^:]+:[0-9]+:[0-9]+: //' | paste -sd';'
}

declare -A linted # module and sorted parameters -> what linted it
for f in "${files[@]}"; do
  m=$(basename "$f" .v)
  if run "$m" "$f" --top-module "$m"; then linted[$(key "$m")]=$m; fi
done
while read -r name module flows params; do
  [ -n "$name" ] || continue
  k=$(key "$module" $params)
  if [ -n "${linted[$k]:-}" ]; then
    echo "lint ok:   $module $name (as ${linted[$k]})"
    continue
  fi
  if [ -n "${verilated[$name]:-}" ]; then
    echo "lint ok:   $module $name (Verilated with -Wall by the build)"
    linted[$k]="$module $name"
    continue
  fi
  mapfile -t g < <(gargs $params)
  if run "$module $name" "$module.v" --top-module "$module" "${g[@]}"; then linted[$k]="$module $name"; fi
done <<<"$lines"
while read -r name module flows params; do
  [ -n "$name" ] || continue
  case $module in
    acore_top) shell=($params) ;;
    acore_serial_top) shell=(SERIAL=1 $params) ;;
    *) continue ;;
  esac
  k=$(key acore_apb "${shell[@]}")
  [ -z "${linted[$k]:-}" ] || continue
  linted[$k]="acore_apb around $name"
  mapfile -t g < <(gargs "${shell[@]}")
  if lint acore_apb.v --top-module acore_apb "${g[@]}"; then
    echo "lint ok:   acore_apb around $name"
  elif why=$(shell_rules_only); then
    echo "lint n/a:  acore_apb around $name: the shell does not take it ($why)"
  else
    echo "lint FAIL: acore_apb around $name"
    echo "$out"
    fail=1
  fi
done <<<"$lines"
exit $fail
