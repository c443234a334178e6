#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `anglecore cosim` and `estimate --engine rtl|rtl-serial` through the CLI: RTL (pipelined top, the
# top folded to 2, 4 and 8 clocks a sample with --fold, serial core) vs model on a simulated
# recording (0 mismatches, JSON fields), stalls, FST trace, RTL = fixed error statistics, bad input;
# a run-time module that is not built: exit 2, and the message names the module and the command that
# builds it (cosim, estimate, demo).
# usage: cli_cosim.sh ANGLECORE SOURCE_DIR. ACORE_WITH_RTL=OFF (CTest passes the build's setting): the
# build makes no modules, so only their absence is checked.
set -u
bin=$1
rtl=${ACORE_WITH_RTL:-ON}
# shellcheck source=lib_cli.sh
source "$(dirname "$0")/lib_cli.sh"
# A two-channel recording with offsets, gain mismatch and a 3rd harmonic, so every stage works.
/usr/bin/python3 - "$tmp/cal.csv" 3000 0 <<'PY'
import math, sys
path, n, phase = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
with open(path, "w") as f:
    f.write("# two-channel test recording\ntheta_ref,sin,cos\n")
    for k in range(n):
        t = 2 * math.pi * (k + phase) / n
        s = 1.9 * math.sin(t) + 0.05 + 0.04 * math.sin(3 * t)
        c = 2.1 * math.cos(t) - 0.03 + 0.03 * math.cos(3 * t)
        f.write(f"{t:.9f},{s:.9f},{c:.9f}\n")
PY
/usr/bin/python3 - "$tmp/val.csv" 5000 0.37 <<'PY'
import math, sys
path, n, phase = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
with open(path, "w") as f:
    f.write("theta_ref,sin,cos\n")
    for k in range(n):
        t = 2 * math.pi * (k + phase) / n
        s = 1.9 * math.sin(t) + 0.05 + 0.04 * math.sin(3 * t)
        c = 2.1 * math.cos(t) - 0.03 + 0.03 * math.cos(3 * t)
        f.write(f"{t:.9f},{s:.9f},{c:.9f}\n")
PY
check calibrate 0 "$bin" calibrate --in "$tmp/cal.csv" --out "$tmp/regs.hex"

# The modules are looked for in $ACORE_RTL_DIR: an empty folder has none. Without the RTL in this
# build, the build's own folder has none either, and the command says how to configure it in.
mkdir "$tmp/empty"
missing() { # missing NAME MODULE COMMAND...: exit 2, the message names MODULE and its build command
  local name=$1 module=$2
  shift 2
  check "$name" 2 "$@"
  expect_text "$name-module" "$tmp/err" "$module.so"
  expect_text "$name-command" "$tmp/err" "cmake --build "
  expect_text "$name-target" "$tmp/err" "--target $module\`"
  expect_text "$name-env" "$tmp/err" "ACORE_RTL_DIR"
}
missing no-module-cosim acore_rtl_default env ACORE_RTL_DIR="$tmp/empty" "$bin" cosim --regs "$tmp/regs.hex" --in "$tmp/val.csv"
expect_text no-module-where "$tmp/err" "$tmp/empty/acore_rtl_default.so"
missing no-module-serial acore_rtl_serial env ACORE_RTL_DIR="$tmp/empty" "$bin" estimate --engine rtl-serial --regs "$tmp/regs.hex" --in "$tmp/val.csv"
missing no-module-fold4 acore_rtl_fold4 env ACORE_RTL_DIR="$tmp/empty" "$bin" estimate --engine rtl --fold 4 --regs "$tmp/regs.hex" --in "$tmp/val.csv"
missing no-module-demo acore_rtl_default env ACORE_RTL_DIR="$tmp/empty" "$bin" demo --no-plots --no-sweep --samples 512 --out "$tmp/demo"
expect_text no-module-demo-hint "$tmp/err" "demo --no-rtl"
check demo-no-rtl 0 env ACORE_RTL_DIR="$tmp/empty" "$bin" demo --no-rtl --no-plots --no-sweep --samples 512 --out "$tmp/demo"
if [ "$rtl" = OFF ]; then
  missing off-cosim acore_rtl_default "$bin" cosim --regs "$tmp/regs.hex" --in "$tmp/val.csv"
  expect_text off-configure "$tmp/err" "-DACORE_WITH_RTL=ON"
  missing off-estimate acore_rtl_default "$bin" estimate --engine rtl --regs "$tmp/regs.hex" --in "$tmp/val.csv"
  echo "$passes passed, $fails failed (built without the RTL: the module-absent checks only)"
  [ "$fails" -eq 0 ]
  exit
