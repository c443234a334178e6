#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The design-space sweep on this machine, one command: the workflow workflow/Snakefile (accuracy of
# every configuration of a grid, area and clock rate on each device and seed, then the tables and
# Pareto plots) run by the project's Snakemake (.venv, scripts/setup.sh) after building anglecore.
#
#   scripts/design_space.sh [--out DIR] [--jobs N] [--grid FILE.json|--quick] [--no-synth]
#                           [--devices D[,D...]] [--seeds S[,S...]] [-- SNAKEMAKE-OPTIONS...]
#
# DIR defaults to out/design_space; --jobs is Snakemake's --cores (default 1); --no-synth: accuracy
# only (seconds); --devices: devices of synth/devices.toml (default: every one); --seeds: nextpnr
# seeds (default 1). Writes DIR/design_space.md (every device's table and plots) and DIR/DEVICE/
# (design_space.md, .csv, pareto.png). A rerun only runs what is missing. On a cluster, the same
# workflow through a profile: docs/synthesis.md "Design space".
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=out/design_space
jobs=1
config=()
usage() { sed -n '3,15p' "$0" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case $1 in
    --out)
      out=${2:?--out needs a directory}
      shift 2
      ;;
    --jobs | -j)
      jobs=${2:?--jobs needs a number}
      shift 2
      ;;
    --grid)
      config+=("grid=${2:?--grid needs a file}")
      shift 2
      ;;
    --quick)
      config+=(grid=quick)
      shift
      ;;
    --no-synth)
      config+=(devices=)
      shift
      ;;
    --devices)
      config+=("devices=${2:?--devices needs device names}")
      shift 2
      ;;
    --seeds)
      config+=("seeds=${2:?--seeds needs seeds}")
      shift 2
      ;;
    -h | --help)
      usage
      exit 0
      ;;
    --)
      shift
      break
      ;;
    *)
      echo "design_space.sh: unknown option '$1'" >&2
      usage >&2
      exit 2
      ;;
  esac
done
[ -x "$root/.venv/bin/snakemake" ] || {
  echo "design_space.sh: $root/.venv/bin/snakemake missing (run scripts/setup.sh)" >&2
  exit 2
}
"$root/scripts/build.sh" anglecore >/dev/null
out=$(realpath -m "$out")
exec "$root/.venv/bin/snakemake" -s "$root/workflow/Snakefile" --cores "$jobs" \
  --config out="$out" "${config[@]}" "$@"
