"""Runs the Python tests for ctest: pytest's exit code, with 'no tests collected' (5) and an
interrupted run (2) counted as failures, and a clear message when pytest is missing."""

import sys

try:
    import pytest
except ImportError:
    sys.stderr.write("asperity: error: pytest is not installed for %s "
                     "(Debian package python3-pytest)\n" % sys.executable)
    sys.exit(1)

if __name__ == "__main__":
    code = int(pytest.main(["-q", "-p", "no:cacheprovider", *sys.argv[1:]]))
    if code == 5:
        sys.stderr.write("asperity: error: pytest collected no tests\n")
    sys.exit(0 if code == 0 else 1)
