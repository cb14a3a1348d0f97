#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Installs surfadapt under DESTDIR/PREFIX: header, shared library with its SONAME and
# development symlinks, static libraries, Fortran module and its source, Python module,
# command-line tool, pkg-config file and CMake package (the items of install-manifest.sh). Run from the top of the tree
# after `make` (make install does).
# Usage: install.sh DESTDIR PREFIX VERSION SOVERSION   (DESTDIR may be empty)
set -eu
# shellcheck source=scripts/install-manifest.sh
. "$(dirname "$0")/install-manifest.sh"
install_arguments "$@"

items=$(manifest | grep -v '^#')

# Everything must be built before anything is copied, so that a failure installs nothing.
while read -r kind a b c; do
  case $kind in
    file) source=$b ;;
    template) source=$a ;;
    *) continue ;;
  esac
  [ -f "$source" ] || { echo "install.sh: $source is missing; run make first" >&2; exit 1; }
done <<ITEMS
$items
ITEMS

# sed replacement text: escape the characters that are special there.
quote() { printf '%s\n' "$1" | sed -e 's/[\\|&]/\\&/g'; }
render() {
  sed -e "s|@PREFIX@|$(quote "$prefix")|g" -e "s|@VERSION@|$(quote "$version")|g" \
      -e "s|@SOVERSION@|$(quote "$soversion")|g" "$1" >"$2"
  chmod 644 "$2"
}

while read -r kind a b c; do
  case $kind in
    file) target=$c ;;
    link | template) target=$b ;;
    *) echo "install.sh: unknown item '$kind' in install-manifest.sh" >&2; exit 1 ;;
  esac
  install -d "$root/$(dirname "$target")"
  case $kind in
    file) install -m "$a" "$b" "$root/$target" ;;
    link) ln -sf "$a" "$root/$target" ;;
    template) render "$a" "$root/$target" ;;
  esac
done <<ITEMS
$items
ITEMS

echo "surfadapt $version installed in $root"
