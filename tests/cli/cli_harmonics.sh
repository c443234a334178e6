#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `anglecore harmonics` through the CLI: exit codes, docs/contracts.md, command line JSON fields, the paper's Eq. 33
# numbers, plots, bad specs.
# usage: cli_harmonics.sh ANGLECORE SOURCE_DIR
set -u
bin=$1
src=$2
# shellcheck source=lib_cli.sh
source "$(dirname "$0")/lib_cli.sh"
spec="$src/tests/data/kuntz_eq33.json"

check help 0 "$bin" harmonics --help
check eq33 0 "$bin" harmonics --spec "$spec" --json "$tmp/h.json"
expect_text table-header "$tmp/out" "order"
expect_text table-residual "$tmp/out" "residual second order"
for f in max_error_deg residual_first_deg residual_second_deg bounds geometric_deg taylor_first_deg \
  taylor_second_deg harmonics order exact_deg first_deg second_deg; do
  expect_text "json-$f" "$tmp/h.json" "\"$f\""
done
# `--json -`: stdout is exactly the JSON document, the table goes to stderr.
check json-stdout 0 "$bin" harmonics --spec "$spec" --json -
cp "$tmp/out" "$tmp/stdout.json"
expect_text json-stdout-table "$tmp/err" "order"
/usr/bin/python3 - "$tmp/h.json" "$tmp/stdout.json" <<'PY' || {
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
assert a == b, "file and stdout JSON differ"
assert abs(a["max_error_deg"] - 7.76) < 0.01, a["max_error_deg"]
assert a["residual_first_deg"] < 0.6 and a["residual_second_deg"] < 0.05, a
assert a["residual_first_deg"] <= a["bounds"]["taylor_first_deg"]
assert a["residual_second_deg"] <= a["bounds"]["taylor_second_deg"]
assert a["max_error_deg"] <= a["bounds"]["geometric_deg"]
h = {r["order"]: r for r in a["harmonics"]}
for k in (1, 5, 7, 11):
    assert abs(h[k]["first_deg"] - h[k]["exact_deg"]) < 1e-3, h[k]
for k in (2, 4, 8, 10, 14, 16):
    assert abs(h[k]["second_deg"] - h[k]["exact_deg"]) < 0.02 * h[k]["exact_deg"], h[k]
PY
  echo "FAIL eq33-numbers"
  fails=$((fails + 1))
}
passes=$((passes + 1))

# Plots (or a clear "skipped" when matplotlib is missing).
check plot 0 "$bin" harmonics --spec "$spec" --plot "$tmp/plot"
expect_text plot-data "$tmp/plot/harmonics_curve.csv" "phi_deg,exact_deg"
if /usr/bin/python3 -c 'import matplotlib, numpy' 2>/dev/null; then
  for f in harmonics_error.png harmonics_spectrum.png; do
    if [ -s "$tmp/plot/$f" ]; then passes=$((passes + 1)); else
      echo "FAIL plot $f missing"
      fails=$((fails + 1))
    fi
  done
else
  expect_text plot-skipped "$tmp/out" "plot skipped"
fi

# Mismatches of the main harmonic are accepted.
echo '{"p": 2, "A0": 0.02, "B0": -0.01, "Ap": 1.03, "Bp": 0.97, "delta_p": 0.02}' >"$tmp/mm.json"
check mismatch 0 "$bin" harmonics --spec "$tmp/mm.json" --json "$tmp/mm_out.json"
expect_text mismatch-order "$tmp/mm_out.json" "\"order\": 8"
# --attribute names the offset at order p and the amplitude mismatch at order 2p.
echo '{"p": 2, "A0": 0.02, "B0": -0.01, "Ap": 1.03, "Bp": 0.97, "terms": [{"n": 5, "A": 0.01, "B": 0.01}]}' >"$tmp/at.json"
check attribute 0 "$bin" harmonics --spec "$tmp/at.json" --attribute --json "$tmp/at_out.json"
/usr/bin/python3 - "$tmp/at_out.json" <<'PY' || {
import json, sys
a = {o["order"]: o["causes"] for o in json.load(open(sys.argv[1]))["attribution"]}
assert a[2][0]["kind"] == "offset" and abs(a[2][0]["parameter"] - 0.02236) < 1e-3, a[2][0]
assert a[4][0]["kind"] == "amplitude" and abs(a[4][0]["parameter"] - 0.06) < 2e-3, a[4][0]
assert {c["signal_order"] for c in a[3] if c["kind"] == "harmonic"} == {1, 5}, a[3]
PY
  echo "FAIL attribution"
  fails=$((fails + 1))
}
passes=$((passes + 1))

# Bad specs: exit 2 and a message naming the field.
bad() { # bad NAME JSON FIELD_TEXT
  echo "$2" >"$tmp/bad.json"
  check "bad-$1" 2 "$bin" harmonics --spec "$tmp/bad.json"
  expect_text "bad-$1-message" "$tmp/err" "$3"
}
bad negative-amplitude '{"p": 2, "terms": [{"n": 3, "A": -0.1, "B": 0.1}]}' "terms[0].A"
bad n-equals-p '{"p": 2, "terms": [{"n": 2, "A": 0.1, "B": 0.1}]}' "terms[0].n"
bad convergence '{"p": 1, "A0": 0.8, "B0": 0.7}' "convergence domain"
bad missing-p '{"A0": 0.1}' "'p'"
bad unknown-field '{"p": 1, "Ap": 1, "Apx": 1}' "'Apx'"
bad not-a-number '{"p": 1, "delta_p": "0.1"}' "'delta_p'"
bad nan '{"p": 1, "A0": NaN}' "not valid JSON"
check missing-file 2 "$bin" harmonics --spec "$tmp/does-not-exist.json"
check no-spec 2 "$bin" harmonics

echo "cli_harmonics: $passes passed, $fails failed"
[ "$fails" -eq 0 ]
