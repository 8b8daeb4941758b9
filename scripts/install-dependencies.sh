#!/usr/bin/env bash
# Installs the Debian 12 packages mcpp needs to build, test and run, and any named on the command line;
# does nothing when all are there.
set -euo pipefail

packages=(
  g++ cmake ninja-build pkg-config git ca-certificates
  qt6-base-dev qt6-base-dev-tools qt6-charts-dev qt6-svg-dev libqt6opengl6-dev qt6-qpa-plugins libgl-dev
  libgdal-dev gdal-bin libeigen3-dev libboost-dev libbenchmark-dev libdeflate-dev
  xvfb xauth fonts-dejavu-core python3 clang-format clang libclang-rt-14-dev
)
# Extra packages a caller needs besides these (the packaging scripts pass theirs).
packages+=("$@")

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "mcpp: installing ${missing[*]}" >&2
if [ "$(id -u)" -eq 0 ]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1; then
  as_root=(sudo)
else
  echo "mcpp: these Debian packages are missing and neither root nor sudo is available: ${missing[*]}" >&2
  exit 2
fi
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
