# SPDX-License-Identifier: BSD-3-Clause
# Sourced by the command-line tests: check and finish, the tool's path, and a scratch
# directory under build/ removed on exit ($work). Run from the repository root.
tool=${SURFADAPT:-bin/surfadapt}
passed=0 failed=0
check() { # $1 = description, then the command
  what=$1
  shift
  if "$@"; then
    passed=$((passed + 1))
    echo "ok - $what"
  else
    failed=$((failed + 1))
    echo "FAIL - $what"
  fi
}
# Ends the test with "cli: N passed, M failed" and a non-zero status if anything failed.
finish() {
  echo "cli: $passed passed, $failed failed"
  [ "$failed" -eq 0 ]
  exit $?
}

if [ ! -x "$tool" ]; then
  echo "FAIL - $tool is not built (run make)"
  failed=1
  finish
fi

mkdir -p build
work=$(mktemp -d build/cli-test.XXXXXX) || exit 1
trap 'rm -rf "$work"' EXIT
