#!/usr/bin/env bash
# Times in the field of drone missions on the Swiss CORINE raster of the shared data (corine-grid preset,
# multirotors at 8 m/s on 22-minute flights with 8-minute turnarounds and 400 items, at 60 m):
#   team   a 6 x 5 km area, three drones spread over it and a 1.5 m/s rover;
#   corner a 3.5 x 3.5 km area, two drones at its south-west corner;
#   road   an L: a 200 m strip with two drones at its south end, 1 km from a 2.7 x 2.5 km block.
# Per case: the paths' makespan and bound, when the last robot is home, the bound in the field, the last over
# the first robot home, the whole process and its peak memory (/usr/bin/time).
#   bench/drone-missions.sh RASTER [MCPP] [CASE...]
# RASTER: corine2006_swiss_ls100.tif; MCPP defaults to build/release/app/mcpp. KEEP_SCRATCH=1 keeps the
# missions and their outputs in the temporary folder (its name is printed) for a look at them.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
raster="$(realpath "$1")"
mcpp="${2:-$root/build/release/app/mcpp}"
shift 2 || shift $#
wanted=("$@")
[ ${#wanted[@]} -eq 0 ] && wanted=(team corner road)
scratch="$(mktemp -d)"
trap '[ -n "${KEEP_SCRATCH:-}" ] || rm -rf "$scratch"' EXIT
[ -z "${KEEP_SCRATCH:-}" ] || echo "missions and outputs in $scratch"
export QT_QPA_PLATFORM=offscreen

python3 - "$raster" "$scratch" <<'PYTHON'
import json, sys
raster, folder = sys.argv[1], sys.argv[2]
def drone(name, x, y):
    return {"name": name, "start": [x, y], "vehicle": "multirotor", "cruise_speed_mps": 8,
            "flight_time_s": 1320, "turnaround_s": 480, "max_waypoints": 400}
cases = {
    "team": ([(2530000, 1158000), (2536000, 1158000), (2536000, 1163000), (2530000, 1163000)],
             [drone("drone-a", 2530500, 1158500), drone("drone-b", 2535500, 1158500),
              drone("drone-c", 2533000, 1162500),
              {"name": "rover", "start": [2531000, 1162000], "vehicle": "rover", "cruise_speed_mps": 1.5}], {}),
    "corner": ([(2530000, 1158000), (2533500, 1158000), (2533500, 1161500), (2530000, 1161500)],
               [drone("drone-a", 2530100, 1158100), drone("drone-b", 2530200, 1158100)], {}),
    "road": ([(2529800, 1158000), (2530000, 1158000), (2530000, 1159000), (2532500, 1159000),
              (2532500, 1161500), (2529800, 1161500)],
             [drone("drone-a", 2529900, 1158100), drone("drone-b", 2529900, 1158300)],
             {"snap_starts_to_free_cells": True}),
}
for name, (ring, robots, parameters) in cases.items():
    area = {"type": "FeatureCollection",
            "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::2056"}},
            "features": [{"type": "Feature", "properties": {},
                          "geometry": {"type": "Polygon", "coordinates": [ring + [ring[0]]]}}]}
    json.dump(area, open(f"{folder}/{name}-area.geojson", "w"))
    mission = {"format": "mcpp-mission", "version": 2, "raster": {"path": raster, "band": 1},
               "area": {"include": f"{name}-area.geojson"}, "classes": {"preset": "corine-grid"},
               "robots": robots, "planner": {"name": "mcpp-mlct", "parameters": parameters},
               "exports": {"altitude_m": 60}}
    json.dump(mission, open(f"{folder}/{name}.json", "w"), indent=1)
PYTHON

printf '%-8s %10s %10s %7s %12s %12s %7s %7s %8s\n' \
    case makespan_s bound_s ratio field_home_s field_bound_s spread total_s peak_MB
for name in "${wanted[@]}"; do
    out="$scratch/$name-out"
    /usr/bin/time -f '%e %M' -o "$scratch/time" "$mcpp" --batch "$scratch/$name.json" --out "$out" -q
    read -r seconds kilobytes < "$scratch/time"
    python3 - "$out/report.json" "$name" "$seconds" "$kilobytes" <<'PYTHON'
import json, sys
report = json.load(open(sys.argv[1]))
print("%-8s %10.0f %10.0f %7.3f %12.0f %12.0f %7.3f %7.2f %8.0f" % (
    sys.argv[2], report["makespan_s"], report["lower_bound_s"], report["ratio"],
    report.get("field_makespan_s", 0), report.get("field_lower_bound_s", 0), report.get("field_spread", 0),
    float(sys.argv[3]), int(sys.argv[4]) / 1024))
PYTHON
done
