#!/usr/bin/env bash
# Builds mcpp for packaging and makes build/package/mcpp_<version>_amd64.deb: the executable in /usr/bin,
# the desktop entry and icons, the samples and presets under /usr/share/mcpp, a man page from --help.
# Dependencies are computed from the binaries (dpkg-shlibdeps).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash scripts/install-dependencies.sh help2man dpkg-dev file
cmake --preset package >/dev/null
cmake --build --preset package
cd build/package
rm -f mcpp_*.deb
cpack -G DEB >/dev/null
deb="$(ls "$PWD"/mcpp_*_amd64.deb)"
echo "$deb"
