#!/usr/bin/env bash
# Frezka developer entry point.
#   scripts/dev.sh run   install what is missing, build, start the GUI on the built-in emulator
#   scripts/dev.sh test  install what is missing, build, run the whole test suite (ctest)
#   scripts/dev.sh build install what is missing and build only
#   scripts/dev.sh package       ... and make the Debian package build/frezka_*.deb (CPack),
#                                checked by lintian
#   scripts/dev.sh package-test  ... and install it in a fresh Debian 12 root (debootstrap,
#                                needs root and the Debian mirror) and run it there
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
build="${FREZKA_BUILD_DIR:-$root/build}"

# Installs the packages listed in the given files (default scripts/packages.txt) that are
# missing: as root directly, else with sudo. Without root and without sudo it names what is
# missing and the one command that installs it, and exits with status 3.
install_missing() {
    local lists=("$@") missing=()
    ((${#lists[@]})) || lists=(scripts/packages.txt)
    while read -r pkg; do
        [[ -z "$pkg" || "$pkg" == \#* ]] && continue
        if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
            missing+=("$pkg")
        fi
    done < <(cat "${lists[@]}")
    ((${#missing[@]})) || return 0
    local sudo=""
    if [[ $(id -u) -ne 0 ]]; then
        if ! command -v sudo >/dev/null 2>&1; then
            {
                echo "scripts/dev.sh: these Debian packages are missing: ${missing[*]}"
                echo "sudo is not installed, so they cannot be installed from this account."
                echo "Install them as root (su -), then run this command again:"
                echo "    apt-get update && apt-get install --no-install-recommends ${missing[*]}"
            } >&2
            exit 3
        fi
        sudo="sudo"
    fi
    echo "Installing missing Debian packages: ${missing[*]}"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

configure_and_build() {
    if [[ ! -f "$build/build.ninja" ]]; then
        cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
    fi
    cmake --build "$build" -j"$(nproc)"
}

cmd="${1:-run}"
shift || true
case "$cmd" in
run)
    install_missing
    configure_and_build
    exec "$build/app/frezka" "$@"
    ;;
test)
    install_missing
    configure_and_build
    # Tests compare English messages: run them in the C locale whatever the user's language.
    export LC_ALL=C.UTF-8 LANGUAGE=
    export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-$(mktemp -d)}"
    chmod 700 "$XDG_RUNTIME_DIR"
    cd "$build"
    exec ctest --output-on-failure -j"$(nproc)" "$@"
    ;;
build)
    install_missing
    configure_and_build
    ;;
package)
    install_missing scripts/packages.txt scripts/packages-package.txt
    configure_and_build
    exec scripts/package.sh "$build"
    ;;
package-test)
    install_missing scripts/packages.txt scripts/packages-package.txt
    configure_and_build
    scripts/package.sh "$build"
    exec scripts/package-test.sh "$build"
    ;;
*)
    echo "usage: scripts/dev.sh run|test|build|package|package-test" >&2
    exit 2
    ;;
esac
