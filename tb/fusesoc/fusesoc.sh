#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The FuseSoC core rtl/anglecore.core, run as a user would from a fresh cores root (no FuseSoC
# configuration, an empty build root): its file list is rtl/files.f, its committed vectors are what
# the model makes now, `--target=lint` passes on the defaults and stops on an illegal parameter with
# its rule, `--target=sim` passes on both tops (the pipelined one also folded, FOLD=2) and `--target=sim_apb` on the APB shell around each
# (the benches exit non-zero on any failure).
# usage: fusesoc.sh SOURCE_DIR GEN_VECTORS_BINARY WORK_DIR
set -euo pipefail
src=$1
gen=$2
work=$3
fusesoc=$src/.venv/bin/fusesoc
if [ ! -x "$fusesoc" ]; then
  echo "FAIL: $fusesoc is missing: run scripts/setup.sh (it installs FuseSoC into .venv)"
  exit 1
fi
rm -rf "$work"
mkdir -p "$work/config" "$work/data" "$work/cache"
cd "$work"
export XDG_CONFIG_HOME=$work/config XDG_DATA_HOME=$work/data XDG_CACHE_HOME=$work/cache
core=anglecore:ip:anglecore
status=0
check() { # check NAME COMMAND...: runs it, keeps its log, prints ok/FAIL
  local name=$1
  shift
  if "$@" >"$work/$name.log" 2>&1; then echo "ok   $name"; else
    echo "FAIL $name (see $work/$name.log)"
    tail -20 "$work/$name.log"
    status=1
  fi
}
run() { # run TARGET [--PARAM=value ...] (the core's parameters come after its name)
  local target=$1
  shift
  "$fusesoc" --cores-root "$src/rtl" run --build-root "$work/build" --target="$target" "$core" "$@"
}

# The core's RTL fileset is rtl/files.f, in order.
sed -n '/^  rtl:/,/file_type/p' "$src/rtl/anglecore.core" | sed -n 's/^ *- *\(acore_[a-z0-9_]*\.v\)$/\1/p' >"$work/core_files.txt"
grep -v '^#' "$src/rtl/files.f" | grep '\.v$' >"$work/files_f.txt"
check core_files_equal_files_f diff "$work/files_f.txt" "$work/core_files.txt"
# The committed vectors are the model's (tb/icarus/gen_vectors.cpp: acore_gen_vectors tb/icarus/vectors 0 400).
mkdir -p "$work/vectors"
"$gen" "$work/vectors" 0 400
check vectors_current diff -r "$src/tb/icarus/vectors" "$work/vectors"

check lint run lint
# An illegal parameter stops the lint target with its rule (rtl/acore_check.v).
lint_illegal() {
  ! run lint --DEGREE=8 >"$work/lint_illegal_run.log" 2>&1 &&
    grep -q "illegal parameter: DEGREE must be 1..7 for poly (CORRECTION=0) (value 8)" "$work/lint_illegal_run.log"
}
check lint_rejects_degree_8 lint_illegal
sim() { run sim "$@" && grep -q '^PASS$' "$work/build/anglecore_ip_anglecore_1.0.0/sim-icarus/icarus.log"; }
check sim_acore_top sim
check sim_acore_top_fold2 sim --FOLD=2
check sim_acore_serial_top sim --SERIAL=1
sim_apb() { run sim_apb "$@" && grep -q '^PASS$' "$work/build/anglecore_ip_anglecore_1.0.0/sim_apb-icarus/icarus.log"; }
check sim_apb_acore_top sim_apb
check sim_apb_acore_serial_top sim_apb --SERIAL=1
grep -h '^icarus' "$work"/sim_*.log || true
exit $status
