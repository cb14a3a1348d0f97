#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Removes from DESTDIR/PREFIX exactly what install.sh put there (the items of
# install-manifest.sh), what using them made beside them (Python's byte code of the
# module), and the package's own directories once they are empty; shared
# directories such as PREFIX/lib stay, and so does anything else in them. Run it from
# the tree of the version that was installed: the shared library's name carries it.
# Usage: uninstall.sh DESTDIR PREFIX VERSION SOVERSION   (DESTDIR may be empty)
set -eu
# shellcheck source=scripts/install-manifest.sh
. "$(dirname "$0")/install-manifest.sh"
install_arguments "$@"

removed=0
missing=""
while read -r kind _ b c; do
  case $kind in
    file) target=$c ;;
    link | template) target=$b ;;
    *) continue ;;
  esac
  # A link counts even when what it points to is gone already.
  if [ -e "$root/$target" ] || [ -L "$root/$target" ]; then
    rm -f "$root/$target"
    removed=$((removed + 1))
  else
    missing="$missing $target"
  fi
done <<ITEMS
$(manifest | grep -v '^#')
ITEMS

made_by_use | while read -r pattern; do
  # The pattern is expanded under $root, on purpose; no match leaves it as it is.
  # shellcheck disable=SC2086
  for file in "$root"/$pattern; do
    if [ -f "$file" ]; then rm -f "$file"; fi
  done
done

for dir in $(own_directories); do
  if [ -d "$root/$dir" ] && ! rmdir "$root/$dir" 2>/dev/null; then
    echo "uninstall.sh: kept $root/$dir: it holds files that surfadapt did not install"
  fi
done

if [ "$removed" -eq 0 ]; then
  echo "uninstall.sh: surfadapt $version is not installed in $root (none of its files is there)" >&2
  exit 1
fi
[ -z "$missing" ] || echo "uninstall.sh: already missing from $root:$missing"
echo "surfadapt $version uninstalled from $root ($removed files and links removed)"
