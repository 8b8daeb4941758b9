#!/usr/bin/env bash
# Installs what is missing, builds a Release build and opens the bundled sample mission.
# Without a display it plans the sample in batch mode and says where the outputs are.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash scripts/install-dependencies.sh
cmake --preset release >/dev/null
cmake --build --preset release
mission="samples/zion-nlcd/mission.json"
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec build/release/app/mcpp "$mission"
fi
out="$root/build/sample-output"
QT_QPA_PLATFORM=offscreen build/release/app/mcpp --batch "$mission" --out "$out"
echo "No display: planned the sample in batch mode. Outputs are in $out"
