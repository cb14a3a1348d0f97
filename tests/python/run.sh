#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Runs the Python binding's tests (test_binding.py, which also runs the example and the
# README's program) against the library built in lib/.
# The interpreter is $PYTHON if set, else Debian's /usr/bin/python3: python3-numpy (which
# make check installs) serves that one, while a `python3` earlier on PATH (pyenv, a venv)
# may have no numpy at all.
# Ends with "python-binding: N passed, M failed" (scripts/run-tests.sh counts it).
set -u
cd "$(dirname "$0")/../.." || exit 1

python=${PYTHON:-/usr/bin/python3}
if ! "$python" -c 'import numpy' 2>/dev/null; then
  echo "FAIL - $python cannot import numpy: install python3-numpy (Debian) or set PYTHON to an interpreter that has it"
  echo "python-binding: 0 passed, 1 failed"
  exit 1
fi
[ -f lib/libsurfadapt.so.1 ] || {
  echo "FAIL - lib/libsurfadapt.so.1 is not built: run make first"
  echo "python-binding: 0 passed, 1 failed"
  exit 1
}
# Spinning OpenMP threads slow everything down on shared cores (see `make test`).
OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive} SURFADAPT_LIBRARY=$PWD/lib/libsurfadapt.so.1 \
  exec "$python" tests/python/test_binding.py
