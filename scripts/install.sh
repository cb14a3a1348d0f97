#!/bin/sh
# Installs surfadapt under DESTDIR/PREFIX: header, shared library with its SONAME and
# development symlinks, static libraries, Fortran module, command-line tool, pkg-config
# file and CMake package. Run from the top of the tree after `make` (make install does).
# Usage: install.sh DESTDIR PREFIX VERSION SOVERSION   (DESTDIR may be empty)
set -eu

if [ $# -ne 4 ]; then
  echo "usage: install.sh DESTDIR PREFIX VERSION SOVERSION" >&2
  exit 2
fi
destdir=$1
prefix=$2
version=$3
soversion=$4

case $prefix in
  /*) ;;
  *) echo "install.sh: PREFIX must be an absolute path, got '$prefix'" >&2; exit 2 ;;
esac
# The generated files name PREFIX, never DESTDIR: DESTDIR is only a staging root.
prefix=${prefix%/}
root=$destdir$prefix
real=libsurfadapt.so.$version

for f in include/surfadapt.h lib/$real lib/libsurfadapt.a lib/libsurfadapt_fortran.a \
         lib/fortran/surfadapt.mod bin/surfadapt; do
  [ -f "$f" ] || { echo "install.sh: $f is missing; run make first" >&2; exit 1; }
done

# sed replacement text: escape the characters that are special there.
quote() { printf '%s\n' "$1" | sed -e 's/[\\|&]/\\&/g'; }
render() {
  sed -e "s|@PREFIX@|$(quote "$prefix")|g" -e "s|@VERSION@|$(quote "$version")|g" \
      -e "s|@SOVERSION@|$(quote "$soversion")|g" "$1" >"$2"
  chmod 644 "$2"
}

install -d "$root/include" "$root/lib/pkgconfig" "$root/lib/cmake/surfadapt" "$root/bin"

install -m 644 include/surfadapt.h "$root/include/surfadapt.h"
install -m 755 "lib/$real" "$root/lib/$real"
ln -sf "$real" "$root/lib/libsurfadapt.so.$soversion"
ln -sf "libsurfadapt.so.$soversion" "$root/lib/libsurfadapt.so"
install -m 644 lib/libsurfadapt.a "$root/lib/libsurfadapt.a"
install -m 644 lib/libsurfadapt_fortran.a "$root/lib/libsurfadapt_fortran.a"
# Beside the C header, so that one -I serves C and Fortran hosts.
install -m 644 lib/fortran/surfadapt.mod "$root/include/surfadapt.mod"
# Its RUNPATH $ORIGIN/../lib finds the library in the installed tree as in the build tree.
install -m 755 bin/surfadapt "$root/bin/surfadapt"

render cmake/surfadapt.pc.in "$root/lib/pkgconfig/surfadapt.pc"
render cmake/surfadaptConfig.cmake.in "$root/lib/cmake/surfadapt/surfadaptConfig.cmake"
render cmake/surfadaptConfigVersion.cmake.in "$root/lib/cmake/surfadapt/surfadaptConfigVersion.cmake"

echo "surfadapt $version installed in $root"
