#!/usr/bin/env bash
# What a user waits for, split up: `mcpp --batch` with its default outputs on the bundled samples, uniform
# grids and block maps of 0.1 M to 25 M pixels. Per case: raster read, planning and output writing (from
# report.json's process_ms), the whole process and its peak memory (/usr/bin/time), the output folder's
# size, and the whole-process target of 1.5 x (read + plan) + 0.2 s.
#   bench/outputs-batch.sh [MCPP] [CASE...]
# MCPP defaults to build/release/app/mcpp; CASE names pick cases (default: all), e.g. uniform-200-20.
# MCPP_EXTRA_ARGS is added to every run, e.g. MCPP_EXTRA_ARGS="--planner cppied".
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
mcpp="${1:-$root/build/release/app/mcpp}"
shift || true
wanted=("$@")
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
export QT_QPA_PLATFORM=offscreen

selected() {
    [ ${#wanted[@]} -eq 0 ] && return 0
    local name
    for name in "${wanted[@]}"; do [ "$name" = "$1" ] && return 0; done
    return 1
}

printf '%-22s %9s %9s %8s %8s %8s %8s %8s %9s %8s %5s\n' \
    case pixels cells read_s plan_s write_s total_s peak_MB output_MB target_s met
# run_case NAME RASTER MCPP-ARGUMENTS...
run_case() {
    local name="$1" raster="$2"
    shift 2
    selected "$name" || return 0
    local out="$scratch/out-$name"
    # shellcheck disable=SC2086
    /usr/bin/time -f '%e %M' -o "$scratch/time" "$mcpp" --batch "$@" ${MCPP_EXTRA_ARGS:-} --out "$out" -q ||
        { echo "$name: mcpp failed" >&2; return 0; }
    read -r wall kilobytes <"$scratch/time"
    local bytes
    bytes="$(du -sb "$out" | cut -f1)"
    python3 - "$out/report.json" "$name" "$wall" "$kilobytes" "$bytes" "$raster" <<'PY'
import json, subprocess, sys
report = json.load(open(sys.argv[1]))
name, wall, kilobytes, size = sys.argv[2], float(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5])
process = report["process_ms"]
read, plan, write = process["read_raster"] / 1000, process["plan"] / 1000, process["write_outputs"] / 1000
cells = sum(robot["cells"] for robot in report["robots"])
info = subprocess.run(["gdalinfo", sys.argv[6]], capture_output=True, text=True).stdout
pixels = "-"
for line in info.splitlines():
    if line.startswith("Size is"):
        columns, rows = (int(v) for v in line[7:].split(","))
        pixels = f"{columns * rows / 1e6:.2f}M"
target = 1.5 * (read + plan) + 0.2
print(f"{name:<22} {pixels:>9} {cells:9d} {read:8.2f} {plan:8.2f} {write:8.2f} {wall:8.2f} "
      f"{kilobytes / 1024:8.0f} {size / 1e6:9.1f} {target:8.2f} {'yes' if wall <= target else 'no':>5}")
PY
}

maps="$scratch/maps"
mkdir -p "$maps"
run_case sample-zion-nlcd "$root/samples/zion-nlcd/nlcd.tif" "$root/samples/zion-nlcd/mission.json"
run_case sample-spain-corine "$root/samples/spain-corine/clc.tif" "$root/samples/spain-corine/mission.json"
run_case sample-synthetic "$root/samples/synthetic/synthetic.asc" "$root/samples/synthetic/mission.json"
for spec in "49 8" "49 20" "100 14" "200 4" "200 20"; do
    read -r side robots <<<"$spec"
    name="uniform-$side-$robots"
    selected "$name" || continue
    mkdir -p "$maps/$name"
    # shellcheck disable=SC2046
    run_case "$name" "$maps/$name/uniform_$side.tif" \
        $(python3 "$root/bench/make_benchmark_map.py" uniform "$side" "$robots" "$maps/$name")
done
for side in 316 1000 2000 3000 4000 5000; do
    name="blocks-$side"
    selected "$name" || continue
    mkdir -p "$maps/$name"
    # shellcheck disable=SC2046
    run_case "$name" "$maps/$name/blocks_${side}x$side.tif" \
        $(python3 "$root/bench/make_benchmark_map.py" blocks "$side" "$side" 6 "$maps/$name")
    rm -rf "${maps:?}/$name"
done
# The most cells a map can hold for its size: 5.0 M and 17.4 M cells (the second takes about half a minute and
# 3.1 GB, and is run only when named).
for side in 2240 4250; do
    name="forest-$side"
    if [ "$side" = 4250 ] && [ ${#wanted[@]} -eq 0 ]; then continue; fi
    selected "$name" || continue
    mkdir -p "$maps/$name"
    # shellcheck disable=SC2046
    run_case "$name" "$maps/$name/forest_$side.tif" \
        $(python3 "$root/bench/make_benchmark_map.py" forest "$side" 6 "$maps/$name")
    rm -rf "${maps:?}/$name"
done
principe="$root/../shared/data/landcover/worldcover2021_principe_crop.tif"
if [ -f "$principe" ]; then
    for planner in mcpp-mlct darp; do
        run_case "principe-$planner" "$principe" --raster "$principe" --preset esa-worldcover --start 7.40,1.62 \
            --start 7.42,1.66 --start 7.38,1.58 --start 7.41,1.60 --start-crs EPSG:4326 --planner "$planner"
    done
fi
