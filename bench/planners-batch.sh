#!/usr/bin/env bash
# Times what a user waits for: `mcpp --batch` on one mission, planning and every output, once per planner.
# Prints wall time, peak memory and the plan's figures from report.json.
#   bench/planners-batch.sh [MCPP] [MISSION]
# MCPP defaults to build/release/app/mcpp, MISSION to the bundled Zion NLCD sample (five robots); the
# one-robot planners get the mission's raster and class table with its first robot's start only.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
mcpp="${1:-$root/build/release/app/mcpp}"
mission="${2:-$root/samples/zion-nlcd/mission.json}"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
export QT_QPA_PLATFORM=offscreen

# Planner names and whether each takes one robot, from `mcpp --help`.
planners="$("$mcpp" --help | awk '/^Planners/{on=1; next} on && /^$/{exit} on{print $1}')"
one_robot_flags() {
    python3 - "$mission" <<'PY'
import json, os, sys
path = sys.argv[1]
mission = json.load(open(path))
base = os.path.dirname(path)
raster = os.path.join(base, mission["raster"]["path"])
table = os.path.join(base, "classes.csv")
x, y = mission["robots"][0]["start"]
print(f"--raster {raster} --classes {table} --start {x},{y}")
PY
}

printf '%-16s %8s %9s %8s %8s %9s %9s\n' planner wall_s peak_MB ratio turns covered repeated
for planner in $planners; do
    out="$scratch/$planner"
    if "$mcpp" --help-planner "$planner" | grep -q "one robot"; then
        arguments=(--batch $(one_robot_flags))
    else
        arguments=(--batch "$mission")
    fi
    /usr/bin/time -f '%e %M' -o "$scratch/time" "$mcpp" "${arguments[@]}" --planner "$planner" --out "$out" \
        >/dev/null 2>&1 || { echo "$planner: mcpp failed" >&2; continue; }
    read -r wall kilobytes <"$scratch/time"
    python3 - "$out/report.json" "$planner" "$wall" "$kilobytes" <<'PY'
import json, sys
report = json.load(open(sys.argv[1]))
turns = sum(robot["turns"] for robot in report["robots"])
print(f"{sys.argv[2]:<16} {float(sys.argv[3]):8.2f} {int(sys.argv[4]) / 1024:9.0f} {report['ratio']:8.3f} "
      f"{turns:8d} {report['covered_fraction']:9.3f} {report['repeated_fraction']:9.3f}")
PY
done
