#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Every source file of the repository is formatted as its formatter says: C++ by clang-format
# (.clang-format), Python by ruff's formatter and linter (pinned in .venv by scripts/setup.sh; the
# rules in pyproject.toml's [tool.ruff]), shell by shfmt (2 spaces, indented case items). Prints the
# files that differ and exits 1. Fix with:
#   clang-format -i $(git ls-files '*.cpp' '*.hpp')
#   .venv/bin/ruff format . && .venv/bin/ruff check --fix .
#   shfmt -i 2 -ci -w $(git ls-files '*.sh') .ci/run
set -euo pipefail
root=${1:-$(cd "$(dirname "$0")/../.." && pwd)}
cd "$root"
ruff=$root/.venv/bin/ruff
for tool in clang-format "$ruff" shfmt; do
  command -v "$tool" >/dev/null || {
    echo "check_format: $tool is missing (scripts/setup.sh installs it)"
    exit 1
  }
done
# Sources only: the build folders and the virtual environment are not the repository's.
sources() { find model tb tests scripts python synth docs .ci "$@" -not -path '*/__pycache__/*' | sort; }
bad=0

mapfile -t cpp < <(sources \( -name '*.cpp' -o -name '*.hpp' \))
for f in "${cpp[@]}"; do
  if ! clang-format --dry-run --Werror "$f" >/dev/null 2>&1; then
    echo "not formatted: $f"
    bad=$((bad + 1))
  fi
done
echo "check_format: ${#cpp[@]} C++ files ($(clang-format --version))"

mapfile -t py < <(sources -name '*.py')
"$ruff" format --check --quiet "${py[@]}" || bad=$((bad + 1))
"$ruff" check --quiet "${py[@]}" || bad=$((bad + 1))
echo "check_format: ${#py[@]} Python files ($("$ruff" --version): format and lint)"

mapfile -t sh < <(sources \( -name '*.sh' -o -path .ci/run \))
shfmt -i 2 -ci -l "${sh[@]}" | sed 's/^/not formatted: /' | grep . && bad=$((bad + 1))
echo "check_format: ${#sh[@]} shell files (shfmt $(shfmt --version))"

[ "$bad" -eq 0 ] && echo "check_format: all formatted" || {
  echo "check_format: $bad formatter findings above"
  exit 1
}
