#!/bin/sh
# install.desktop_validate / install.appstream_validate: TOOL FILE. Exit 77 (skipped, with the
# reason printed) when the validator is not installed (Debian: desktop-file-utils, appstream).
tool=$1
file=$2
if ! command -v "$tool" >/dev/null 2>&1; then
    echo "SKIPPED: $tool is not installed (apt-get install desktop-file-utils appstream)"
    exit 77
fi
case $tool in
appstreamcli) exec appstreamcli validate --no-net --pedantic "$file" ;;
*) exec "$tool" "$file" ;;
esac
