# SPDX-License-Identifier: BSD-3-Clause
# shellcheck shell=sh
# What `make install` puts where: sourced by install.sh, which installs these items, and
# by uninstall.sh, which removes exactly them, so that the two cannot disagree.
#
# install_arguments DESTDIR PREFIX VERSION SOVERSION checks the arguments and sets
# destdir, prefix, root (= DESTDIR/PREFIX), version and soversion. manifest then prints
# one item per line, TARGET relative to PREFIX (lines starting with # are comments):
#   file MODE SOURCE TARGET   a copy of SOURCE (relative to the top of the tree)
#   link POINTS_TO TARGET     a symbolic link
#   template SOURCE TARGET    SOURCE with @PREFIX@, @VERSION@ and @SOVERSION@ filled in
# own_directories lists the directories, relative to PREFIX, that only this package uses,
# deepest first; made_by_use the files that using the package makes in them (patterns).

# The variables it sets are for the script that sources this file.
# shellcheck disable=SC2034
install_arguments() {
  if [ $# -ne 4 ]; then
    echo "usage: $(basename "$0") DESTDIR PREFIX VERSION SOVERSION   (DESTDIR may be empty)" >&2
    exit 2
  fi
  destdir=$1
  prefix=$2
  version=$3
  soversion=$4
  case $prefix in
    /*) ;;
    *) echo "$(basename "$0"): PREFIX must be an absolute path, got '$prefix'" >&2; exit 2 ;;
  esac
  # Generated files name PREFIX, never DESTDIR: DESTDIR is only a staging root.
  prefix=${prefix%/}
  root=$destdir$prefix
}

manifest() {
  real=libsurfadapt.so.$version
  cat <<EOF
file 644 include/surfadapt.h include/surfadapt.h
file 755 lib/$real lib/$real
link $real lib/libsurfadapt.so.$soversion
link libsurfadapt.so.$soversion lib/libsurfadapt.so
file 644 lib/libsurfadapt.a lib/libsurfadapt.a
file 644 lib/libsurfadapt_fortran.a lib/libsurfadapt_fortran.a
# Beside the C header, so that one -I serves C and Fortran hosts.
file 644 lib/fortran/surfadapt.mod include/surfadapt.mod
# The module's source beside it: a .mod is gfortran's own format, so a host built with
# another compiler (ifx, nvfortran, Cray ftn, flang) compiles this with its sources.
file 644 bindings/fortran/surfadapt.f90 include/surfadapt.f90
# The Python module, pure Python: in a directory of its own rather than a site-packages
# path, which differs between Python versions and distributions. Hosts put it on
# PYTHONPATH; it finds PREFIX/lib/libsurfadapt.so.$soversion relative to itself.
file 644 bindings/python/surfadapt.py share/surfadapt/python/surfadapt.py
# Its RUNPATH \$ORIGIN/../lib finds the library in the installed tree as in the build tree.
file 755 bin/surfadapt bin/surfadapt
template cmake/surfadapt.pc.in lib/pkgconfig/surfadapt.pc
template cmake/surfadaptConfig.cmake.in lib/cmake/surfadapt/surfadaptConfig.cmake
template cmake/surfadaptConfigVersion.cmake.in lib/cmake/surfadapt/surfadaptConfigVersion.cmake
# The terms the whole of it is distributed under (BSD-3-Clause).
file 644 LICENSE share/doc/surfadapt/LICENSE
EOF
}

own_directories() {
  echo lib/cmake/surfadapt
  echo share/doc/surfadapt
  echo share/surfadapt/python/__pycache__
  echo share/surfadapt/python
  echo share/surfadapt
}

# Python writes the module's byte code beside it on import when it may (installed as
# root, imported as root); uninstall removes it with the module.
made_by_use() {
  echo 'share/surfadapt/python/__pycache__/surfadapt.*.pyc'
}
