# SPDX-License-Identifier: MIT
"""The package as a user gets it: `python -m build` makes an sdist and, from it, a wheel; the wheel
installs into a fresh virtual environment, where docs/python_example.py runs.

usage: .venv/bin/python python/tests/wheel_install.py WORK_DIR ANGLECORE_CLI

Offline and with the pinned tools: `python -m build --no-isolation` with .venv's scikit-build-core
and nanobind; the fresh environment sees the system's numpy and matplotlib
(--system-site-packages) and pip installs the wheel with --no-index. The sdist is unpacked and built
inside WORK_DIR (TMPDIR), so that the compiler cache serves the objects of the repository's own
build of the package (the same paths relative to the build folder). Checks: one sdist and one
wheel, both named for the version `anglecore --version` prints (the project's one version); the
sdist holds the sources the build needs and nothing of a build or environment; the installed
package is the wheel's (not the repository's), reports that version, and the example prints the
demo table's five rows and writes its plot. Exit 1 on a failed check.
"""

import os
import re
import shutil
import subprocess
import sys
import tarfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def fail(msg: str) -> None:
    print(f"wheel_install: FAIL: {msg}")
    sys.exit(1)


def run(cmd, **kw) -> str:
    print("$ " + " ".join(map(str, cmd)), flush=True)
    p = subprocess.run([str(c) for c in cmd], capture_output=True, text=True, **kw)
    if p.returncode != 0:
        fail(f"exit {p.returncode}: {' '.join(map(str, cmd))}\n{p.stdout}\n{p.stderr}")
    return p.stdout


def main() -> None:
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    work, cli = Path(sys.argv[1]).resolve(), sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    (work / "tmp").mkdir(parents=True)
    version = run([cli, "--version"]).split()[-1]
    if not re.fullmatch(r"\d+\.\d+\.\d+", version):
        fail(f"anglecore --version printed {version!r}")

    env = dict(os.environ, TMPDIR=str(work / "tmp"))
    t0 = time.monotonic()
    out = run(
        [sys.executable, "-m", "build", "--no-isolation", "--outdir", work / "dist", ROOT], env=env
    )
    print(out.strip().splitlines()[-1])
    print(f"python -m build: {time.monotonic() - t0:.1f} s")
    dist = sorted(p.name for p in (work / "dist").iterdir())
    sdists = [d for d in dist if d.endswith(".tar.gz")]
    wheels = [d for d in dist if d.endswith(".whl")]
    if sdists != [f"anglecore-{version}.tar.gz"] or len(wheels) != 1:
        fail(f"expected anglecore-{version}.tar.gz and one wheel, got {dist}")
    if not wheels[0].startswith(f"anglecore-{version}-"):
        fail(f"the wheel {wheels[0]} is not of version {version}")

    with tarfile.open(work / "dist" / sdists[0]) as tf:
        names = {n.split("/", 1)[1] for n in tf.getnames() if "/" in n}
    for need in (
        "pyproject.toml",
        "CMakeLists.txt",
        "python/CMakeLists.txt",
        "python/anglecore/__init__.py",
        "python/src/anglecore_ext.cpp",
        "model/ip/engine/track_series.cpp",
        "rtl/configs.txt",
    ):
        if need not in names:
            fail(f"the sdist lacks {need}")
    stray = sorted(n for n in names if n.split("/")[0] in (".venv", "build", "out"))
    if stray:
        fail(f"the sdist holds build or environment files: {stray[:5]}")
    print(f"sdist: {len(names)} files; wheel: {wheels[0]}")

    fresh = work / "fresh"
    run(["/usr/bin/python3", "-m", "venv", "--system-site-packages", fresh])
    py = fresh / "bin" / "python"
    print(run([py, "-m", "pip", "install", "--no-index", work / "dist" / wheels[0]]).strip())
    where = run(
        [py, "-c", "import anglecore; print(anglecore.__version__, anglecore.__file__)"],
        cwd=work,
    ).split()
    if where[0] != version:
        fail(f"the installed package reports {where[0]}, the command {version}")
    if not where[1].startswith(str(fresh)):
        fail(f"imported {where[1]}, not the fresh environment's")
    png = work / "error.png"
    out = run([py, ROOT / "docs" / "python_example.py", png], cwd=work)
    print(out.rstrip())
    rows = [line for line in out.splitlines() if line.startswith("  ours")]
    if len(rows) != 5 or not png.is_file() or png.stat().st_size < 10000:
        fail(f"the example printed {len(rows)} of 5 rows or wrote no plot")
    print(f"wheel_install: OK, anglecore {version}")


if __name__ == "__main__":
    main()
