#include "BrokenMissions.hpp"

namespace mcpp::test {

const char* const validMission = R"({
  "format": "mcpp-mission",
  "version": 1,
  "raster": {"path": "map.tif", "band": 1},
  "classes": {"preset": "paper", "missing_as_obstacles": false, "table": [{"value": 1, "name": "farm", "color": "#e8c547", "speed_mps": 1, "fov_m": 10, "passable": true}]},
  "robots": [{"name": "a", "start": [1, 2]}, {"name": "b", "start": [3, 4], "start_crs": "EPSG:4326"}],
  "planner": {"name": "mcpp-mlct", "purity_tolerance": 0, "blocked_threshold": 0.5, "closed_tour": true, "rebalance_iterations": 0, "snap_starts_to_free_cells": false},
  "exports": {"altitude_m": 30, "cruise_speed_mps": 0, "merge_collinear": true}
})";

const char* const validMissionVersion2 = R"({
  "format": "mcpp-mission",
  "version": 2,
  "raster": {"path": "map.tif", "band": 1},
  "robots": [{"name": "a", "start": [1, 2]}],
  "planner": {"name": "mcpp-mlct", "parameters": {"purity_tolerance": 0.02, "blocked_threshold": 0.5, "closed_tour": false, "rebalance_iterations": 10}}
})";

std::vector<MissionMutation> missionVersion2Mutations() {
    return {
        {"v2 version newer", R"("version": 2)", R"("version": 3)", "version"},
        {"v2 planner.parameters",
         R"("parameters": {"purity_tolerance": 0.02, "blocked_threshold": 0.5, "closed_tour": false, "rebalance_iterations": 10})",
         R"("parameters": [0.02])", "planner.parameters"},
        {"v2 parameter unknown", R"("closed_tour": false)", R"("closed_tours": false)",
         "planner.parameters.closed_tours"},
        {"v2 parameter type", R"("closed_tour": false)", R"("closed_tour": "no")",
         "planner.parameters.closed_tour"},
        {"v2 parameter range", R"("purity_tolerance": 0.02)", R"("purity_tolerance": 1)",
         "planner.parameters.purity_tolerance"},
        {"v2 parameter integer", R"("rebalance_iterations": 10)", R"("rebalance_iterations": -3)",
         "planner.parameters.rebalance_iterations"},
        {"v2 flat parameter", R"("name": "mcpp-mlct", )", R"("name": "mcpp-mlct", "closed_tour": true, )",
         "planner.closed_tour"},
    };
}

