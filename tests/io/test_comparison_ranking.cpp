// A comparison reads the same in the window, batch mode's summary, comparison.csv and the sheet: the soonest
// done of the plans covering the most first, plans covering less after them whatever their time, then
// failed and skipped planners.
#include "io/ComparisonRanking.hpp"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using namespace mcpp;
using io::ComparisonRow;

namespace {

ComparisonRow plannedRow(const std::string& planner, double covered, double makespanSeconds,
                         double planningMilliseconds = 10.0) {
    ComparisonRow row;
    row.planner = planner;
    row.metrics.coveredFraction = covered;
    row.metrics.makespanSeconds = makespanSeconds;
    row.planningMilliseconds = planningMilliseconds;
    return row;
}

ComparisonRow unplannedRow(const std::string& planner, ComparisonRow::Outcome outcome) {
    ComparisonRow row;
    row.planner = planner;
    row.outcome = outcome;
    row.message = "why";
    return row;
}

std::vector<std::string> namesInOrder(const std::vector<ComparisonRow>& rows) {
    std::vector<std::string> names;
    for (const std::size_t index : io::rankedRows(rows))
        names.push_back(rows[index].planner);
    return names;
}

} // namespace

class TestComparisonRanking : public QObject {
    Q_OBJECT

  private slots:
    void soonestDoneOfThoseCoveringTheMostComesFirst();
    void withinTheShortfallCoveringLessIsNoPenalty();
    void timeInTheFieldDecidesWhereFlightsSplitMissions();
    void ranksSkipRowsThatDidNotPlan();
    void eachPlanIsTimedAgainstTheFirst();
    void plansAtTheClassTablesSpeedsComeAfterThoseKeepingOwnSpeeds();
    void plansWithFlightsPastTheirBatteriesComeAfterThoseWhoseFlightsFit();
    void theExportsSayWhyAPlanIsRankedApart();
};

// A battery planner that covers a quarter of the land in less time than the others is last of the planned,
// and failed and skipped planners follow in the order asked.
void TestComparisonRanking::soonestDoneOfThoseCoveringTheMostComesFirst() {
    const std::vector<ComparisonRow> rows{
        unplannedRow("spiral-stc", ComparisonRow::Outcome::Skipped),
        plannedRow("darp", 0.999, 130000.0),
        plannedRow("wavefront-battery", 0.264, 90000.0),
        unplannedRow("cppied", ComparisonRow::Outcome::Failed),
        plannedRow("mcpp-mlct", 0.999, 125000.0),
        unplannedRow("full-spiral-stc", ComparisonRow::Outcome::Skipped),
        plannedRow("mstc", 0.998, 260000.0),
    };
    const std::vector<std::string> expected{"mcpp-mlct", "darp",       "mstc",           "wavefront-battery",
                                            "cppied",    "spiral-stc", "full-spiral-stc"};
    QCOMPARE(namesInOrder(rows), expected);
    QCOMPARE(io::mostCovered(rows), 0.999);
    QVERIFY(io::coversLessThanMost(rows[2], 0.999));
    QVERIFY(!io::coversLessThanMost(rows[6], 0.999));
}

// Half a percent less is the same job (cells of another size round the edges differently); more is not.
void TestComparisonRanking::withinTheShortfallCoveringLessIsNoPenalty() {
    const std::vector<ComparisonRow> within{plannedRow("a", 0.990, 200.0), plannedRow("b", 0.986, 100.0)};
    QCOMPARE(namesInOrder(within), (std::vector<std::string>{"b", "a"}));
    const std::vector<ComparisonRow> beyond{plannedRow("a", 0.990, 200.0), plannedRow("b", 0.984, 100.0)};
    QCOMPARE(namesInOrder(beyond), (std::vector<std::string>{"a", "b"}));
    // Equal times go to the quicker planner.
    const std::vector<ComparisonRow> tied{plannedRow("slow", 0.99, 100.0, 50.0),
                                          plannedRow("quick", 0.99, 100.0, 5.0)};
    QCOMPARE(namesInOrder(tied), (std::vector<std::string>{"quick", "slow"}));
}

