// The comparison sheet's panels read as batch mode's summary does: in rank order, each plan after the first
// timed against it, every ratio said to be to the plan's own bound.

#include "render/ComparisonSheet.hpp"
#include "render/RobotPalette.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>

using namespace mcpp;

namespace {

io::ComparisonRow plannedRow(const std::string& planner, double coveredFraction, double makespanSeconds) {
    io::ComparisonRow row;
    row.planner = planner;
    row.metrics.coveredFraction = coveredFraction;
    row.metrics.makespanSeconds = makespanSeconds;
    row.metrics.ratio = 1.5;
    return row;
}

int pixelsNear(const QImage& image, const QColor& colour) {
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor pixel = image.pixelColor(x, y);
            count += std::abs(pixel.red() - colour.red()) + std::abs(pixel.green() - colour.green()) +
                                 std::abs(pixel.blue() - colour.blue()) <
                             30
                         ? 1
                         : 0;
        }
    return count;
}

} // namespace

class TestComparisonSheet : public QObject {
    Q_OBJECT

  private slots:
    void panelsAreRankedAndTimedAgainstTheFirst() {
        const std::vector<io::ComparisonRow> rows{plannedRow("darp", 1.0, 9000.0),
                                                  plannedRow("wavefront-battery", 0.2, 3600.0),
                                                  plannedRow("mcpp-mlct", 1.0, 7200.0)};
        const auto panels = render::rankedComparisonPanels(rows, {nullptr, nullptr, nullptr});
        QCOMPARE(panels.size(), std::size_t{3});
        QCOMPARE(panels[0].title, QStringLiteral("1. mcpp-mlct"));
        QCOMPARE(panels[0].caption.front(), QStringLiteral("makespan 2 h, 1.500 x its own lower bound"));
        QCOMPARE(panels[1].title, QStringLiteral("2. darp"));
        QCOMPARE(panels[1].caption.front(),
                 QStringLiteral("makespan 2 h 30 min (1.25 x mcpp-mlct's), 1.500 x its own lower bound"));
        // Covering less, it is smaller, not quicker: not timed against the first, and its title says why.
        QCOMPARE(panels[2].title, QStringLiteral("3. wavefront-battery: covers less"));
        QCOMPARE(panels[2].caption.front(), QStringLiteral("makespan 1 h, 1.500 x its own lower bound"));
    }

    // A plan timing the robots at the class table's speeds beside plans keeping their own reads sooner done;
    // its title says why it is ranked after them.
    void aPlanAtTheClassTablesSpeedsSaysWhyItIsRankedAfter() {
        io::ComparisonRow classSpeeds = plannedRow("mdstc", 1.0, 3600.0);
        classSpeeds.metrics.ownSpeedsIgnored = true;
        const std::vector<io::ComparisonRow> rows{classSpeeds, plannedRow("mcpp-mlct", 1.0, 7200.0)};
        const auto panels = render::rankedComparisonPanels(rows, {nullptr, nullptr});
        QCOMPARE(panels[0].title, QStringLiteral("1. mcpp-mlct"));
        QCOMPARE(panels[1].title, QStringLiteral("2. mdstc: at the class table's speeds"));
        QCOMPARE(panels[1].caption.front(), QStringLiteral("makespan 1 h, 1.500 x its own lower bound"));
    }

    // Where flights split the missions, plans are ranked by when the last robot is home: the caption leads
    // with that time, timed against the first's, and the paths' makespan follows without it.
    void panelsInTheFieldLeadWithWhenTheLastRobotIsHome() {
        std::vector<io::ComparisonRow> rows{plannedRow("darp", 1.0, 7000.0),
                                            plannedRow("mcpp-mlct", 1.0, 7200.0)};
        for (io::ComparisonRow& row : rows) {
            row.metrics.fieldLowerBoundSeconds = 5000.0;
            row.metrics.robots = {RobotMetrics{}, RobotMetrics{}};
            row.metrics.robots[1].robot = 1;
        }
        rows[0].metrics.fieldMakespanSeconds = 10800.0; // darp: paths sooner done, robots later home
        rows[0].metrics.robots[0].fieldSeconds = 9000.0;
        rows[0].metrics.robots[1].fieldSeconds = 10800.0;
        rows[1].metrics.fieldMakespanSeconds = 9000.0;
        rows[1].metrics.robots[0].fieldSeconds = 9000.0;
        rows[1].metrics.robots[1].fieldSeconds = 9000.0;
        const auto panels = render::rankedComparisonPanels(rows, {nullptr, nullptr});
        QCOMPARE(panels[0].title, QStringLiteral("1. mcpp-mlct"));
        QCOMPARE(panels[0].caption.at(0),
                 QStringLiteral("last robot home after 2 h 30 min, the last 1.000 x the first"));
        QCOMPARE(panels[0].caption.at(1), QStringLiteral("paths' makespan 2 h, 1.500 x its own lower bound"));
        QCOMPARE(
            panels[1].caption.at(0),
            QStringLiteral("last robot home after 3 h (1.20 x mcpp-mlct's), the last 1.200 x the first"));
        QCOMPARE(panels[1].caption.at(1),
                 QStringLiteral("paths' makespan 1 h 57 min, 1.500 x its own lower bound"));
    }

