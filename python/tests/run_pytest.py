# SPDX-License-Identifier: MIT
"""CTest's entry to the package's pytest files: exit 77 (CTest SKIP) when anglecore or pytest is
not importable from this interpreter, pytest's own status otherwise."""

import sys

try:
    import anglecore  # noqa: F401
    import pytest
except ImportError as e:
    print(f"SKIP: {e} (scripts/setup.sh installs the package into .venv)")
    sys.exit(77)
sys.exit(pytest.main([*sys.argv[1:], "-p", "no:cacheprovider"]))
