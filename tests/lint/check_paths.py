#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks that every repository path named in a comment, a doc or a string exists.

Reads every file git tracks (text only) and every token that starts with a top-level folder of the
repository (rtl/, model/, tb/, tests/, synth/, scripts/, python/, docs/, cmake/, .ci/) or names a
top-level file (README.md, CMakeLists.txt, pyproject.toml, LICENSE): the token must name a file or
folder of the checkout. Placeholders are patterns: `<name>`, `NAME` in upper case after a separator
and `*` match any part of one name, `{a,b}` each alternative, `.{hpp,cpp}` each; a pattern must
match at least one path. Paths under build/, out/ or .venv/ are not the repository's and are not
read. Fails (exit 1) listing file:line: token for each path that names nothing.
usage: check_paths.py [ROOT]
"""

import fnmatch
import os
import re
import subprocess
import sys

ROOT = os.path.abspath(
    sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
)
TOPS = ("rtl", "model", "tb", "tests", "synth", "scripts", "python", "docs", "cmake", ".ci")
TOP_FILES = ("README.md", "CMakeLists.txt", "pyproject.toml", "LICENSE")
# A path token: a top folder, then path characters (placeholders and braces included).
TOKEN = re.compile(
    r"(?<![\w./<>{}*-])((?:" + "|".join(re.escape(t) for t in TOPS) + r")/[\w./<>{}*,+-]*)"
)
# Text that names generated or external places, not repository paths.
SKIP_PREFIX = (
    "build/",
    "out/",
    ".venv/",
    os.path.join("synth", "build", ""),
)  # synth.sh writes there


def tracked():
    out = subprocess.run(
        ["git", "-C", ROOT, "ls-files", "-z"], capture_output=True, text=True, check=True
    )
    return [f for f in out.stdout.split("\0") if f]


def expand_braces(s):
    m = re.search(r"\{([^{}]*,[^{}]*)\}", s)
    if not m:
        return [s]
    out = []
    for alt in m.group(1).split(","):
        out += expand_braces(s[: m.start()] + alt + s[m.end() :])
    return out


def clean(tok):
    # Trailing punctuation of the sentence or the code around it.
    tok = re.sub(r"[.,:;)]+$", "", tok)
    if tok.count("{") != tok.count("}"):
        tok = tok.split("{")[0]
    return tok.rstrip("/") if tok.endswith("/") and len(tok) > 1 else tok


def to_glob(p):
    p = re.sub(r"<[^<>/]*>", "*", p)  # <name>
    p = re.sub(r"\{[^{},/]*\}", "*", p)  # {name}: a format field, not alternatives
    # An upper-case word as a part of a name is a placeholder (DESIGN.json, acore_rtl_NAME.so).
    p = re.sub(r"(?<![a-z0-9])[A-Z][A-Z_]{2,}(?![a-z0-9])", "*", p)
    if p.endswith("_"):
        p += "*"  # a prefix: nextpnr_<design>
    return p


def exists(pattern, paths, dirs):
    for alt in expand_braces(pattern):
        g = to_glob(alt).rstrip("/")
        if not any(c in g for c in "*?["):
            if g in paths or g in dirs:
                continue
            return False
        if not (fnmatch.filter(paths, g) or fnmatch.filter(dirs, g)):
            return False
    return True


def main():
    files = tracked()
    paths = set(files)
    dirs = set()
    for f in files:
        d = os.path.dirname(f)
        while d:
            dirs.add(d)
            d = os.path.dirname(d)
    # Folders the build or the tools make, named as places to look: not repository paths.
    problems = []
    checked = 0
    for f in files:
        full = os.path.join(ROOT, f)
        try:
            with open(full, encoding="utf-8") as fh:
                text = fh.read()
        except (UnicodeDecodeError, OSError):
            continue
        if "\0" in text:
            continue
        for n, line in enumerate(text.splitlines(), 1):
            for m in TOKEN.finditer(line):
                tok = clean(m.group(1))
                if tok.startswith(SKIP_PREFIX) or tok in TOPS:
                    continue
                checked += 1
                if not exists(tok, paths, dirs):
                    problems.append(f"{f}:{n}: {tok}")
    for p in problems:
        print(p)
    print(f"check_paths: {checked} path names in {len(files)} files, {len(problems)} name nothing")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
