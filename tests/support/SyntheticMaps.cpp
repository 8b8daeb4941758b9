#include "tests/support/SyntheticMaps.hpp"

#include "core/decomposition/UniformGridDecomposition.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <utility>

namespace mcpp::test {

CellGraph cellPerPixelGraph(const PlanningProblem& problem) {
    return UniformGridDecomposition(DecompositionOptions{}, GridCellRule::WholeCell)
        .decompose(problem.grid, problem.classes);
}

MapPoint pixelCentre(const ClassGrid& grid, int column, int row) {
    return {grid.originX + (column + 0.5) * grid.pixelWidth, grid.originY - (row + 0.5) * grid.pixelHeight};
}

PlanningProblem uniformProblem(int columns, int rows, double pixelSize, const std::vector<bool>& blocked,
                               const std::vector<MapPoint>& starts) {
    PlanningProblem problem;
    problem.grid.columns = columns;
    problem.grid.rows = rows;
    problem.grid.pixelWidth = pixelSize;
    problem.grid.pixelHeight = pixelSize;
    problem.grid.originX = 500000.0;
    problem.grid.originY = 4000000.0;
    problem.grid.values.assign(static_cast<std::size_t>(columns * rows), 1);
    for (std::size_t i = 0; i < blocked.size() && i < problem.grid.values.size(); ++i)
        if (blocked[i])
            problem.grid.values[i] = 99;
    problem.classes.set({1, "grass", 0x88cc44, 1.0, pixelSize / 2.0, true});
    problem.classes.set({99, "water", 0x2255cc, 0.0, pixelSize / 2.0, false});
    problem.starts = starts;
    return problem;
}

PlanningProblem obstacleGridProblem(int size, int robots, std::uint32_t seed) {
    std::mt19937 random(seed);
    std::bernoulli_distribution obstacle(0.15);
    std::vector<bool> blocked(static_cast<std::size_t>(size * size));
    for (std::size_t i = 0; i < blocked.size(); ++i)
        blocked[i] = obstacle(random);
    auto problem = uniformProblem(size, size, 10.0, blocked, {});
    std::uniform_int_distribution<int> position(0, size - 1);
    std::set<std::pair<int, int>> used;
    while (static_cast<int>(problem.starts.size()) < robots) {
        const int column = position(random);
        const int row = position(random);
        if (blocked[static_cast<std::size_t>(row * size + column)] || !used.insert({column, row}).second)
            continue;
        // The north-west sub-cell centre: robots start on the coverage grid, as in DARP.
        const MapPoint centre = pixelCentre(problem.grid, column, row);
        problem.starts.push_back({centre.x - 2.5, centre.y + 2.5});
    }
    return problem;
}

PlanningProblem drawnProblem(const std::vector<std::string>& rows, const std::vector<MapPoint>& starts) {
    PlanningProblem problem;
    ClassGrid& grid = problem.grid;
    grid.columns = static_cast<int>(rows.front().size());
    grid.rows = static_cast<int>(rows.size());
    grid.originX = 1000.0;
    grid.originY = 2000.0;
    for (const std::string& row : rows)
        for (char pixel : row)
            grid.values.push_back(pixel == '#' ? 99 : pixel == 'm' ? 2 : 1);
    problem.classes.set({1, "grass", 0x88cc44, 1.0, 1.0, true});
    problem.classes.set({2, "mud", 0x886644, 0.5, 1.0, true});
    problem.classes.set({99, "water", 0x2255cc, 0.0, 1.0, false});
    for (const MapPoint& start : starts)
        problem.starts.push_back({grid.originX + start.x, grid.originY - start.y});
    return problem;
}

RandomMapSpec multiCoverSpec(int size, int robots, std::uint32_t seed) {
    RandomMapSpec spec;
    spec.columns = size;
    spec.rows = size;
    spec.landCovers = 3;
    spec.obstacleFraction = 0.05;
    spec.robots = robots;
    spec.seed = seed;
    return spec;
}

RandomMapSpec waterCrossingSpec() {
    RandomMapSpec spec;
    spec.columns = 24;
    spec.rows = 24;
    spec.obstacleFraction = 0.04;
    spec.fovPixels = 2.0;
    spec.robots = 2;
    spec.seed = 5;
    return spec;
}

PlanningProblem randomProblem(const RandomMapSpec& spec) {
    std::mt19937 random(spec.seed);
    PlanningProblem problem;
    ClassGrid& grid = problem.grid;
    grid.columns = spec.columns;
    grid.rows = spec.rows;
    grid.pixelWidth = spec.pixelSize;
    grid.pixelHeight = spec.pixelSize;
    grid.originX = 300000.0;
    grid.originY = 5000000.0;
    grid.values.assign(static_cast<std::size_t>(spec.columns * spec.rows), 1);
    const int covers = std::clamp(spec.landCovers, 1, 4);
    const double speeds[4] = {2.0, 1.0, 3.0, 0.5};
    const char* names[4] = {"grass", "wood", "road", "marsh"};
    // FOVs 5, 10, 20, 40 m: each class needs its own quadtree level.
    for (int c = 0; c < covers; ++c)
        problem.classes.set({c + 1, names[c], 0x404040U + static_cast<std::uint32_t>(c) * 0x302010U,
                             speeds[c], spec.pixelSize * spec.fovPixels * (1 << c), true});
    problem.classes.set({99, "water", 0x2255cc, 0.0, 1.0, false});
    std::uniform_int_distribution<int> columnDistribution(0, spec.columns - 1);
    std::uniform_int_distribution<int> rowDistribution(0, spec.rows - 1);
    std::uniform_int_distribution<int> coverDistribution(1, covers);
    if (covers > 1) {
        const int patches = std::max(4, spec.columns * spec.rows / 40);
        for (int patch = 0; patch < patches; ++patch) {
            const int value = coverDistribution(random);
            const int size = 1 << std::uniform_int_distribution<int>(0, covers)(random);
            const int column = columnDistribution(random) / size * size;
            const int row = rowDistribution(random) / size * size;
            for (int r = row; r < std::min(spec.rows, row + size * 2); ++r)
                for (int c = column; c < std::min(spec.columns, column + size * 2); ++c)
                    grid.values[grid.index(c, r)] = value;
        }
    }
    std::bernoulli_distribution obstacle(spec.obstacleFraction);
    for (auto& value : grid.values)
        if (obstacle(random))
            value = 99;
    // The smallest FOV class is present, so every pixel is exactly one bottom cell.
    grid.values[0] = 1;
    // Starts on distinct free pixels, kept apart by at least the largest cell so no two share one; where a
    // bottom cell spans several pixels, the start's own bottom cell is cleared of obstacles.
    std::vector<std::pair<int, int>> chosen;
    const int bottomPixels = std::max(1, static_cast<int>(std::lround(2.0 * spec.fovPixels)));
    const int spacing = bottomPixels * (1 << (covers - 1));
    int attempts = 0;
    while (static_cast<int>(problem.starts.size()) < spec.robots && attempts < 100000) {
        ++attempts;
        const int column = columnDistribution(random);
        const int row = rowDistribution(random);
        if (grid.values[grid.index(column, row)] == 99)
            continue;
        const bool clash = std::any_of(chosen.begin(), chosen.end(), [&](const auto& other) {
            return column / spacing == other.first / spacing && row / spacing == other.second / spacing;
        });
        if (clash)
            continue;
        chosen.emplace_back(column, row);
        problem.starts.push_back(pixelCentre(grid, column, row));
        const int value = grid.values[grid.index(column, row)];
        for (int r = row / bottomPixels * bottomPixels;
             r < std::min(spec.rows, (row / bottomPixels + 1) * bottomPixels); ++r)
            for (int c = column / bottomPixels * bottomPixels;
                 c < std::min(spec.columns, (column / bottomPixels + 1) * bottomPixels); ++c)
                grid.values[grid.index(c, r)] = value;
    }
    return problem;
}

ClassGrid filledGrid(int columns, int rows, double originX, double originY, double pixelSide,
                     std::int32_t value) {
    ClassGrid grid;
    grid.columns = columns;
    grid.rows = rows;
    grid.originX = originX;
    grid.originY = originY;
    grid.pixelWidth = pixelSide;
    grid.pixelHeight = pixelSide;
    grid.values.assign(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows), value);
    return grid;
}

} // namespace mcpp::test
