#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Install every Debian package AngleCore needs, only when something is missing.
# Idempotent and quiet when all is there; uses sudo when not root.
set -euo pipefail

packages=(
  cmake ninja-build g++ make pkg-config git
  verilator iverilog yosys nextpnr-ice40 fpga-icestorm
  libsystemc-dev libgtest-dev libgmock-dev libbenchmark-dev
  libeigen3-dev nlohmann-json3-dev libcli11-dev libfmt-dev zlib1g-dev
  python3-matplotlib python3-numpy
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup: installing ${missing[*]}" >&2
sudo_cmd=()
[ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
