#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Measures the quick start as a new user meets it: a fresh `git clone` of HEAD for each of
# ./scripts/demo.sh and ./scripts/test.sh (Debian packages already installed; the clone's .venv is
# made by the run), wall time of each, the CTest summary of test.sh; writes
# docs/reports/timings.json (the README's figure; `python3 scripts/doc_figures.py write` after).
# Run it on an otherwise idle machine: it takes about as long as both commands.
# usage: scripts/time_fresh_clone.sh [WORK_DIR]   (default: a new temporary folder)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
work=${1:-$(mktemp -d)}
commit=$(git -C "$root" rev-parse --short HEAD)
results=()
for cmd in demo test; do
  dir=$work/$cmd
  rm -rf "$dir"
  # (the commit read at the start, for both: a commit made on the branch meanwhile is not measured)
  git clone -q "$root" "$dir"
  git -C "$dir" checkout -q "$commit"
  echo "time_fresh_clone: ./scripts/$cmd.sh in $dir (log $dir.log)" >&2
  start=$(date +%s)
  rc=0
  (cd "$dir" && "./scripts/$cmd.sh") >"$dir.log" 2>&1 || rc=$?
  end=$(date +%s)
  [ "$rc" -eq 0 ] || {
    echo "time_fresh_clone: ./scripts/$cmd.sh failed (exit $rc), see $dir.log" >&2
    exit 1
  }
  results+=("$cmd $((end - start)) $(grep -oE '[0-9]+% tests passed, [0-9]+ tests failed out of [0-9]+' "$dir.log" | tail -1 || true)")
done
/usr/bin/python3 - "$root/docs/reports/timings.json" "$commit" "$(nproc)" "$(lscpu | sed -n 's/^Model name: *//p' | head -1)" "${results[@]}" <<'PY'
import datetime, json, re, sys
path, commit, cores, cpu = sys.argv[1:5]
runs = []
for r in sys.argv[5:]:
    name, secs, rest = (r.split(" ", 2) + [""])[:3]
    m = re.search(r"(\d+) tests failed out of (\d+)", rest)
    total = int(m.group(2)) if m else None
    runs.append({"command": f"./scripts/{name}.sh", "wall_seconds": int(secs),
                 "tests_passed": total - int(m.group(1)) if m else None, "tests_total": total,
                 "date": datetime.date.today().isoformat(), "commit": commit,
                 "machine": f"{cores} cores ({cpu})"})
report = {"how": "scripts/time_fresh_clone.sh: wall time of each command in a fresh `git clone` of "
                 "the commit, Debian packages already installed, the clone's .venv made by the run; "
                 "tests from CTest's summary line",
          "runs": runs}
with open(path, "w") as f:
    json.dump(report, f, indent=1, ensure_ascii=False)
    f.write("\n")
print(f"time_fresh_clone: wrote {path}")
PY