// Where flights split missions the team waits for the last robot home, not the longest path.
void TestComparisonRanking::timeInTheFieldDecidesWhereFlightsSplitMissions() {
    ComparisonRow shortPaths = plannedRow("short-paths", 0.99, 100.0);
    shortPaths.metrics.fieldMakespanSeconds = 400.0;
    shortPaths.metrics.fieldLowerBoundSeconds = 300.0;
    ComparisonRow longPaths = plannedRow("long-paths", 0.99, 150.0);
    longPaths.metrics.fieldMakespanSeconds = 350.0;
    longPaths.metrics.fieldLowerBoundSeconds = 300.0;
    QCOMPARE(io::doneAfterSeconds(shortPaths), 400.0);
    QCOMPARE(namesInOrder({shortPaths, longPaths}), (std::vector<std::string>{"long-paths", "short-paths"}));
    // Without a bound in the field (a battery plan's paths hold their sorties) the makespan counts.
    shortPaths.metrics.fieldLowerBoundSeconds = 0.0;
    QCOMPARE(io::doneAfterSeconds(shortPaths), 100.0);
}

void TestComparisonRanking::ranksSkipRowsThatDidNotPlan() {
    const std::vector<ComparisonRow> rows{
        unplannedRow("spiral-stc", ComparisonRow::Outcome::Skipped), plannedRow("darp", 0.99, 300.0),
        unplannedRow("cppied", ComparisonRow::Outcome::Failed), plannedRow("mcpp-mlct", 0.99, 200.0)};
    QCOMPARE(io::ranksOf(rows), (std::vector<int>{0, 2, 0, 1}));
    QCOMPARE(io::ranksOf({}), std::vector<int>{});
}

// One figure across plans: each one's time against the first's, none for a plan covering less (smaller, not
// slower) or one that did not plan.
void TestComparisonRanking::eachPlanIsTimedAgainstTheFirst() {
    const std::vector<ComparisonRow> rows{
        unplannedRow("spiral-stc", ComparisonRow::Outcome::Skipped), plannedRow("darp", 0.999, 150000.0),
        plannedRow("wavefront-battery", 0.264, 90000.0), plannedRow("mcpp-mlct", 0.999, 125000.0)};
    QCOMPARE(io::timesTheFirst(rows), (std::vector<double>{0.0, 1.2, 0.0, 1.0}));
    QCOMPARE(io::timesTheFirst({unplannedRow("cppied", ComparisonRow::Outcome::Failed)}),
             std::vector<double>{0.0});
    QCOMPARE(io::timesTheFirst({}), std::vector<double>{});
}

// A plan timing the robots at the class table's speeds, beside plans keeping their own (a drone's cruise
// speed), is not quicker for reading quicker: it comes after them, untimed against the first. Among plans
// that all ignore own speeds, time decides again.
void TestComparisonRanking::plansAtTheClassTablesSpeedsComeAfterThoseKeepingOwnSpeeds() {
    ComparisonRow classSpeeds = plannedRow("mdstc", 0.999, 100.0);
    classSpeeds.metrics.ownSpeedsIgnored = true;
    ComparisonRow ownSpeeds = plannedRow("mcpp-mlct", 0.999, 140.0);
    ownSpeeds.metrics.fieldMakespanSeconds = 120.0;
    ownSpeeds.metrics.fieldLowerBoundSeconds = 110.0;
    const ComparisonRow slower = plannedRow("darp", 0.999, 150.0);
    const ComparisonRow smaller = plannedRow("wavefront-battery", 0.5, 50.0);
    const std::vector<ComparisonRow> rows{classSpeeds, ownSpeeds, slower, smaller};
    QVERIFY(io::timedUnlikeTheOthers(rows[0], rows));
    QVERIFY(!io::timedUnlikeTheOthers(rows[1], rows));
    QVERIFY(io::readingGroup(rows[0], rows) == io::ReadingGroup::OwnSpeedsIgnored);
    QVERIFY(io::readingGroup(rows[3], rows) == io::ReadingGroup::CoversLess);
    QCOMPARE(namesInOrder(rows),
             (std::vector<std::string>{"mcpp-mlct", "darp", "mdstc", "wavefront-battery"}));
    QCOMPARE(io::ranksOf(rows), (std::vector<int>{3, 1, 2, 4}));
    QCOMPARE(io::timesTheFirst(rows), (std::vector<double>{0.0, 1.0, 1.25, 0.0}));
    // Only plans covering the most count as the others: beside a plan covering less it is timed as usual.
    ComparisonRow lessOwnSpeeds = smaller;
    const std::vector<ComparisonRow> besideSmaller{classSpeeds, lessOwnSpeeds};
    QVERIFY(!io::timedUnlikeTheOthers(besideSmaller[0], besideSmaller));
    ComparisonRow alsoClassSpeeds = plannedRow("mstc", 0.999, 90.0);
    alsoClassSpeeds.metrics.ownSpeedsIgnored = true;
    QCOMPARE(namesInOrder({classSpeeds, alsoClassSpeeds}), (std::vector<std::string>{"mstc", "mdstc"}));
}

