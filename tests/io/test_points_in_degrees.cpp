// Map points in messages given their longitude and latitude: those on the map or near it, read back to the
// same point; pairs of numbers that are not the map's points, and maps without a CRS, left as they are.
#include "io/PointsInDegrees.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <regex>

using namespace mcpp;

namespace {

// 49 x 49 pixels of 10 m in WGS 84 / UTM zone 33N, north-west corner at (431000, 5400000).
ClassGrid utmGrid() {
    return test::filledGrid(49, 49, 431000.0, 5400000.0, 10.0, 1);
}

io::GeoReference utm33() {
    const auto georeference = io::GeoReference::fromDefinition("EPSG:32633");
    if (!georeference)
        qFatal("EPSG:32633 is not known");
    return georeference.value();
}

} // namespace

class TestPointsInDegrees : public QObject {
    Q_OBJECT

  private slots:
    void mapPointsGetDegreesThatLeadBack() {
        const io::GeoReference georeference = utm33();
        const std::string message =
            "land cut off (in 3 pieces, the largest (300 m2) round (431385, 5399995)); "
            "robot 2 takes off at (431005.5, 5399515.25)";
        const std::string placed = io::withPointsInDegrees(message, georeference, utmGrid());
        const std::regex withDegrees(
            R"(\((-?[0-9.]+), (-?[0-9.]+); longitude (-?[0-9.]+), latitude (-?[0-9.]+)\))");
        int found = 0;
        for (auto match = std::sregex_iterator(placed.begin(), placed.end(), withDegrees);
             match != std::sregex_iterator(); ++match, ++found) {
            const MapPoint given{std::stod((*match)[1].str()), std::stod((*match)[2].str())};
            const auto back =
                georeference.fromWgs84({std::stod((*match)[3].str()), std::stod((*match)[4].str())});
            QVERIFY(back.ok());
            QVERIFY2(std::hypot(back.value().x - given.x, back.value().y - given.y) < 0.05, placed.c_str());
        }
        QCOMPARE(found, 2);
        QVERIFY2(placed.find("(300 m2)") != std::string::npos, placed.c_str());
        QVERIFY2(placed.rfind(
                     "land cut off (in 3 pieces, the largest (300 m2) round (431385, 5399995; longitude 14.",
                     0) == 0,
                 placed.c_str());
    }

    // Seven decimals (about a centimetre) at any size of degrees, trailing zeros dropped.
    void degreesHaveSevenDecimals() {
        QCOMPARE(io::degreesText({-122.41941554, 7.5}), std::string("longitude -122.4194155, latitude 7.5"));
        QCOMPARE(io::degreesText({0.123456789, -0.0000004}),
                 std::string("longitude 0.1234568, latitude -0.0000004"));
        QCOMPARE(io::degreesText({-0.00000001, 45.0}), std::string("longitude 0, latitude 45"));
    }

    void otherPairsAndMapsWithoutCrsAreLeftAlone() {
        const std::string farOff = "ratios (1, 2) and (431385, 5399995)";
        const std::string placed = io::withPointsInDegrees(farOff, utm33(), utmGrid());
        QVERIFY2(placed.find("(1, 2)") != std::string::npos, placed.c_str());
        QVERIFY2(placed.find("(431385, 5399995; longitude") != std::string::npos, placed.c_str());
        QCOMPARE(io::withPointsInDegrees(farOff, io::GeoReference(), utmGrid()), farOff);
    }
};

QTEST_APPLESS_MAIN(TestPointsInDegrees)
#include "test_points_in_degrees.moc"
