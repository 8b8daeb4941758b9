#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/PlanningProblem.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace mcpp::test {

struct RandomMapSpec {
    int columns = 20;
    int rows = 20;
    double pixelSize = 10.0;
    int landCovers = 1;            // 1..4 passable classes with FOVs 5 * 2^k
    double obstacleFraction = 0.0; // share of pixels set to the obstacle class 99
    // The smallest FOV in pixels: 0.5 makes each pixel one bottom cell (its four sub-cells alike); 1 makes
    // each pixel one sub-cell, so scattered obstacles block some sub-cells of a cell and not others.
    double fovPixels = 0.5;
    int robots = 2;
    std::uint32_t seed = 1;
};

// A map of random rectangular land-cover patches and scattered obstacles, with robots at distinct free
// cells of the bottom level. Deterministic for a seed.
[[nodiscard]] PlanningProblem randomProblem(const RandomMapSpec& spec);

// The benchmarks' multi-cover map: size x size pixels of three land covers (FOV 5, 10, 20 m) in patches and
// 5 % scattered obstacles.
[[nodiscard]] RandomMapSpec multiCoverSpec(int size, int robots, std::uint32_t seed = 7);

// 24 x 24 pixels of grass with 4 % water pixels scattered, sub-cells of 2 x 2 pixels, two robots: some
// sub-cells keep one water pixel in four (under the 50 % blocked threshold), so paths cross water there.
[[nodiscard]] RandomMapSpec waterCrossingSpec();

// A one-class grid of columns x rows pixels of `pixelSize` metres, FOV = pixelSize / 2, so each pixel is one
// bottom cell. Obstacles (value 99) where `blocked` says.
[[nodiscard]] PlanningProblem uniformProblem(int columns, int rows, double pixelSize,
                                             const std::vector<bool>& blocked,
                                             const std::vector<MapPoint>& starts);

// The DARP / DMSTC set-up: size x size pixels of one land cover (10 m pixels, FOV 5 m, 1 m/s), 15 % random
// obstacles, robots at random free cells. Deterministic for a seed.
[[nodiscard]] PlanningProblem obstacleGridProblem(int size, int robots, std::uint32_t seed);

// A map drawn as text, north row first, one-metre pixels that are one sub-cell each (FOV 1 m, so cells of
// 2 x 2 pixels): '#' water, 'm' mud (half speed), anything else grass. Starts are given in metres east and
// south of the north-west corner.
[[nodiscard]] PlanningProblem drawnProblem(const std::vector<std::string>& rows,
                                           const std::vector<MapPoint>& starts);

// The problem's map as one planning cell per whole pixel (a uniform grid, no quadtree), for tests of the
// stages after decomposition.
[[nodiscard]] CellGraph cellPerPixelGraph(const PlanningProblem& problem);

// The centre of pixel (column, row) of a grid.
[[nodiscard]] MapPoint pixelCentre(const ClassGrid& grid, int column, int row);

// A north-up grid of square pixels, every one holding `value`, its north-west corner at (originX, originY).
[[nodiscard]] ClassGrid filledGrid(int columns, int rows, double originX, double originY, double pixelSide,
                                   std::int32_t value);

} // namespace mcpp::test