std::vector<MissionMutation> missionMutations() {
    return {
        {"format", R"("format": "mcpp-mission")", R"("format": 7)", "format"},
        {"format value", R"("format": "mcpp-mission")", R"("format": "qgc")", "format"},
        {"version", R"("version": 1)", R"("version": "1")", "version"},
        {"version newer", R"("version": 1)", R"("version": 3)", "version"},
        {"raster", R"("raster": {"path": "map.tif", "band": 1})", R"("raster": "map.tif")", "raster"},
        {"raster.path", R"("path": "map.tif")", R"("path": 3)", "raster.path"},
        {"raster.band", R"("band": 1)", R"("band": 1.5)", "raster.band"},
        {"classes",
         R"("classes": {"preset": "paper", "missing_as_obstacles": false, "table": [{"value": 1, "name": "farm", "color": "#e8c547", "speed_mps": 1, "fov_m": 10, "passable": true}]})",
         R"("classes": [1])", "classes"},
        {"classes.preset", R"("preset": "paper")", R"("preset": true)", "classes.preset"},
        {"classes.preset unknown", R"("preset": "paper")", R"("preset": "papers")", "classes.preset"},
        {"classes.missing_as_obstacles", R"("missing_as_obstacles": false)", R"("missing_as_obstacles": 0)",
         "classes.missing_as_obstacles"},
        {"classes.table",
         R"("table": [{"value": 1, "name": "farm", "color": "#e8c547", "speed_mps": 1, "fov_m": 10, "passable": true}])",
         R"("table": {"value": 1})", "classes.table"},
        {"table value", R"("value": 1)", R"("value": "1")", "classes.table[0].value"},
        {"table name", R"("name": "farm")", R"("name": 1)", "classes.table[0].name"},
        {"table color", R"("color": "#e8c547")", R"("color": "yellow")", "classes.table[0].color"},
        {"table speed", R"("speed_mps": 1)", R"("speed_mps": "1")", "classes.table[0].speed_mps"},
        {"table fov", R"("fov_m": 10)", R"("fov_m": null)", "classes.table[0].fov_m"},
        {"table passable", R"("passable": true)", R"("passable": "yes")", "classes.table[0].passable"},
        {"robots",
         R"("robots": [{"name": "a", "start": [1, 2]}, {"name": "b", "start": [3, 4], "start_crs": "EPSG:4326"}])",
         R"("robots": {"name": "a"})", "robots"},
        {"robots[1]", R"({"name": "b")", R"(7, {"name": "b")", "robots[1]"},
        {"robot name", R"("name": "a")", R"("name": ["a"])", "robots[0].name"},
        {"robot start", R"("start": [3, 4])", R"("start": [3, "4"])", "robots[1].start"},
        {"robot start length", R"("start": [1, 2])", R"("start": [1, 2, 3])", "robots[0].start"},
        {"robot start_crs", R"("start_crs": "EPSG:4326")", R"("start_crs": 4326)", "robots[1].start_crs"},
        {"robot start_crs unknown", R"("start_crs": "EPSG:4326")", R"("start_crs": "EPSG:999999")",
         "robots[1].start_crs"},
        {"robot extra key", R"("name": "a")", R"("nmae": "a")", "robots[0].nmae"},
        {"planner",
         R"("planner": {"name": "mcpp-mlct", "purity_tolerance": 0, "blocked_threshold": 0.5, "closed_tour": true, "rebalance_iterations": 0, "snap_starts_to_free_cells": false})",
         R"("planner": "mcpp-mlct")", "planner"},
        {"planner.name", R"("name": "mcpp-mlct")", R"("name": 1)", "planner.name"},
        {"planner.name unknown", R"("name": "mcpp-mlct")", R"("name": "dijkstra")", "planner.name"},
        {"purity_tolerance", R"("purity_tolerance": 0)", R"("purity_tolerance": "0")",
         "planner.purity_tolerance"},
        {"blocked_threshold", R"("blocked_threshold": 0.5)", R"("blocked_threshold": false)",
         "planner.blocked_threshold"},
        {"blocked_threshold range", R"("blocked_threshold": 0.5)", R"("blocked_threshold": 1.5)",
         "planner.blocked_threshold"},
        {"closed_tour", R"("closed_tour": true)", R"("closed_tour": 1)", "planner.closed_tour"},
        {"rebalance_iterations", R"("rebalance_iterations": 0)", R"("rebalance_iterations": 0.5)",
         "planner.rebalance_iterations"},
        {"snap", R"("snap_starts_to_free_cells": false)", R"("snap_starts_to_free_cells": "no")",
         "planner.snap_starts_to_free_cells"},
        {"exports", R"("exports": {"altitude_m": 30, "cruise_speed_mps": 0, "merge_collinear": true})",
         R"("exports": 1)", "exports"},
        {"altitude_m", R"("altitude_m": 30)", R"("altitude_m": "30")", "exports.altitude_m"},
        {"cruise_speed_mps", R"("cruise_speed_mps": 0)", R"("cruise_speed_mps": [])",
         "exports.cruise_speed_mps"},
        {"merge_collinear", R"("merge_collinear": true)", R"("merge_collinear": null)",
         "exports.merge_collinear"},
    };
}

} // namespace mcpp::test
