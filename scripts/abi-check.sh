#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Compares the ABI of the built shared library with the committed baseline.
# Usage: abi-check.sh LIB BASELINE            check (make abi-check)
#        abi-check.sh --update LIB BASELINE   write the baseline (make abi-baseline)
# Run from the top of the tree.
#
# Additions (new functions, members appended to sfa_api) pass; anything else that
# abidiff reports -- a removed function, a changed parameter or return type, a changed,
# removed, reordered or inserted sfa_api member -- fails. A check ends with exactly one
# line "abi: 1 passed, 0 failed" or "abi: 0 passed, 1 failed".
set -u

update=no
if [ "${1:-}" = --update ]; then update=yes; shift; fi
lib=${1:?usage: abi-check.sh [--update] LIB BASELINE}
baseline=${2:?usage: abi-check.sh [--update] LIB BASELINE}
suppr=tests/abi/sfa_api.suppr
out=build/abi
current=$out/libsurfadapt.abi

# Only what the public header defines counts: sfa_surface is opaque there, so its C++
# definition is dropped (--drop-private-types) and internal changes never show up; only
# exported interfaces are read, which keeps the dump small. No source locations or build
# directories: the baseline is committed and must not depend on where it was built.
dump() {
  abidw --headers-dir include --drop-private-types --exported-interfaces-only \
    --no-corpus-path --no-show-locs --no-comp-dir-path --out-file "$2" "$1"
}

if [ $update = yes ]; then
  dump "$lib" "$baseline" || exit 1
  echo "wrote $baseline from $lib; commit it only for compatible additions (tests/abi/README.md)"
  exit 0
fi

verdict() {
  echo "ABI verdict: $1"
  if [ "$2" = pass ]; then echo "abi: 1 passed, 0 failed"; exit 0; fi
  echo "abi: 0 passed, 1 failed"
  exit 1
}

[ -f "$lib" ] || verdict "library $lib not found" fail
[ -f "$baseline" ] || verdict "no baseline $baseline (create it with: make abi-baseline)" fail
[ -f "$suppr" ] || verdict "suppression file $suppr missing" fail
mkdir -p "$out"

if ! dump "$lib" "$current"; then
  verdict "abidw could not read $lib (built without -g?)" fail
fi

# Full report, additions included, so that every change is visible in the log.
echo "abidiff $baseline $current"
abidiff "$baseline" "$current"
status=$?

# abidiff's status is a bit set: 1 error, 2 usage, 4 ABI change, 8 incompatible change.
case $status in
  0) verdict "identical to the baseline" pass ;;
  4) ;;
  *)
    [ $((status & 3)) -ne 0 ] && verdict "abidiff failed (status $status)" fail
    verdict "incompatible change (abidiff status $status)" fail
    ;;
esac

# Status 4 covers additions but also changed parameter and member types, so look again
# with additions set aside: anything left is a change that breaks existing hosts.
echo
echo "abidiff --no-added-syms --suppressions $suppr $baseline $current"
rest=$(abidiff --no-added-syms --suppressions "$suppr" "$baseline" "$current")
rest_status=$?
if [ $rest_status -ne 0 ]; then
  printf '%s\n' "$rest"
  verdict "changes beyond additions (abidiff status $rest_status without added symbols)" fail
fi

# The suppression lets through any change of sfa_api that inserts nothing in the middle,
# including a reordering; so require the baseline's members, with their offsets, to
# come first and unchanged in the current table.
api_members() {
  awk '
    /<class-decl name=.sfa_api. / && !/is-declaration-only=.yes./ { inside = 1; next }
    inside && /<\/class-decl>/ { if (n) exit; inside = 0 }
    inside && /<data-member / { match($0, /layout-offset-in-bits=.[0-9]+/); off = substr($0, RSTART + 23, RLENGTH - 23) }
    inside && /<var-decl / { match($0, /name=.[A-Za-z_0-9]+/); print off, substr($0, RSTART + 6, RLENGTH - 6); n++ }
  ' "$1"
}
api_members "$baseline" >"$out/sfa_api.baseline"
api_members "$current" >"$out/sfa_api.current"
nbase=$(wc -l <"$out/sfa_api.baseline")
[ "$nbase" -gt 0 ] || verdict "sfa_api not found in $baseline" fail
if ! head -n "$nbase" "$out/sfa_api.current" | cmp -s - "$out/sfa_api.baseline"; then
  echo "sfa_api members, baseline vs current (offset in bits, name):"
  diff "$out/sfa_api.baseline" "$out/sfa_api.current"
  verdict "members of sfa_api moved, changed or were removed" fail
fi

verdict "compatible: additions only" pass
