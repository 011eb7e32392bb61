#!/usr/bin/env bash
# Makes the Debian package from a built tree (scripts/dev.sh package calls it after the build):
# CPack's DEB generator over the install rules (packaging/), then lintian, which must report no
# errors (tags accepted with a reason: packaging/lintian-accepted.txt).
#   scripts/package.sh BUILD_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:?usage: scripts/package.sh BUILD_DIR}
cd "$build"
rm -f frezka_*.deb
cpack -G DEB >cpack.log 2>&1 || { cat cpack.log >&2; echo "cpack failed" >&2; exit 1; }
deb=$(ls frezka_*.deb)
echo "Package: $build/$deb"
dpkg-deb --field "$deb" Package Version Architecture Depends Recommends
if command -v lintian >/dev/null 2>&1; then
    # --fail-on error: warnings and notes are printed, only errors fail the command.
    lintian --fail-on error --suppress-tags-from-file "$root/packaging/lintian-accepted.txt" \
        "$deb" || { echo "lintian found errors in $deb" >&2; exit 1; }
    echo "lintian: no errors"
else
    echo "lintian is not installed: the package was not checked (apt-get install lintian)"
fi
