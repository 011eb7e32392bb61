#!/usr/bin/env bash
# The package in a fresh Debian 12 root (issue 18 "Done when"): debootstrap a minimal bookworm
# from the mirror this machine's apt uses, `apt-get install ./frezka_*.deb` in it, then there:
# `frezka --version`, `frezka-cli check` of the installed sample, and the window under xvfb-run
# still up after 10 s. Needs root (debootstrap, chroot) and the mirror; where it cannot run it
# prints why and exits 77 (skipped), never silently.
#   scripts/package-test.sh BUILD_DIR     (after scripts/package.sh BUILD_DIR)
# The root is kept in BUILD_DIR/package-root/base and copied for each run, so a second run does
# not download the base system again; delete the folder for a fresh one.
set -euo pipefail
build=$(cd "${1:?usage: scripts/package-test.sh BUILD_DIR}" && pwd)
skip() {
    echo "SKIPPED: the clean-root install test cannot run here: $*"
    exit 77
}
deb=$(ls "$build"/frezka_*.deb 2>/dev/null | head -1) || true
[[ -n "$deb" ]] || { echo "no package in $build: run scripts/dev.sh package first" >&2; exit 1; }
[[ $(id -u) -eq 0 ]] || skip "it needs root for debootstrap and chroot (run it as root)"
command -v debootstrap >/dev/null || skip "debootstrap is not installed (apt-get install debootstrap)"
mirror=$(sed -n 's/^URIs: *\(http[^ ]*\/debian\)$/\1/p' /etc/apt/sources.list.d/debian.sources \
    2>/dev/null | head -1)
mirror=${mirror:-http://deb.debian.org/debian}

base="$build/package-root/base"
if [[ ! -x "$base/usr/bin/apt-get" ]]; then
    rm -rf "$base"
    echo "debootstrap bookworm from $mirror into $base (a few minutes, once)"
    debootstrap --variant=minbase bookworm "$base" "$mirror" >"$build/package-root.log" 2>&1 ||
        skip "debootstrap failed (no mirror or no chroot here; see $build/package-root.log)"
fi
root="$build/package-root/run"
rm -rf "$root"
cp -a "$base" "$root"
cleanup() {
    umount "$root/proc" 2>/dev/null || true
    rm -rf "$root"
}
trap cleanup EXIT
mount -t proc proc "$root/proc" || skip "cannot mount /proc in the root (no privileges here)"
cp /etc/resolv.conf "$root/etc/resolv.conf"
cp "$deb" "$root/tmp/"
in_root() { chroot "$root" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LC_ALL=C.UTF-8 "$@"; }

echo "== apt-get install ./$(basename "$deb") (and xvfb, xauth to start the window)"
in_root apt-get update -qq
in_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "/tmp/$(basename "$deb")" \
    xvfb xauth >"$build/package-test-apt.log" 2>&1 ||
    { tail -30 "$build/package-test-apt.log"; echo "FAILED: apt-get install" >&2; exit 1; }
echo "== frezka --version"
in_root frezka --version
echo "== frezka-cli check /usr/share/frezka/programs/frezka-demo.nc"
in_root frezka-cli check /usr/share/frezka/programs/frezka-demo.nc
echo "== xvfb-run frezka: the window must still be up after 10 s"
set +e
in_root xvfb-run -a timeout 10 frezka --software-view /usr/share/frezka/programs/frezka-demo.nc \
    >"$build/package-test-gui.log" 2>&1
rc=$?
set -e
if [[ $rc -ne 124 ]]; then
    cat "$build/package-test-gui.log"
    echo "FAILED: frezka ended within 10 s (exit $rc)" >&2
    exit 1
fi
echo "frezka ran 10 s under xvfb-run (stopped by timeout)"
echo "PASSED: the package installs and runs in a fresh Debian 12 root"
