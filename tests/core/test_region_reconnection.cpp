#include "core/allocation/RegionReconnection.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <string>
#include <vector>

using namespace mcpp;

namespace {

// A map drawn row by row, one cell per character ('#' water), and robots' cells drawn the same way:
// digits for a robot, '.' for nobody.
struct DrawnDivision {
    CellGraph graph;
    std::vector<int> robotOfCell;
    std::vector<int> startCells;
    int columns = 0;
};

DrawnDivision drawn(const std::vector<std::string>& map, const std::vector<std::string>& owners,
                    const std::vector<std::pair<int, int>>& starts) {
    DrawnDivision result;
    result.columns = static_cast<int>(map.front().size());
    std::vector<bool> blocked;
    for (const std::string& row : map)
        for (char pixel : row)
            blocked.push_back(pixel == '#');
    const PlanningProblem problem =
        test::uniformProblem(result.columns, static_cast<int>(map.size()), 10.0, blocked, {});
    result.graph = test::cellPerPixelGraph(problem);
    result.robotOfCell.assign(result.graph.size(), -1);
    for (std::size_t id = 0; id < result.graph.size(); ++id) {
        const Cell& cell = result.graph.cell(static_cast<int>(id));
        const char owner = owners[static_cast<std::size_t>(cell.row)][static_cast<std::size_t>(cell.column)];
        result.robotOfCell[id] = owner == '.' ? -1 : owner - '0';
    }
    for (const auto& [column, row] : starts)
        result.startCells.push_back(result.graph.cellAt(test::pixelCentre(problem.grid, column, row)));
    return result;
}

// The division drawn back as text, '#' where there is no cell.
std::vector<std::string> ownersOf(const DrawnDivision& division, int rows) {
    std::vector<std::string> text(static_cast<std::size_t>(rows),
                                  std::string(static_cast<std::size_t>(division.columns), '#'));
    for (std::size_t id = 0; id < division.graph.size(); ++id) {
        const Cell& cell = division.graph.cell(static_cast<int>(id));
        const int robot = division.robotOfCell[id];
        text[static_cast<std::size_t>(cell.row)][static_cast<std::size_t>(cell.column)] =
            robot < 0 ? '.' : static_cast<char>('0' + robot);
    }
    return text;
}

} // namespace

class TestRegionReconnection : public QObject {
    Q_OBJECT

  private slots:
    void cutOffCellsGoToTheRegionAroundThem() {
        // Robot 0's island inside robot 1's region, and a robot-1 cell behind the wall on robot 0's side.
        DrawnDivision division =
            drawn({"........", "........", "...#....", "...#....", "........"},
                  {"00001111", "00001001", "000#1001", "010#1111", "00001111"}, {{0, 0}, {7, 4}});
        reconnectRegions(division.graph, division.startCells, division.robotOfCell);
        const std::vector<std::string> expected{"00001111", //
                                                "00001111", //
                                                "000#1111", //
                                                "000#1111", //
                                                "00001111"};
        QCOMPARE(ownersOf(division, 5), expected);
    }

    void connectedRegionsStayAsTheyAre() {
        DrawnDivision division =
            drawn({"......", "..##..", "......"}, {"000111", "00##11", "001111"}, {{0, 0}, {5, 2}});
        const std::vector<int> before = division.robotOfCell;
        reconnectRegions(division.graph, division.startCells, division.robotOfCell);
        QCOMPARE(division.robotOfCell, before);
    }

    void cellsNoStartReachesAreNobodys() {
        // The right-hand room is walled off from both starts: whatever it was given, it is nobody's.
        DrawnDivision division =
            drawn({"...#..", "...#..", "...#.."}, {"001#11", "001#11", "011#.."}, {{0, 0}, {2, 2}});
        reconnectRegions(division.graph, division.startCells, division.robotOfCell);
        const std::vector<std::string> expected{"001#..", "001#..", "011#.."};
        QCOMPARE(ownersOf(division, 3), expected);
    }

    // Robot 1's start in the middle of robot 0's row cuts it: the far end is robot 1's, as its start
    // reaches it and robot 0's does not.
    void aStartInsideAnotherRegionCutsIt() {
        DrawnDivision division = drawn({"....."}, {"00000"}, {{0, 0}, {2, 0}});
        reconnectRegions(division.graph, division.startCells, division.robotOfCell);
        const std::vector<std::string> expected{"00111"};
        QCOMPARE(ownersOf(division, 1), expected);
    }

    void aStartGivenAwayIsGivenBack() {
        // Robot 1's start lies in robot 0's cells: the start is its own again and the cells it reaches stay.
        DrawnDivision division = drawn({"....", "...."}, {"0000", "0011"}, {{0, 0}, {1, 1}});
        reconnectRegions(division.graph, division.startCells, division.robotOfCell);
        const std::vector<std::string> expected{"0000", "0111"};
        QCOMPARE(ownersOf(division, 2), expected);
    }
};

QTEST_GUILESS_MAIN(TestRegionReconnection)
#include "test_region_reconnection.moc"
