#include "core/decomposition/FieldOfViewRounding.hpp"

#include <QtTest>
#include <map>

using namespace mcpp;

namespace {

std::map<std::int32_t, RoundedFieldOfView> byValue(const std::vector<RoundedFieldOfView>& rounded) {
    std::map<std::int32_t, RoundedFieldOfView> map;
    for (const auto& entry : rounded)
        map[entry.classValue] = entry;
    return map;
}

} // namespace

// The one FOV rule (spec 2), shared by the planners and the class table view.
class TestFieldOfViewRounding : public QObject {
    Q_OBJECT

  private slots:
    void roundsDownToPowersOfTwoOfTheSmallest() {
        const ClassTable table(
            {LandCoverClass{1, "Grass", 0, 2.0, 10.0, true}, LandCoverClass{2, "Forest", 0, 1.0, 25.0, true},
             LandCoverClass{3, "Field", 0, 3.0, 40.0, true}, LandCoverClass{4, "Water", 0, 0.0, 1.0, false}});
        const auto rounded = byValue(roundFieldsOfView(table, {1, 2, 3, 4}));
        QCOMPARE(rounded.at(1).roundedMetres, 10.0);
        QCOMPARE(rounded.at(2).roundedMetres, 20.0);
        QCOMPARE(rounded.at(3).roundedMetres, 40.0);
        QCOMPARE(rounded.at(3).level, 1); // the largest FOV is the top level
        QCOMPARE(rounded.at(2).level, 2);
        QCOMPARE(rounded.at(1).level, 3);
        QVERIFY(!rounded.contains(4)); // obstacles take no part
    }

    void ignoresClassesAbsentFromTheRaster() {
        const ClassTable table(
            {LandCoverClass{1, "Grass", 0, 2.0, 10.0, true}, LandCoverClass{2, "Forest", 0, 1.0, 5.0, true}});
        const auto rounded = byValue(roundFieldsOfView(table, {1}));
        QCOMPARE(rounded.at(1).roundedMetres, 10.0);
        QCOMPARE(rounded.at(1).level, 1);
        QVERIFY(!rounded.contains(2));
    }

    void unusableFieldsOfViewTakeNoPart() {
        const ClassTable table({LandCoverClass{1, "Grass", 0, 2.0, 10.0, true},
                                LandCoverClass{2, "Bad", 0, 1.0, -5.0, true},
                                LandCoverClass{3, "Unknown", 0, 1.0, std::nan(""), true}});
        const auto rounded = byValue(roundFieldsOfView(table, {1, 2, 3}));
        QCOMPARE(rounded.size(), std::size_t{1});
        QCOMPARE(rounded.at(1).roundedMetres, 10.0);
    }

    void noPassableClassGivesNothing() {
        const ClassTable table({LandCoverClass{4, "Water", 0, 0.0, 10.0, false}});
        QVERIFY(roundFieldsOfView(table, {4}).empty());
    }
};

QTEST_GUILESS_MAIN(TestFieldOfViewRounding)
#include "test_field_of_view_rounding.moc"
