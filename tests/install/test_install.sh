#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Installs into a staging tree under build/ with `make install DESTDIR=... PREFIX=...`,
# checks what was installed, then builds and runs a C host found only through
# pkg-config, linked against the shared library and, fully static, against the static
# one (which proves Libs.private); a Fortran host compiled from the module's installed
# source, as compilers other than gfortran build it; and the installed Python module,
# imported from there, which must find the installed library by itself. Finally `make uninstall` with the same DESTDIR and
# PREFIX must leave no file or link of ours and keep one that is not. Needs the tree
# built (`make`).
# Ends with exactly "install: 1 passed, 0 failed" or "install: 0 passed, 1 failed".
set -u
cd "$(dirname "$0")/../.." || exit 1

work=build/install-test
destdir=$PWD/$work/stage
prefix=/opt/surfadapt
root=$destdir$prefix
cc=${CC:-cc}

fail() {
  echo "FAIL - $*"
  echo "install: 0 passed, 1 failed"
  exit 1
}

rm -rf "$work"
mkdir -p "$work"
# MAKEFLAGS of an enclosing make would be inherited; install and uninstall need none of them.
run_make() { # target log
  env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL "${MAKE:-make}" --no-print-directory "$1" \
    DESTDIR="$destdir" PREFIX="$prefix" >"$2" 2>&1
}
if ! run_make install "$work/install.log"; then
  cat "$work/install.log"
  fail "make install DESTDIR=$destdir PREFIX=$prefix"
fi
echo "ok - make install DESTDIR=... PREFIX=$prefix"

for f in include/surfadapt.h include/surfadapt.mod include/surfadapt.f90 share/surfadapt/python/surfadapt.py \
         lib/libsurfadapt.a lib/libsurfadapt_fortran.a \
         lib/pkgconfig/surfadapt.pc lib/cmake/surfadapt/surfadaptConfig.cmake \
         lib/cmake/surfadapt/surfadaptConfigVersion.cmake; do
  [ -f "$root/$f" ] || fail "$prefix/$f not installed"
done
[ -x "$root/bin/surfadapt" ] || fail "$prefix/bin/surfadapt not installed"
# The SONAME link and the development link must both lead to the real file.
for l in libsurfadapt.so.1 libsurfadapt.so; do
  if ! { [ -L "$root/lib/$l" ] && [ -f "$root/lib/$l" ]; }; then
    fail "$prefix/lib/$l is not a working symlink"
  fi
done
echo "ok - header, libraries, symlinks, Fortran module and source, Python module, tool, pkg-config and CMake files in place"

# The staging root is not where the package will live: it must not leak into any file.
if grep -rl "$destdir" "$root/lib/pkgconfig" "$root/lib/cmake"; then
  fail "DESTDIR written into the files above"
fi
echo "ok - no DESTDIR in the generated files"

# Only the staged package is visible; the sysroot maps its -I and -L into the stage.
PKG_CONFIG_LIBDIR=$root/lib/pkgconfig
PKG_CONFIG_PATH=
PKG_CONFIG_SYSROOT_DIR=$destdir
export PKG_CONFIG_LIBDIR PKG_CONFIG_PATH PKG_CONFIG_SYSROOT_DIR
flags=$(pkg-config --cflags --libs surfadapt) || fail "pkg-config --cflags --libs surfadapt"
echo "ok - pkg-config --cflags --libs surfadapt: $flags"

# The version is the installed header's, in pkg-config and in the CMake version file.
header_version=$(awk '$1 == "#define" && $2 ~ /^SFA_VERSION_(MAJOR|MINOR|PATCH)$/ { v = v sep $3; sep = "." } END { print v }' \
  "$root/include/surfadapt.h")
pc_version=$(pkg-config --modversion surfadapt)
[ "$pc_version" = "$header_version" ] ||
  fail "pkg-config --modversion gives '$pc_version', the installed header's version is '$header_version'"
grep -qx "set(PACKAGE_VERSION \"$header_version\")" "$root/lib/cmake/surfadapt/surfadaptConfigVersion.cmake" ||
  fail "surfadaptConfigVersion.cmake does not carry the header's version $header_version"
echo "ok - pkg-config and CMake carry the header's version $header_version"

# shellcheck disable=SC2086 # flags are a list of words
$cc tests/install/host.c -o "$work/host" $flags -lm || fail "compile and link the host against the shared library"
LD_LIBRARY_PATH=$root/lib "$work/host" || fail "run the host linked against the shared library"
echo "ok - host linked against the shared library runs"

# The README's way to need no LD_LIBRARY_PATH: the libdir pkg-config names as RUNPATH.
libdir=$(pkg-config --variable=libdir surfadapt) || fail "pkg-config --variable=libdir surfadapt"
# shellcheck disable=SC2086
$cc tests/install/host.c -o "$work/host-rpath" $flags -lm -Wl,-rpath,"$libdir" ||
  fail "link the host with -Wl,-rpath,\$(pkg-config --variable=libdir surfadapt)"