fi
check cosim 0 "$bin" cosim --regs "$tmp/regs.hex" --in "$tmp/val.csv" --json "$tmp/cosim.json"
check cosim-stalls 0 "$bin" cosim --regs "$tmp/regs.hex" --in "$tmp/val.csv" --backpressure 0.5 --json "$tmp/cosim2.json"
check cosim-trace 0 "$bin" cosim --regs "$tmp/regs.hex" --in "$tmp/val.csv" --trace "$tmp/wave.fst"
[ -s "$tmp/wave.fst" ] || {
  echo "FAIL trace: no FST written"
  fails=$((fails + 1))
}
check est-rtl 0 "$bin" estimate --regs "$tmp/regs.hex" --in "$tmp/val.csv" --engine rtl --json "$tmp/rtl.json"
check est-fixed 0 "$bin" estimate --regs "$tmp/regs.hex" --in "$tmp/val.csv" --engine fixed --json "$tmp/fx.json"
check cosim-serial 0 "$bin" cosim --engine rtl-serial --regs "$tmp/regs.hex" --in "$tmp/val.csv" --json "$tmp/cs.json"
check cosim-serial-stalls 0 "$bin" cosim --engine rtl-serial --regs "$tmp/regs.hex" --in "$tmp/val.csv" --backpressure 0.5 --seed 3 --json "$tmp/cs2.json"
check cosim-serial-trace 0 "$bin" cosim --engine rtl-serial --regs "$tmp/regs.hex" --in "$tmp/val.csv" --trace "$tmp/wave_s.fst"
[ -s "$tmp/wave_s.fst" ] || {
  echo "FAIL serial trace: no FST written"
  fails=$((fails + 1))
}
check est-serial 0 "$bin" estimate --regs "$tmp/regs.hex" --in "$tmp/val.csv" --engine rtl-serial --json "$tmp/rs.json"
# The same image on the folded builds (a register image does not depend on FOLD).
for n in 2 4 8; do
  check "cosim-fold$n" 0 "$bin" cosim --fold $n --regs "$tmp/regs.hex" --in "$tmp/val.csv" --backpressure 0.3 --json "$tmp/cf$n.json"
done
check est-fold4 0 "$bin" estimate --engine rtl --fold 4 --regs "$tmp/regs.hex" --in "$tmp/val.csv" --json "$tmp/rf4.json"
/usr/bin/python3 - "$tmp" <<'PY' && passes=$((passes + 1)) || {
import json, sys
d = sys.argv[1]
for name, engine in (("cosim.json", "rtl"), ("cosim2.json", "rtl"), ("cs.json", "rtl-serial"), ("cs2.json", "rtl-serial")):
    j = json.load(open(f"{d}/{name}"))
    assert j["samples"] == 5000 and j["mismatches"] == 0 and j["first_mismatch"] is None, j
    assert j["engine"] == engine, j
for n in (2, 4, 8):
    j = json.load(open(f"{d}/cf{n}.json"))
    assert j["samples"] == 5000 and j["mismatches"] == 0 and j["fold"] == n and j["engine"] == "rtl", j
r, f, rs = json.load(open(f"{d}/rtl.json")), json.load(open(f"{d}/fx.json")), json.load(open(f"{d}/rs.json"))
assert r["error_deg"] == f["error_deg"], (r["error_deg"], f["error_deg"])
rf4 = json.load(open(f"{d}/rf4.json"))
assert rf4["error_deg"] == f["error_deg"] and rf4["fold"] == 4, (rf4, f["error_deg"])
assert rs["error_deg"] == f["error_deg"] and rs["engine"] == "rtl-serial", (rs, f["error_deg"])
PY
  echo "FAIL json"
  fails=$((fails + 1))
}
# Bad input: missing file, an image of another configuration (the RTL is built for the defaults).
check missing-regs 2 "$bin" cosim --regs "$tmp/nope.hex" --in "$tmp/val.csv"
check bad-backpressure 2 "$bin" cosim --regs "$tmp/regs.hex" --in "$tmp/val.csv" --backpressure 2
sed 's/acore: iterations=16/acore: iterations=12/' "$tmp/regs.hex" | grep -v -e 'atan(2^-1[2-5])' -e 'acore: crc32=' >"$tmp/k12.hex"
check other-config 2 "$bin" cosim --regs "$tmp/k12.hex" --in "$tmp/val.csv"
check other-config-serial 2 "$bin" cosim --engine rtl-serial --regs "$tmp/k12.hex" --in "$tmp/val.csv"
check est-other-config-serial 2 "$bin" estimate --engine rtl-serial --regs "$tmp/k12.hex" --in "$tmp/val.csv"
check cosim-not-rtl 2 "$bin" cosim --engine fixed --regs "$tmp/regs.hex" --in "$tmp/val.csv"
check cosim-bad-engine 2 "$bin" cosim --engine rtl-parallel --regs "$tmp/regs.hex" --in "$tmp/val.csv"
check cosim-bad-fold 2 "$bin" cosim --fold 3 --regs "$tmp/regs.hex" --in "$tmp/val.csv"
check cosim-fold-serial 2 "$bin" cosim --engine rtl-serial --fold 2 --regs "$tmp/regs.hex" --in "$tmp/val.csv"
check est-fold-fixed 2 "$bin" estimate --engine fixed --fold 2 --regs "$tmp/regs.hex" --in "$tmp/val.csv"
# No folded build of the 12-iteration configuration: the error names the available builds.
check fold-other-config 2 "$bin" cosim --fold 2 --regs "$tmp/k12.hex" --in "$tmp/val.csv"
echo "$passes passed, $fails failed"
[ "$fails" -eq 0 ]
