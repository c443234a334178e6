# SPDX-License-Identifier: MIT
# Shared harness of the tests/cli/cli_*.sh scripts (sourced, not run): a scratch folder and counters,
# check (exit status), expect_text (a file contains a string), expect_eq (two strings are equal).
# Each script ends with: echo "$passes passed, $fails failed"; [ "$fails" -eq 0 ]
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
passes=0
check() { # check NAME EXPECTED_STATUS COMMAND...
  local name=$1 want=$2
  shift 2
  "$@" >"$tmp/out" 2>"$tmp/err"
  local got=$?
  if [ "$got" -ne "$want" ]; then
    echo "FAIL $name: exit $got, expected $want"
    sed 's/^/  /' "$tmp/err" | head -5
    fails=$((fails + 1))
  else
    passes=$((passes + 1))
  fi
}
expect_text() { # expect_text NAME FILE TEXT
  if grep -qF -- "$3" "$2"; then passes=$((passes + 1)); else
    echo "FAIL $1: '$3' not in $2"
    sed 's/^/  /' "$2" | head -5
    fails=$((fails + 1))
  fi
}
expect_eq() { # expect_eq NAME GOT WANT
  if [ "$2" = "$3" ]; then passes=$((passes + 1)); else
    echo "FAIL $1: got '$2', expected '$3'"
    fails=$((fails + 1))
  fi
}
