#!/usr/bin/env bash
# check-package.sh MARBLER.deb: the package's contents and metadata, in a few seconds and without
# installing it (./dev.sh test runs it; packaging/install-check.sh installs it on a fresh Debian):
# the files an installed Marbler needs, runtime dependencies from the binaries and no -dev
# package, valid AppStream and launcher files, a manual page, and no lintian error.
set -euo pipefail
if [ $# -ne 1 ] || [ ! -f "$1" ]; then
    echo "usage: $0 MARBLER.deb" >&2
    exit 2
fi
deb=$1
fail() {
    echo "check-package: FAIL: $*" >&2
    exit 1
}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

field() { dpkg-deb -f "$deb" "$1"; }
[ "$(field Package)" = marbler ] || fail "Package is '$(field Package)'"
[ "$(field Architecture)" = amd64 ] || fail "Architecture is '$(field Architecture)'"
[ "$(field Section)" = graphics ] || fail "Section is '$(field Section)'"
[ -n "$(field Maintainer)" ] || fail "no Maintainer"
depends=$(field Depends)
# shlibdeps: the libraries the executable and its modules link, by their runtime packages.
for lib in libc6 libqt6widgets6 libqt6opengl6 libopenimageio libavcodec qt6-qpa-plugins; do
    grep -qE "(^|, )${lib}[a-z0-9.-]*( |,|$)" <<<"$depends" || fail "Depends lacks $lib: $depends"
done
! grep -qE -- '-dev\b' <<<"$depends" || fail "Depends names a development package: $depends"

dpkg-deb -c "$deb" | awk '{ print $NF }' | sed 's|^\./|/|' >"$tmp/files"
for f in /usr/bin/marbler /usr/lib/marbler/marbler-window.so /usr/lib/marbler/marbler-imageio.so \
    /usr/lib/marbler/marbler-video.so /usr/share/applications/marbler.desktop \
    /usr/share/icons/hicolor/scalable/apps/marbler.svg /usr/share/mime/packages/marbler.xml \
    /usr/share/metainfo/io.github.marbler.Marbler.metainfo.xml /usr/share/man/man1/marbler.1.gz \
    /usr/share/bash-completion/completions/marbler /usr/share/doc/marbler/copyright \
    /usr/share/doc/marbler/changelog.gz /usr/share/doc/marbler/examples/five-stones.marble.json; do
    grep -qx -- "$f" "$tmp/files" || fail "the package has no $f"
done
! grep -q '^/usr/local' "$tmp/files" || fail "the package installs into /usr/local"

dpkg-deb -x "$deb" "$tmp/root"
appstreamcli validate --no-net "$tmp/root/usr/share/metainfo/io.github.marbler.Marbler.metainfo.xml" >"$tmp/appstream" 2>&1 ||
    { cat "$tmp/appstream"; fail "appstreamcli validate"; }
desktop-file-validate "$tmp/root/usr/share/applications/marbler.desktop" || fail "desktop-file-validate"
# The packed executable runs, and finds its modules in ../lib/marbler, not in the build tree.
"$tmp/root/usr/bin/marbler" --version >/dev/null || fail "the packed marbler does not run"
env -u MARBLER_MODULE_DIR "$tmp/root/usr/bin/marbler" doctor >"$tmp/doctor" 2>&1 || true
grep -q "$tmp/root/usr/lib/marbler/marbler-window.so" "$tmp/doctor" ||
    { cat "$tmp/doctor"; fail "the packed marbler does not load its modules from its own lib/marbler"; }

# lintian: errors fail; warnings are listed (docs/packaging.md says which remain and why).
lintian --fail-on error --tag-display-limit 0 "$deb" >"$tmp/lintian" 2>&1 || { cat "$tmp/lintian"; fail "lintian reports errors"; }
if [ -s "$tmp/lintian" ]; then
    echo "lintian's remaining tags:"
    cat "$tmp/lintian"
fi
echo "check-package: $(basename "$deb"): $(wc -l <"$tmp/files") paths, metadata valid, no lintian error"