// A plan whose waypoint files hold flights longer than a battery reads sooner done only because no drone can
// fly them: beside a plan whose flights all fit it comes after it, untimed against the first, even after a
// plan at the class table's speeds. Where every plan has such flights (or none has a flight time), time
// decides again; a plan covering less still comes last.
void TestComparisonRanking::plansWithFlightsPastTheirBatteriesComeAfterThoseWhoseFlightsFit() {
    ComparisonRow tooLong = plannedRow("darp", 0.999, 100.0);
    tooLong.flightsOverBattery = 162;
    ComparisonRow fits = plannedRow("mcpp-mlct", 0.999, 140.0);
    fits.flightsOverBattery = 0;
    ComparisonRow classSpeeds = plannedRow("mdstc", 0.999, 120.0);
    classSpeeds.metrics.ownSpeedsIgnored = true;
    classSpeeds.flightsOverBattery = 0;
    ComparisonRow smaller = plannedRow("wavefront-battery", 0.5, 50.0);
    smaller.flightsOverBattery = 0;
    const std::vector<ComparisonRow> rows{tooLong, fits, classSpeeds, smaller};
    QVERIFY(io::fliesPastItsBatteries(rows[0], rows));
    QVERIFY(!io::fliesPastItsBatteries(rows[1], rows));
    QVERIFY(io::readingGroup(rows[0], rows) == io::ReadingGroup::FlightsOverBattery);
    QCOMPARE(namesInOrder(rows),
             (std::vector<std::string>{"mcpp-mlct", "mdstc", "darp", "wavefront-battery"}));
    QCOMPARE(io::ranksOf(rows), (std::vector<int>{3, 1, 2, 4}));
    QCOMPARE(io::timesTheFirst(rows), (std::vector<double>{0.0, 1.0, 0.0, 0.0}));
    // Only a plan covering the most whose flights fit sets the others apart: beside one covering less, or
    // beside other plans with such flights, time decides.
    QVERIFY(!io::fliesPastItsBatteries(tooLong, {tooLong, smaller}));
    ComparisonRow alsoTooLong = plannedRow("mstc", 0.999, 90.0);
    alsoTooLong.flightsOverBattery = 3;
    QCOMPARE(namesInOrder({tooLong, alsoTooLong}), (std::vector<std::string>{"mstc", "darp"}));
    // A plan set apart for its flights sets no other apart: beside it, a plan at the class table's speeds
    // whose flights fit is read first and timed alike.
    ComparisonRow ownSpeedsTooLong = plannedRow("darp", 0.999, 100.0);
    ownSpeedsTooLong.flightsOverBattery = 12;
    ComparisonRow classSpeedsFit = plannedRow("mdstc", 0.999, 120.0);
    classSpeedsFit.metrics.ownSpeedsIgnored = true;
    classSpeedsFit.flightsOverBattery = 0;
    const std::vector<ComparisonRow> crossed{ownSpeedsTooLong, classSpeedsFit};
    QVERIFY(io::readingGroup(crossed[1], crossed) == io::ReadingGroup::TimedAlike);
    QVERIFY(io::readingGroup(crossed[0], crossed) == io::ReadingGroup::FlightsOverBattery);
    QCOMPARE(io::timesTheFirst(crossed), (std::vector<double>{0.0, 1.0}));
    // Without flight times nothing is counted, and nothing is set apart.
    ComparisonRow untimed = plannedRow("darp", 0.999, 100.0);
    QVERIFY(!io::fliesPastItsBatteries(untimed, {untimed, fits}));
}