    // Every panel's map shows the edges of the area the plans were made in, as plan.png does.
    void panelsShowTheAreaEdges() {
        const ClassGrid grid = test::filledGrid(20, 10, 1000.0, 5000.0, 10.0, 1); // one passable class
        const ClassTable classes({LandCoverClass{1, "Meadow", 0x40a040, 2.0, 10.0, true}});
        Plan plan;
        plan.planner = "test";
        const std::vector<render::ComparisonPanel> panels{{QStringLiteral("one"), {}, &plan, {}},
                                                          {QStringLiteral("two"), {}, &plan, {}}};
        AreaOutline area;
        area.include = {{{{1020, 4920}, {1180, 4920}, {1180, 4980}, {1020, 4980}}}};
        area.exclude = {{{{1040, 4940}, {1080, 4940}, {1080, 4960}, {1040, 4960}}}};
        const QImage without = render::renderComparisonSheet(grid, classes, panels);
        const QImage with = render::renderComparisonSheet(grid, classes, panels, &area);
        QCOMPARE(with.size(), without.size());
        const int edges = pixelsNear(with, render::RobotPalette::areaEdgeColour()) -
                          pixelsNear(without, render::RobotPalette::areaEdgeColour());
        const int noGo = pixelsNear(with, render::RobotPalette::noGoColour()) -
                         pixelsNear(without, render::RobotPalette::noGoColour());
        // Each panel's map is 520 pixels wide (2.6 a metre): the area's edge 320 m round, dashed, in two
        // panels.
        QVERIFY2(edges > 1000, qPrintable(QString::number(edges)));
        QVERIFY2(noGo > 200, qPrintable(QString::number(noGo)));
    }

    // A planner without a plan takes a line saying why, not a tile of its own: three plans and a skipped
    // planner make one row of maps; nor has it a place in the chart.
    void plannersWithoutAPlanTakeALine() {
        const ClassGrid grid = test::filledGrid(20, 10, 1000.0, 5000.0, 10.0, 1);
        const ClassTable classes({LandCoverClass{1, "Meadow", 0x40a040, 2.0, 10.0, true}});
        Plan plan;
        plan.planner = "test";
        std::vector<render::ComparisonPanel> panels{{QStringLiteral("1. one"), {}, &plan, {}},
                                                    {QStringLiteral("2. two"), {}, &plan, {}},
                                                    {QStringLiteral("3. three"), {}, &plan, {}}};
        const QImage planned = render::renderComparisonSheet(grid, classes, panels);
        panels.push_back({QStringLiteral("spiral-stc"),
                          {QStringLiteral("skipped: spiral-stc plans for one robot and the mission has 5")},
                          nullptr,
                          {}});
        const QImage withSkipped = render::renderComparisonSheet(grid, classes, panels);
        QCOMPARE(withSkipped.width(), planned.width());
        const int added = withSkipped.height() - planned.height();
        QVERIFY2(added > 0 && added < 100, qPrintable(QString::number(added)));
        // Only planners without plans: their lines, no map and no chart.
        const QImage none = render::renderComparisonSheet(grid, classes, {panels.back()});
        QVERIFY2(none.height() < 150, qPrintable(QString::number(none.height())));
    }

    // The caption under each map is as tall as the longest needs: six lines are not cut to three.
    void longCaptionsAreNotCut() {
        const ClassGrid grid = test::filledGrid(20, 10, 1000.0, 5000.0, 10.0, 1);
        const ClassTable classes({LandCoverClass{1, "Meadow", 0x40a040, 2.0, 10.0, true}});
        Plan plan;
        plan.planner = "test";
        const QStringList three{QStringLiteral("a"), QStringLiteral("b"), QStringLiteral("c")};
        const QImage short_ =
            render::renderComparisonSheet(grid, classes, {{QStringLiteral("one"), three, &plan, {}}});
        const QImage tall =
            render::renderComparisonSheet(grid, classes, {{QStringLiteral("one"), three + three, &plan, {}}});
        const int added = tall.height() - short_.height();
        QVERIFY2(added >= 3 * 13, qPrintable(QString::number(added)));
    }
};

QTEST_MAIN(TestComparisonSheet)
#include "test_comparison_sheet.moc"
