// The comparison sheet's panels read as batch mode's summary does: in rank order, each plan after the first
// timed against it, every ratio said to be to the plan's own bound.

#include "render/ComparisonSheet.hpp"

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
        // Covering less, it is smaller, not quicker: not timed against the first.
        QCOMPARE(panels[2].title, QStringLiteral("3. wavefront-battery"));
        QCOMPARE(panels[2].caption.front(), QStringLiteral("makespan 1 h, 1.500 x its own lower bound"));
    }
};

QTEST_MAIN(TestComparisonSheet)
#include "test_comparison_sheet.moc"
