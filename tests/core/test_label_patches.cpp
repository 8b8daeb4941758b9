#include "core/outlines/LabelPatches.hpp"

#include <QtTest>
#include <random>
#include <vector>

using namespace mcpp;

namespace {

// The reference: a flood fill through sides, patches numbered in the order of their first pixel.
std::vector<int> floodFilledPatches(const LabelGrid& grid) {
    std::vector<int> patch(grid.labels.size(), -1);
    int next = 0;
    for (std::size_t start = 0; start < grid.labels.size(); ++start) {
        if (grid.labels[start] == LabelGrid::noLabel || patch[start] >= 0)
            continue;
        std::vector<std::size_t> stack{start};
        patch[start] = next;
        while (!stack.empty()) {
            const std::size_t pixel = stack.back();
            stack.pop_back();
            const int column = static_cast<int>(pixel % static_cast<std::size_t>(grid.columns));
            const int row = static_cast<int>(pixel / static_cast<std::size_t>(grid.columns));
            const int steps[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
            for (const auto& step : steps) {
                const int c = column + step[0], r = row + step[1];
                if (!grid.contains(c, r) || grid.at(c, r) != grid.labels[pixel] ||
                    patch[grid.index(c, r)] >= 0)
                    continue;
                patch[grid.index(c, r)] = next;
                stack.push_back(grid.index(c, r));
            }
        }
        ++next;
    }
    return patch;
}

LabelGrid randomGrid(int seed) {
    std::mt19937 random(static_cast<unsigned>(seed));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    LabelGrid grid;
    grid.columns = 1 + seed % 23;
    grid.rows = 1 + seed % 19;
    const auto labels = static_cast<unsigned>(1 + seed % 4);
    const double emptyShare = 0.1 * (seed % 5);
    for (int i = 0; i < grid.columns * grid.rows; ++i)
        grid.labels.push_back(unit(random) < emptyShare ? LabelGrid::noLabel
                                                        : static_cast<std::int32_t>(random() % labels));
    return grid;
}

} // namespace

class LabelPatchesTest : public QObject {
    Q_OBJECT

  private slots:
    // Every pixel's patch, the patches' order, labels and sizes agree with a flood fill, on grids with
    // U shapes and spirals that join only rows below their first (seed 0 is a hand-drawn one).
    void patchesAgreeWithAFloodFill_data() {
        QTest::addColumn<int>("seed");
        for (int seed = 0; seed <= 60; ++seed)
            QTest::addRow("seed %d", seed) << seed;
    }

    void patchesAgreeWithAFloodFill() {
        QFETCH(int, seed);
        LabelGrid grid;
        if (seed == 0) {
            // A U of label 1 whose arms meet only in the last row, beside a spiral of label 2.
            const char* rows[] = {"1.1.22222", "1.1.2...2", "1.1.2.2.2",
                                  "1.1.2.222", "111......", "....22222"};
            grid.columns = 9;
            grid.rows = 6;
            for (const char* row : rows)
                for (int c = 0; c < grid.columns; ++c)
                    grid.labels.push_back(row[c] == '.' ? LabelGrid::noLabel : row[c] - '0');
        } else {
            grid = randomGrid(seed);
        }
        const std::vector<int> expected = floodFilledPatches(grid);
        const LabelPatches patches(grid);
        const int count = expected.empty() ? 0 : *std::max_element(expected.begin(), expected.end()) + 1;
        QCOMPARE(patches.count(), count);
        std::vector<std::int64_t> pixels(static_cast<std::size_t>(count), 0);
        for (int row = 0; row < grid.rows; ++row)
            for (int column = 0; column < grid.columns; ++column) {
                const int want = expected[grid.index(column, row)];
                QCOMPARE(patches.patchAt(column, row), want);
                if (want >= 0) {
                    QCOMPARE(patches.label(want), grid.at(column, row));
                    ++pixels[static_cast<std::size_t>(want)];
                }
            }
        for (int patch = 0; patch < count; ++patch)
            QCOMPARE(patches.pixels(patch), pixels[static_cast<std::size_t>(patch)]);
        if (seed == 0)
            QCOMPARE(count, 3); // the U, the spiral and the bottom run of 2s
        QCOMPARE(patches.patchAt(-1, 0), -1);
        QCOMPARE(patches.patchAt(0, grid.rows), -1);
    }
};

QTEST_GUILESS_MAIN(LabelPatchesTest)
#include "test_label_patches.moc"
