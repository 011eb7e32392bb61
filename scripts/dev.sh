#!/usr/bin/env bash
# Frezka developer entry point.
#   scripts/dev.sh run   install what is missing, build, start the GUI on the built-in emulator
#   scripts/dev.sh test  install what is missing, build, run the whole test suite (ctest)
#   scripts/dev.sh build install what is missing and build only
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
build="${FREZKA_BUILD_DIR:-$root/build}"

install_missing() {
    local missing=()
    while read -r pkg; do
        [[ -z "$pkg" || "$pkg" == \#* ]] && continue
        if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
            missing+=("$pkg")
        fi
    done < scripts/packages.txt
    if ((${#missing[@]})); then
        echo "Installing missing Debian packages: ${missing[*]}"
        local sudo=""
        [[ $(id -u) -ne 0 ]] && sudo="sudo"
        $sudo apt-get update -qq
        DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
    fi
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
*)
    echo "usage: scripts/dev.sh run|test|build" >&2
    exit 2
    ;;
esac