// comparison.csv and .json say why a plan with the shorter makespan is ranked after the first, as batch
// mode's summary does: a script reading only rank and makespan would otherwise take it for a mistake.
void TestComparisonRanking::theExportsSayWhyAPlanIsRankedApart() {
    ComparisonRow classSpeeds = plannedRow("mdstc", 0.999, 100.0);
    classSpeeds.metrics.ownSpeedsIgnored = true;
    classSpeeds.flightsOverBattery = 0;
    ComparisonRow farFlights = plannedRow("mcpp-mlct", 0.999, 140.0);
    farFlights.flightsOverBattery = 124; // robots with flight times: how many flights overrun a battery
    ComparisonRow ownSpeedsFit = plannedRow("mstc", 0.999, 150.0);
    ownSpeedsFit.flightsOverBattery = 0;
    const std::vector<ComparisonRow> rows{classSpeeds, farFlights, plannedRow("wavefront-battery", 0.5, 50.0),
                                          unplannedRow("cppied", ComparisonRow::Outcome::Failed),
                                          ownSpeedsFit};
    QTemporaryDir directory;
    QVERIFY(directory.isValid());
    const QString csvPath = directory.filePath("comparison.csv");
    const QString jsonPath = directory.filePath("comparison.json");
    QVERIFY(io::writeComparisonCsv(rows, csvPath.toStdString()).ok());
    QVERIFY(io::writeComparisonJson(rows, jsonPath.toStdString()).ok());

    QFile csv(csvPath);
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(csv.readAll()).split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 6);
    const int column = lines[0].split(',').indexOf("ranked_apart");
    QVERIFY(column >= 0);
    // mdstc times at the class table's speeds where mstc keeps the robots' own; farFlights' flights overrun
    // a battery where theirs all fit.
    const QStringList expected{"own_speeds_ignored", "flights_over_battery", "covers_less", "", ""};
    for (int row = 0; row < 5; ++row)
        QCOMPARE(lines[row + 1].split(',').at(column), expected[row]);
    const int flights = lines[0].split(',').indexOf("flights_over_battery");
    QCOMPARE(flights, column + 1);                          // after the columns earlier versions wrote
    const QStringList overBattery{"0", "124", "", "", "0"}; // empty: no flight times, or not planned
    for (int row = 0; row < 5; ++row)
        QCOMPARE(lines[row + 1].split(',').at(flights), overBattery[row]);

    QFile json(jsonPath);
    QVERIFY(json.open(QIODevice::ReadOnly));
    const QJsonArray planners = QJsonDocument::fromJson(json.readAll()).object().value("planners").toArray();
    QCOMPARE(planners.size(), 5);
    for (int row = 0; row < 5; ++row)
        QCOMPARE(planners[row].toObject().value("ranked_apart").toString(), expected[row]);
    QVERIFY(!planners[3].toObject().contains("ranked_apart"));
    QCOMPARE(planners[1].toObject().value("flights_over_battery").toInt(), 124);
    QVERIFY(!planners[2].toObject().contains("flights_over_battery"));

    // The window's words and the exports' keys name the same groups: each group apart has both, the
    // others neither.
    for (const io::ReadingGroup group : {io::ReadingGroup::OwnSpeedsIgnored,
                                         io::ReadingGroup::FlightsOverBattery, io::ReadingGroup::CoversLess})
        QVERIFY(!io::rankedApartReason(group).empty() && !io::rankedApartKey(group).empty());
    QCOMPARE(io::rankedApartReason(io::ReadingGroup::FlightsOverBattery), std::string("flights too long"));
    for (const io::ReadingGroup group :
         {io::ReadingGroup::TimedAlike, io::ReadingGroup::Failed, io::ReadingGroup::Skipped})
        QVERIFY(io::rankedApartReason(group).empty() && io::rankedApartKey(group).empty());
}

QTEST_APPLESS_MAIN(TestComparisonRanking)
#include "test_comparison_ranking.moc"
