#!/usr/bin/env bash
# The install as a user gets it: `cmake --install` into a temporary DESTDIR, the installed
# isurface-cli run from there on an installed sample (its resources are compiled in: no file of
# the source or build tree is needed), the desktop entry validated, the file types compiled by
# update-mime-database, the man pages formatted without warnings, the bash completion loaded,
# and `cpack -G DEB`'s package listed with its dependencies.
# Usage: install_test.sh BUILD_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
work=$(mktemp -d /tmp/isurface-install.XXXXXX)
trap 'rm -rf "$work"' EXIT
fail() { echo "install_test: $*" >&2; exit 1; }

DESTDIR="$work/root" cmake --install "$build" --prefix /usr > "$work/install.log"
root="$work/root/usr"
for f in bin/isurface bin/isurface-cli bin/isurface-cli-all share/applications/isurface.desktop \
         share/mime/packages/isurface.xml share/man/man1/isurface.1.gz share/man/man1/isurface-cli.1.gz \
         share/bash-completion/completions/isurface-cli share/isurface/samples/transition-surface.nc \
         share/isurface/machines/default.json share/icons/hicolor/48x48/apps/isurface.png; do
  [ -e "$root/$f" ] || fail "not installed: $f"
done

# The installed programs, away from the source and build trees.
cd "$work"
"$root/bin/isurface-cli" --version | grep -q "0\." || fail "isurface-cli --version"
"$root/bin/isurface" --version | grep -q "^isurface " || fail "isurface --version"
"$root/bin/isurface-cli" render "$root/share/isurface/samples/transition-surface.nc" -o "$work/map.png" \
  --size 320x240 > "$work/render.log" 2>&1 || { cat "$work/render.log" >&2; fail "installed render failed"; }
file "$work/map.png" | grep -q "PNG image data, 320 x 240" || fail "the installed render wrote no 320x240 PNG"
file "$root/share/icons/hicolor/16x16/apps/isurface.png" | grep -q "PNG image data, 16 x 16" || fail "16 px icon"

desktop-file-validate "$root/share/applications/isurface.desktop" || fail "desktop entry"
xmllint --noout "$root/share/mime/packages/isurface.xml" || fail "MIME XML"
XDG_DATA_DIRS="$root/share:/usr/share" update-mime-database "$root/share/mime" > "$work/mime.log" 2>&1 \
  || { cat "$work/mime.log" >&2; fail "update-mime-database"; }
! grep -qiE "error|warning|invalid|unknown" "$work/mime.log" || { cat "$work/mime.log" >&2; fail "update-mime-database complained"; }
grep -q "application/x-isurface-biip" "$root/share/mime/magic" || fail "no magic for .biip dumps"
grep -q "text/x-gcode" "$root/share/mime/globs2" || fail "no glob for G-code"

for page in isurface isurface-cli; do
  warnings=$(LC_ALL=C.UTF-8 MANWIDTH=80 man --warnings -l "$root/share/man/man1/$page.1.gz" 2>&1 > "$work/$page.txt")
  [ -z "$warnings" ] || fail "man $page: $warnings"
done
grep -q "isurface-cli render" "$work/isurface-cli.txt" || fail "the isurface-cli page has no render section"
bash -c "source '$root/share/bash-completion/completions/isurface-cli' && complete -p isurface-cli" > /dev/null \
  || fail "bash completion"

(cd "$build" && cpack -G DEB -B "$work/package" > "$work/cpack.log" 2>&1) || { cat "$work/cpack.log" >&2; fail "cpack"; }
deb=$(ls "$work"/package/*.deb)
echo "package: $(basename "$deb")"
echo "Depends: $(dpkg-deb -f "$deb" Depends)"
dpkg-deb -f "$deb" Depends | grep -q "libvtk9" || fail "the package does not depend on VTK's runtime library"
dpkg-deb -c "$deb" | awk '{ print $6 }' | tee "$work/contents.txt" | grep -E "usr/bin/|\.desktop|\.1\.gz|\.1$|mime" 
grep -q "./usr/bin/isurface-cli$" "$work/contents.txt" || fail "the package has no isurface-cli"
echo "install_test: passed"
