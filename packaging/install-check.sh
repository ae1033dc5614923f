#!/usr/bin/env bash
# install-check.sh MARBLER.deb: the package on a brand-new Debian 12, as a person meets it. As
# root, on a machine where nothing of Marbler's build is installed (the lead's
# fresh-machine-check gives one):
#   cp build-package/marbler_*.deb /dev/shm/
#   ../shared/tools/fresh-machine-check 'bash packaging/install-check.sh /dev/shm/marbler_*.deb'
# It installs the package with apt (which must pull in only runtime libraries, no -dev package),
# then as an ordinary user runs `marbler --help`, a render of an example, `marbler doctor` and the
# window under a virtual display, checks the launcher and that genome files open in Marbler by
# their MIME type, removes the package and checks that none of its files is left.
set -euo pipefail
if [ $# -ne 1 ] || [ ! -f "$1" ]; then
    echo "usage: $0 MARBLER.deb (as root on a fresh Debian 12)" >&2
    exit 2
fi
deb=$(realpath "$1")
export DEBIAN_FRONTEND=noninteractive
step() { echo "== $*"; }
fail() {
    echo "install-check: FAIL: $*" >&2
    exit 1
}

step "installing $(basename "$deb") with apt"
apt-get update -qq
dpkg-query -W -f='${Package}\n' | sort >/tmp/packages-before
apt-get install -y -qq "$deb" >/tmp/apt-install.log 2>&1 || { tail -30 /tmp/apt-install.log; fail "apt-get install"; }
dpkg-query -W -f='${Package}\n' | sort >/tmp/packages-after
pulled=$(comm -13 /tmp/packages-before /tmp/packages-after)
echo "apt installed $(echo "$pulled" | wc -l) packages with marbler"
dev=$(echo "$pulled" | grep -E -- '-dev$|-dev-' || true)
[ -z "$dev" ] || fail "installing marbler pulled in development packages: $dev"
dpkg -L marbler | sort >/tmp/marbler-files

# What a desktop brings and the package does not need: a virtual display for the window, and
# xdg-utils with the MIME and launcher databases to ask which program opens a genome file.
step "installing xvfb and xdg-utils for the checks"
apt-get install -y -qq xvfb xauth xdg-utils libfile-mimeinfo-perl shared-mime-info desktop-file-utils \
    >/tmp/apt-tools.log 2>&1 ||
    { tail -30 /tmp/apt-tools.log; fail "installing the tools of the check"; }

# A chroot made in a mktemp -d folder has a root of mode 0700, which no user but root can
# enter; a real machine's is 0755.
[ "$(stat -c %a /)" = 755 ] || chmod 755 /
id marbler-user >/dev/null 2>&1 || useradd -m marbler-user
as_user() { runuser -u marbler-user -- env HOME=/home/marbler-user "$@"; }
home=/home/marbler-user

step "marbler --help"
help=$(as_user marbler --help) || fail "marbler --help"
grep -q "^usage: marbler" <<<"$help" || fail "marbler --help prints no usage"
man_page=$(dpkg -L marbler | grep '/man1/marbler.1.gz$') || fail "no manual page in the package"
grep -q '^\.SH EXAMPLES' <(zcat "$man_page") || fail "the manual page has no examples"
test -f /usr/share/bash-completion/completions/marbler || fail "no bash completion"

step "marbler render an example"
example=/usr/share/doc/marbler/examples/five-stones.marble.json
test -f "$example" || fail "no example at $example"
as_user marbler render "$example" -o "$home/five-stones.png" --width 256
as_user marbler info "$home/five-stones.png" >/dev/null || fail "the render carries no valid genome"
[ "$(head -c 8 "$home/five-stones.png" | od -An -tx1 | tr -d ' ')" = 89504e470d0a1a0a ] ||
    fail "the render is not a PNG"
as_user marbler render "$example" -o "$home/five-stones.exr" --width 64 ||
    fail "an EXR render (the image module, /usr/lib/marbler)"

step "marbler doctor"
as_user marbler doctor >/tmp/doctor.txt 2>&1 || { cat /tmp/doctor.txt; fail "marbler doctor"; }
grep -q /usr/lib/marbler /tmp/doctor.txt || { cat /tmp/doctor.txt; fail "doctor does not find the modules in /usr/lib/marbler"; }

step "the window under xvfb-run"
as_user xvfb-run -a -s "-screen 0 1280x1024x24" marbler --flat --seed 1 --screenshot "$home/window.png" \
    >/tmp/window.log 2>&1 || { cat /tmp/window.log; fail "the window"; }
[ "$(stat -c %s "$home/window.png")" -gt 10000 ] || fail "the window's screenshot is empty"

step "the launcher and the MIME type"
desktop-file-validate /usr/share/applications/marbler.desktop || fail "the launcher is not valid"
test -f /usr/share/metainfo/io.github.marbler.Marbler.metainfo.xml || fail "no AppStream metadata"
cp "$example" "$home/mine.marble.json" && chown marbler-user "$home/mine.marble.json"
type=$(as_user xdg-mime query filetype "$home/mine.marble.json")
[ "$type" = application/x-marbler-genome ] || fail "a .marble.json file is '$type', not application/x-marbler-genome"
app=$(as_user xdg-mime query default application/x-marbler-genome)
[ "$app" = marbler.desktop ] || fail "genome files open with '$app', not marbler.desktop"

step "apt-get remove marbler"
apt-get remove -y -qq marbler >/tmp/apt-remove.log 2>&1 || { tail -30 /tmp/apt-remove.log; fail "apt-get remove"; }
left=""
while read -r path; do
    [ -e "$path" ] || continue
    # A folder other packages also use (/usr/share/man/man1, ...) stays; the package's own go.
    if [ -d "$path" ] && [ -n "$(ls -A "$path")" ]; then continue; fi
    if [ -d "$path" ] && dpkg -S "$path" >/dev/null 2>&1; then continue; fi
    left+=" $path"
done </tmp/marbler-files
[ -z "$left" ] || fail "left behind after apt-get remove:$left"
for path in /usr/bin/marbler /usr/lib/marbler /usr/share/doc/marbler; do
    [ ! -e "$path" ] || fail "left behind after apt-get remove: $path"
done
echo "install-check: marbler $(dpkg-deb -f "$deb" Version) installed ($(echo "$pulled" | wc -l) packages, no -dev), ran (help, render, doctor, window, MIME) and was removed without a trace"
