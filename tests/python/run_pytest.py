"""Runs pytest on the given files; exit 77 (ctest's SKIP_RETURN_CODE) when pytest, NumPy or pandas
is missing, saying which (Debian: python3-pytest python3-numpy python3-pandas)."""

import sys

try:
    import numpy  # noqa: F401
    import pandas  # noqa: F401
    import pytest
except ImportError as missing:
    print(f"SKIP: {missing.name} is not installed for {sys.executable} "
          "(apt-get install python3-pytest python3-numpy python3-pandas)")
    sys.exit(77)

sys.exit(pytest.main(["-q", "-p", "no:cacheprovider", *sys.argv[1:]]))
