#!/usr/bin/env bash
# Robots setting off from one base: uniform grids (15 % obstacles) with every start inside one small square,
# planned by `mcpp --batch`. Per case and binary: the ratio of the makespan to the lower bound, the turns,
# the allocation and planning time (report.json) and the whole process (/usr/bin/time), and whether the
# plan carries the uneven-plan warning.
#   [PLANNER_FLAGS="--planner mstc --param balanced=true"] bench/crowded-starts.sh [MCPP...]
# MCPP defaults to build/release/app/mcpp; several binaries are run case by case, one after the other.
# PLANNER_FLAGS are given to every run (default: none, the default planner).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
binaries=("$@")
[ ${#binaries[@]} -eq 0 ] && binaries=("$root/build/release/app/mcpp")
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
export QT_QPA_PLATFORM=offscreen

printf '%-16s %-10s %8s %7s %9s %8s %8s %7s\n' case binary ratio turns alloc_ms plan_ms total_s warned
# side robots window: eight robots in 7 x 7 cells, twenty in 9 x 9 on 49 x 49; fourteen in 11 x 11 on 100 x 100
for setting in "49 8 7" "49 20 9" "100 14 11"; do
    read -r side robots window <<<"$setting"
    for seed in 1 2 3 4 5 6; do
        name="$side-$robots-seed$seed"
        map="$scratch/map-$name"
        mkdir -p "$map"
        flags="$(python3 "$root/bench/make_benchmark_map.py" crowded "$side" "$robots" "$window" "$seed" "$map" |
            tail -1)"
        for index in "${!binaries[@]}"; do
            out="$scratch/out-$name-$index"
            # shellcheck disable=SC2086
            /usr/bin/time -f '%e' -o "$scratch/time" "${binaries[$index]}" --batch $flags ${PLANNER_FLAGS:-} \
                --out "$out" -q
            python3 - "$out/report.json" "$name" "$index" "$(cat "$scratch/time")" <<'PY'
import json, sys
report = json.load(open(sys.argv[1]))
turns = sum(robot["turns"] for robot in report["robots"])
warned = any(issue["code"] == "uneven-plan" for issue in report.get("issues", []))
print(f"{sys.argv[2]:<16} {'#' + sys.argv[3]:<10} {report['ratio']:8.4f} {turns:7d} "
      f"{report['timings_ms']['allocation']:9.0f} {report['process_ms']['plan']:8.0f} {float(sys.argv[4]):8.2f} "
      f"{'yes' if warned else 'no':>7}")
PY
        done
    done
done
