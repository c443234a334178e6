#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The design-space sweep, one command: accuracy of every configuration of a grid
# (anglecore sweep), its area and clock rate (scripts/design_space_hw.py: Yosys + nextpnr-ice40),
# then the table and the Pareto plots (scripts/design_space_report.py).
#
#   scripts/design_space.sh [--out DIR] [--jobs N] [--grid FILE.json] [--quick] [--no-synth]
#   scripts/design_space.sh --shard i/N [...]   one shard of a batch job (e.g. a cluster job array:
#                                               --shard $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT)
#   scripts/design_space.sh --merge DIR         join the shards of DIR into the table and plots
#
# DIR defaults to out/design_space. Writes DIR/design_space.md, .csv and pareto.png. Synthesis is
# cached in DIR/cache/ (a rerun only pays for new configurations); the full default grid takes
# about an hour on two cores, --no-synth a few seconds.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=out/design_space
jobs=1
shard=""
merge=""
synth=1
sweep_args=()
usage() { sed -n '3,16p' "$0" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case $1 in
    --out)
      out=$2
      shift 2
      ;;
    --jobs | -j)
      jobs=$2
      shift 2
      ;;
    --shard)
      shard=$2
      shift 2
      ;;
    --merge)
      merge=$2
      shift 2
      ;;
    --grid)
      sweep_args+=(--grid "$2")
      shift 2
      ;;
    --quick)
      sweep_args+=(--quick)
      shift
      ;;
    --no-synth)
      synth=0
      shift
      ;;
    -h | --help)
      usage
      exit 0
      ;;
    *)
      echo "design_space.sh: unknown option '$1'" >&2
      usage >&2
      exit 2
      ;;
  esac
done
report() { /usr/bin/python3 "$root/scripts/design_space_report.py" "$1" && echo "wrote $1/design_space.md, $1/pareto.png"; }
if [ -n "$merge" ]; then
  report "$merge"
  exit
fi
"$root/scripts/build.sh" anglecore >/dev/null
"$root/build/anglecore" sweep --out "$out" --jobs "$jobs" --shard "${shard:-0/1}" "${sweep_args[@]}"
if [ "$synth" = 1 ]; then
  python3 "$root/scripts/design_space_hw.py" "$root" "$out" "${shard:-0/1}" --jobs "$jobs"
fi
if [ -z "$shard" ]; then
  report "$out"
else
  echo "shard $shard done; after every shard: scripts/design_space.sh --merge $out"
fi