env -u LD_LIBRARY_PATH "$work/host-rpath" || fail "run the host linked with an rpath, without LD_LIBRARY_PATH"
echo "ok - host linked with -Wl,-rpath,$libdir runs without LD_LIBRARY_PATH"

static_flags=$(pkg-config --static --cflags --libs surfadapt) || fail "pkg-config --static"
# shellcheck disable=SC2086
$cc -static tests/install/host.c -o "$work/host-static" $static_flags ||
  fail "link the host statically with pkg-config --static --libs ($static_flags)"
"$work/host-static" || fail "run the statically linked host"
echo "ok - host linked statically with $static_flags runs"

# Fortran with only the installed source, as for ifx, nvfortran or Cray ftn: compile the
# module with the host into a directory of the host's own, link with pkg-config's flags.
fc=${FC:-gfortran}
mkdir -p "$work/fortran"
$fc -c "$root/include/surfadapt.f90" -J "$work/fortran" -o "$work/fortran/surfadapt.o" ||
  fail "compile the installed $prefix/include/surfadapt.f90 with $fc"
# Only the libraries: an -I of the installed include/ would offer gfortran its installed
# .mod, and the host must use the module it compiled itself.
libs=$(pkg-config --libs surfadapt) || fail "pkg-config --libs surfadapt"
# shellcheck disable=SC2086
$fc -I"$work/fortran" tests/install/host.f90 "$work/fortran/surfadapt.o" -o "$work/host-fortran" $libs ||
  fail "compile and link the Fortran host against the module built from the installed source"
LD_LIBRARY_PATH=$root/lib "$work/host-fortran" || fail "run the Fortran host built from the installed source"
echo "ok - Fortran host built with $fc from $prefix/include/surfadapt.f90 runs"

# Python: the installed module, imported from where it was installed with no library
# path given, must load the installed library (PREFIX/lib, relative to itself), not the
# build tree's. Debian's interpreter, as in tests/python/run.sh. Byte code is written as
# a user's import would write it, so that uninstall is seen to take it away.
python=${PYTHON:-/usr/bin/python3}
"$python" -c 'import numpy' 2>/dev/null || fail "$python cannot import numpy: install python3-numpy"
if ! env -u SURFADAPT_LIBRARY -u PYTHONDONTWRITEBYTECODE PYTHONPATH="$root/share/surfadapt/python" \
     OMP_WAIT_POLICY=passive "$python" - "$root" >"$work/python.log" 2>&1 <<'PY'
import os, sys
import surfadapt
root = os.path.realpath(sys.argv[1])
assert os.path.realpath(surfadapt.__file__) == os.path.join(root, "share/surfadapt/python/surfadapt.py"), surfadapt.__file__
lib = surfadapt.load_library()
assert os.path.realpath(lib.path) == os.path.realpath(os.path.join(root, "lib/libsurfadapt.so.1")), lib.path
with surfadapt.Surface(*surfadapt.icosphere(2)) as s:
    v0 = s.measure("volume")
    s.adapt()
    assert abs(s.measure("volume") / v0 - 1) < 1e-12
print("surfadapt", surfadapt.version(), "from", lib.path)
PY
then
  cat "$work/python.log"
  fail "import the installed Python module and adapt a sphere with the installed library"
fi
[ -n "$(ls "$root"/share/surfadapt/python/__pycache__/surfadapt.*.pyc 2>/dev/null)" ] ||
  fail "importing the installed module wrote no byte code beside it (uninstall is meant to remove it)"
echo "ok - Python: $(cat "$work/python.log")"

# Uninstall. The shared directories hold something of another package, which must stay.
foreign=lib/not-surfadapt.txt
echo "another package's file" >"$root/$foreign"
if ! run_make uninstall "$work/uninstall.log"; then
  cat "$work/uninstall.log"
  fail "make uninstall DESTDIR=$destdir PREFIX=$prefix"
fi
# Whatever install put anywhere under DESTDIR, uninstall must have taken away.
left=$(cd "$destdir" && find . \( -type f -o -type l \) ! -path "./${prefix#/}/$foreign" | sort)
[ -z "$left" ] || fail "make uninstall left these behind: $(echo "$left" | tr '\n' ' ')"
[ -f "$root/$foreign" ] || fail "make uninstall removed $prefix/$foreign, which make install did not put there"
for d in lib/cmake/surfadapt share/surfadapt; do
  [ ! -e "$root/$d" ] || fail "make uninstall left the package's own directory $prefix/$d"
done
echo "ok - make uninstall removed every file and link make install made, and kept $prefix/$foreign"

if run_make uninstall "$work/uninstall-again.log"; then
  fail "a second make uninstall succeeded although nothing was installed"
fi
grep -q "is not installed in" "$work/uninstall-again.log" ||
  fail "a second make uninstall did not say that nothing was installed: $(cat "$work/uninstall-again.log")"
echo "ok - a second make uninstall fails: $(grep 'is not installed in' "$work/uninstall-again.log")"

echo "install: 1 passed, 0 failed"
