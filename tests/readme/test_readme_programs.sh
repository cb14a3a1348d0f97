#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Every program in the README, compiled and run as a new user would: each ```c, ```fortran
# and ```python block is extracted to build/readme/, built against the libraries of this
# tree the way the README's "Linking" section builds a host (warnings are errors for C; a
# Fortran velocity callback may leave arguments unused),
# and run; it must exit 0. So the README's examples cannot rot. ```sh blocks are commands
# for the user's shell (make, pkg-config), run by CI and tests/install, not programs.
# Ends with "readme: N passed, M failed". Needs `make` (the libraries and the module).
set -u
cd "$(dirname "$0")/../.." || exit 1

out=build/readme
rm -rf "$out"
mkdir -p "$out"
# Block n of language L goes to $out/program_n.L (c, fortran, python).
awk -v out="$out" '
  /^```(c|fortran|python)$/ { lang = substr($0, 4); n++; file = out "/program_" n "." lang; next }
  /^```/ { file = ""; next }
  file != "" { print > file }
' README.md

passed=0 failed=0
result() { # $1 = status, $2 = description
  if [ "$1" -eq 0 ]; then
    passed=$((passed + 1))
    echo "ok - $2"
  else
    failed=$((failed + 1))
    echo "FAIL - $2"
  fi
}
lib=$(pwd)/lib
for program in "$out"/program_*; do
  [ -e "$program" ] || continue
  exe=${program%.*}
  case $program in
    *.c)
      gcc -std=c11 -Wall -Wextra -Wpedantic -Werror -Iinclude -o "$exe" "$program" \
        -L"$lib" -lsurfadapt -lm -Wl,-rpath,"$lib"
      built=$? ;;
    *.fortran)
      cp "$program" "$exe.f90"
      gfortran -std=f2008 -Wall -Wextra -Wno-unused-dummy-argument -fimplicit-none -I"$lib/fortran" -J "$out" -o "$exe" "$exe.f90" \
        "$lib/libsurfadapt_fortran.a" -L"$lib" -lsurfadapt -Wl,-rpath,"$lib"
      built=$? ;;
    *.python)
      # Debian's interpreter, which python3-numpy serves (not another python3 on PATH).
      printf '#!/bin/sh\nPYTHONPATH=bindings/python SURFADAPT_LIBRARY=%s/libsurfadapt.so.1 exec /usr/bin/python3 %s\n' \
        "$lib" "$program" >"$exe"
      chmod +x "$exe"
      built=0 ;;
  esac
  result "$built" "README block $(basename "$program") builds"
  [ "$built" -eq 0 ] || continue
  OMP_WAIT_POLICY=passive "$exe"
  result $? "README block $(basename "$program") runs and exits 0"
done
[ $((passed + failed)) -gt 0 ] || result 1 "the README has programs"
echo "readme: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
