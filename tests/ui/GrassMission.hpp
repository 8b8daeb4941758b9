#pragma once

// A small open mission for the ui tests: no raster file involved.

#include "core/model/ClassTable.hpp"
#include "io/LoadedRaster.hpp"
#include "io/Mission.hpp"

#include <memory>

namespace mcpp::test {

// 10 x 10 pixels of 10 m grass, north-west corner at (0, 100).
inline std::shared_ptr<io::LoadedRaster> grassRaster() {
    auto raster = std::make_shared<io::LoadedRaster>();
    raster->path = "synthetic.tif";
    ClassGrid& grid = raster->grid;
    grid.columns = 10;
    grid.rows = 10;
    grid.originX = 0.0;
    grid.originY = 100.0;
    grid.pixelWidth = 10.0;
    grid.pixelHeight = 10.0;
    grid.values.assign(100, 1);
    grid.outside.assign(100, 0);
    raster->classPixelCounts = {{1, 100}};
    return raster;
}

// Two robots on the grass: "east" at (75, 55), "west" at (25, 55).
inline io::Mission twoRobotMission() {
    io::Mission mission;
    mission.classes = ClassTable({LandCoverClass{1, "Grass", 0x80c080, 2.0, 10.0, true}});
    mission.robots = {io::RobotSpec{"east", {75.0, 55.0}, ""}, io::RobotSpec{"west", {25.0, 55.0}, ""}};
    return mission;
}

} // namespace mcpp::test
