#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Provenance: an image's `// acore: command=` line is the command line that made it, verbatim
# (tokens shell-quoted where they need it, the binary by its base name), so running that line
# again makes the same image; `demo` records its own command line the same way.
# usage: cli_provenance.sh ANGLECORE SOURCE_DIR
set -u
bin=$1
# shellcheck source=lib_cli.sh
source "$(dirname "$0")/lib_cli.sh"

cd "$tmp" || exit 1
mkdir -p bin "dir with space"
ln -s "$bin" bin/anglecore
check simulate 0 "$bin" simulate --scenario paper --samples 2048 --seed 1 --out "dir with space/cal'1.csv"
# Options as a user may spell them: NAME=VALUE, a flag, quotes and spaces in paths, a tab.
check calibrate 0 "$bin" calibrate --in "dir with space/cal'1.csv" --out "out 1.hex" --degree=4 \
  --coef-frac 14 --zero-word --json "$(printf 'a\tb.json')"
want="command=anglecore calibrate --in 'dir with space/cal'\\''1.csv' --out 'out 1.hex' --degree=4 --coef-frac 14 --zero-word --json \$'a\\tb.json'"
expect_eq command-line "$(sed -n 's#^// acore: \(command=.*\)$#\1#p' "out 1.hex")" "$want"
expect_text periodicity "out 1.hex" "// acore: periodicity=1"
# The recorded line, run by a shell with `anglecore` on its PATH, makes the same image.
mv "out 1.hex" first.hex
rm -f "$(printf 'a\tb.json')"
cmd=$(sed -n 's#^// acore: command=##p' first.hex)
check rerun 0 env PATH="$tmp/bin:$PATH" bash -c "$cmd"
check same-image 0 cmp first.hex "out 1.hex"
check same-json-name 0 test -f "$(printf 'a\tb.json')"

# The demo's image: its own command line, and the calibration it ran.
check demo 0 "$bin" demo --no-rtl --no-plots --no-sweep --samples 1024 --out demo_out
expect_text demo-command demo_out/regs.hex "// acore: command=anglecore demo --no-rtl --no-plots --no-sweep --samples 1024 --out demo_out"
expect_text demo-calibration demo_out/regs.hex "// acore: calibration=paper scenario, 1024 samples, seed 1"
expect_text demo-report demo_out/report.md 'Command: `anglecore demo --no-rtl --no-plots --no-sweep --samples 1024 --out demo_out`'
echo "$passes passed, $fails failed"
[ "$fails" -eq 0 ]
