#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Checks that the Debian packages surfadapt builds with are present. As root, installs
# what is missing with apt-get; otherwise names it in one message and fails.
# Usage: ensure-deps.sh [build|check|doc]   (check and doc need more than build)
set -u
need="$*"
missing=""

have_header() { [ -f "/usr/include/$1" ]; }
have_cmd() { command -v "$1" >/dev/null 2>&1; }

have_cmd g++ || missing="$missing g++"
have_cmd gfortran || missing="$missing gfortran"
have_header eigen3/Eigen/Core || missing="$missing libeigen3-dev"
case " $need " in
  *" check "*)
    have_header cmocka.h || missing="$missing libcmocka-dev"
    have_header gmpxx.h || missing="$missing libgmp-dev"
    have_cmd abidiff || missing="$missing abigail-tools"
    have_cmd clang || missing="$missing clang"
    [ -n "$(ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.asan-x86_64.a 2>/dev/null)" ] ||
      missing="$missing libclang-rt-dev"
    have_cmd pkg-config || missing="$missing pkg-config"
    # The Python binding's test runs Debian's own interpreter, the one python3-numpy
    # serves: a python3 earlier on PATH (pyenv, a venv) may lack numpy.
    { [ -x /usr/bin/python3 ] && /usr/bin/python3 -c 'import numpy' 2>/dev/null; } ||
      missing="$missing python3-numpy"
    ;;
esac
case " $need " in
  *" doc "*) have_cmd doxygen || missing="$missing doxygen" ;;
esac

[ -z "$missing" ] && exit 0
if [ "$(id -u)" = 0 ] && have_cmd apt-get; then
  echo "surfadapt: installing missing Debian packages:$missing"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq >/dev/null && apt-get install -y -qq $missing >/dev/null && exit 0
  echo "surfadapt: apt-get could not install:$missing" >&2
  exit 1
fi
echo "surfadapt: missing Debian packages:$missing" >&2
echo "surfadapt: install them with: sudo apt-get install$missing" >&2
exit 1
