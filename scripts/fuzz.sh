#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Long fuzz runs of every input parser with libFuzzer (clang, ASan + UBSan, coverage-guided).
#   scripts/fuzz.sh [-s SECONDS] [-j JOBS] [TARGET ...]     (default 600 s each, every target)
# Builds build-fuzz/ (clang++, -DACORE_FUZZ=ON), then runs each target from its seeds
# (tests/fuzz/corpus/<target>/) into build-fuzz/tests/fuzz/<target>_corpus/ and prints one line
# per target: executions, seconds, corpus files, and "0 crashes" or the artifact it wrote. Exit 1
# when any target found a crash, a leak, undefined behaviour, a timeout or ran out of memory.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=600 jobs=1
usage() { sed -n 3,8p "$0" | sed 's/^# \{0,1\}//'; }
while getopts "s:j:h" o; do
  case $o in
    s) seconds=$OPTARG ;;
    j) jobs=$OPTARG ;;
    h)
      usage
      exit 0
      ;;
    *)
      usage >&2
      exit 2
      ;;
  esac
done
shift $((OPTIND - 1))
all=$(sed -n 's/^set(ACORE_FUZZ_TARGETS \(.*\))$/\1/p' tests/fuzz/CMakeLists.txt)
targets=${*:-$all}
[ -n "$targets" ] || {
  echo "fuzz.sh: no targets found in tests/fuzz/CMakeLists.txt" >&2
  exit 2
}
cxx=$(command -v clang++ || command -v clang++-14 || true)
[ -n "$cxx" ] || {
  echo "fuzz.sh: clang++ not found (Debian: clang, libclang-rt-14-dev)" >&2
  exit 2
}
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER="$cxx" \
  -DACORE_FUZZ=ON "${launcher[@]}" >/dev/null
# shellcheck disable=SC2086
cmake --build build-fuzz -j2 --target $targets
run_one() {
  local t=$1 dir=build-fuzz/tests/fuzz
  mkdir -p "$dir/${t}_corpus"
  local log="$dir/$t.log"
  local rc=0
  "$dir/$t" -seed=1 -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$dir/$t-" "$dir/${t}_corpus" "tests/fuzz/corpus/$t" >"$log" 2>&1 || rc=$?
  local runs corpus
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  corpus=$(find "$dir/${t}_corpus" -type f | wc -l)
  if [ "$rc" = 0 ]; then
    echo "$t: ${runs:-?} executions in ${seconds} s, corpus ${corpus} files, 0 crashes"
  else
    echo "$t: FAILED (exit $rc) after ${runs:-?} executions: $(grep -m1 -E 'ERROR|SUMMARY|==[0-9]+==' "$log" || true); artifact: $(ls "$dir/$t-"* 2>/dev/null | head -1); log $log"
    return 1
  fi
}
export -f run_one
export seconds
# shellcheck disable=SC2086
printf '%s\n' $targets | xargs -P "$jobs" -I{} bash -c 'run_one {}'
