#!/usr/bin/env bash
# Installs the .deb (default: the one scripts/make-deb.sh made) into a clean Debian 12 made by debootstrap
# and checks what a user gets: mcpp on the PATH, its version, man page, desktop entry and icon, and a batch
# plan of the installed sample. Needs root (debootstrap, chroot) and the network to a Debian mirror.
# The Debian 12 tree is kept in build/debian12 (remove it for a fresh one): MCPP_DEBIAN_ROOT overrides.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
deb="$(realpath "${1:-$(ls "$root"/build/package/mcpp_*_amd64.deb)}")"
target="${MCPP_DEBIAN_ROOT:-$root/build/debian12}"
mirror="${MCPP_DEBIAN_MIRROR:-http://deb.debian.org/debian}"
bash "$root/scripts/install-dependencies.sh" debootstrap

if [ ! -x "$target/usr/bin/apt-get" ]; then
  rm -rf "$target"
  debootstrap --variant=minbase bookworm "$target" "$mirror" >/dev/null
fi
# A fresh copy of the clean tree for each run, so a second run checks a clean install again.
work="$(mktemp -d)"
cleanup() {
  umount "$work/root/proc" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
cp -a "$target" "$work/root"
cp /etc/resolv.conf "$work/root/etc/resolv.conf"
mount -t proc proc "$work/root/proc"
cp "$deb" "$work/root/tmp/"
in_debian() { chroot "$work/root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root "$@"; }

in_debian apt-get update -qq
in_debian env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
  "/tmp/$(basename "$deb")" >/dev/null
echo "installed: $(in_debian dpkg-query -W -f='${Package} ${Version} (${Installed-Size} KiB)' mcpp)"
in_debian mcpp --version
for file in /usr/bin/mcpp /usr/share/man/man1/mcpp.1.gz /usr/share/applications/mcpp.desktop \
  /usr/share/icons/hicolor/scalable/apps/mcpp.svg /usr/share/icons/hicolor/48x48/apps/mcpp.png \
  /usr/share/mcpp/samples/zion-nlcd/mission.json /usr/share/mcpp/presets/nlcd.csv; do
  [ -f "$work/root$file" ] || { echo "missing from the package: $file" >&2; exit 1; }
done
in_debian env QT_QPA_PLATFORM=offscreen mcpp --batch --quiet /usr/share/mcpp/samples/zion-nlcd/mission.json \
  --out /tmp/mcpp-out
for output in plan.geojson plan.gpkg report.json plan.png robot_0.plan; do
  [ -s "$work/root/tmp/mcpp-out/$output" ] || { echo "batch run wrote no $output" >&2; exit 1; }
done
echo "mcpp --batch planned the installed sample: $(ls "$work/root/tmp/mcpp-out" | wc -l) files in /tmp/mcpp-out"
