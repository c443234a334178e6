#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Every C++ file of the repository is formatted as .clang-format says (clang-format from Debian):
# prints the files that differ and exits 1. Fix with:
#   clang-format -i $(git ls-files '*.cpp' '*.hpp')
set -euo pipefail
root=${1:-$(cd "$(dirname "$0")/../.." && pwd)}
cd "$root"
command -v clang-format >/dev/null || { echo "check_format: clang-format is missing (scripts/setup.sh installs it)"; exit 1; }
mapfile -t files < <(find model tb tests -name '*.cpp' -o -name '*.hpp' | sort)
bad=0
for f in "${files[@]}"; do
  if ! clang-format --dry-run --Werror "$f" >/dev/null 2>&1; then
    echo "not formatted: $f"
    bad=$((bad + 1))
  fi
done
echo "check_format: ${#files[@]} files, $bad not formatted ($(clang-format --version))"
[ "$bad" -eq 0 ]
