// Recognising well-known land-cover products from a raster's metadata, names, palette, file name or codes,
// and the table a raster opens with when nothing is recognised.

#include "io/ClassTableSources.hpp"
#include "io/internal/LegendReader.hpp"
#include "tests/support/TestData.hpp"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

using namespace mcpp;
using namespace mcpp::io;
using mcpp::test::testDataPath;

namespace {

LoadedRaster load(const std::string& relative) {
    auto raster = loadLandCoverRaster(testDataPath(relative));
    if (!raster)
        qFatal("%s", raster.error().c_str());
    return std::move(raster.value());
}

// A raster as the loader would hand it over, without a file: only what recognition looks at.
LoadedRaster rasterOf(const std::map<std::int32_t, std::int64_t>& counts,
                      const std::string& path = "map.tif") {
    LoadedRaster raster;
    raster.path = path;
    raster.classPixelCounts = counts;
    return raster;
}

LoadedRaster rasterWithValues(const std::vector<std::int32_t>& values, const std::string& path = "map.tif") {
    std::map<std::int32_t, std::int64_t> counts;
    for (const std::int32_t value : values)
        counts[value] = 1000;
    return rasterOf(counts, path);
}

double colourDistance(std::uint32_t first, std::uint32_t second) {
    double sum = 0.0;
    for (const unsigned shift : {16U, 8U, 0U}) {
        const double difference =
            static_cast<double>((first >> shift) & 0xffU) - static_cast<double>((second >> shift) & 0xffU);
        sum += difference * difference;
    }
    return std::sqrt(sum);
}

} // namespace

class ProductRecognitionTest : public QObject {
    Q_OBJECT

  private slots:
    void realRastersAreRecognised_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("preset");
        QTest::addColumn<QString>("evidence");
        QTest::addColumn<QList<int>>("walls");
        QTest::addColumn<int>("namedValue");
        QTest::addColumn<QString>("name");
        QTest::newRow("NLCD groups, category names") << "landcover/nlcd.tif"
                                                     << "nlcd-simplified"
                                                     << "class names" << QList<int>{1, 2} << 4 << "Forest";
        QTest::newRow("CORINE codes, Spanish QGIS style")
            << "landcover/corine-spain/clc.tif"
            << "corine"
            << "metadata" << QList<int>{111, 112, 512} << 311 << "Bosques de frondosas";
        QTest::newRow("ESA WorldCover, legend metadata")
            << "landcover/worldcover2021_principe_crop.tif"
            << "esa-worldcover"
            << "metadata" << QList<int>{50, 80} << 10 << "Tree cover";
        QTest::newRow("Canada, file name") << "landcover/nrcan_landcover2015_example.tif"
                                           << "canada-landcover"
                                           << "file name" << QList<int>{17, 18, 19} << 14 << "Wetland";
        QTest::newRow("CORINE grid codes, file name")
            << "landcover/corine2006_swiss_ls100.tif"
            << "corine-grid"
            << "file name" << QList<int>{1, 2, 3, 41} << 24 << "Coniferous forest";
    }

    void realRastersAreRecognised() {
        QFETCH(QString, file);
        QFETCH(QString, preset);
        QFETCH(QString, evidence);
        QFETCH(QList<int>, walls);
        QFETCH(int, namedValue);
        QFETCH(QString, name);
        const LoadedRaster raster = load(file.toStdString());
        const OpeningClassTable opening = openingClassTable(raster);
        QCOMPARE(QString::fromStdString(opening.preset), preset);
        QVERIFY2(opening.explanation.find(evidence.toStdString()) != std::string::npos,
                 opening.explanation.c_str());
        QVERIFY2(opening.explanation.find(preset.toStdString()) != std::string::npos,
                 opening.explanation.c_str());
        QCOMPARE(opening.table.size(), raster.classPixelCounts.size());
        for (const int value : walls) {
            QVERIFY2(raster.classPixelCounts.count(value) == 1, "the wall class is in the raster");
            QVERIFY2(!opening.table.find(value)->passable, std::to_string(value).c_str());
        }
        QCOMPARE(QString::fromStdString(opening.table.find(namedValue)->name), name);
        for (const LandCoverClass& row : opening.table.classes())
            QVERIFY2(row.name.rfind("Class ", 0) != 0, row.name.c_str());
        // Opening a mission with neither rows nor a preset gives the same table.
        QCOMPARE(missionClassTable({}, "", raster), opening.table);
    }

    // The same files under a name that says nothing: the palette, or the codes and the CRS, recognise them.
    void recognisedWithoutTheFileName_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("preset");
        QTest::addColumn<QString>("evidence");
        QTest::newRow("Canada: codes and CRS") << "landcover/nrcan_landcover2015_example.tif"
                                               << "canada-landcover"
                                               << "Canada Atlas Lambert";
        QTest::newRow("CORINE grid codes: palette") << "landcover/corine2006_swiss_ls100.tif"
                                                    << "corine-grid"
                                                    << "palette";
    }

    void recognisedWithoutTheFileName() {
        QFETCH(QString, file);
        QFETCH(QString, preset);
        QFETCH(QString, evidence);
        QTemporaryDir folder;
        const QString copy = folder.filePath("map.tif");
        QVERIFY(QFile::copy(QString::fromStdString(testDataPath(file.toStdString())), copy));
        auto raster = loadLandCoverRaster(copy.toStdString());
        QVERIFY(raster.ok());
        const OpeningClassTable opening = openingClassTable(raster.value());
        QCOMPARE(QString::fromStdString(opening.preset), preset);
        QVERIFY2(opening.explanation.find(evidence.toStdString()) != std::string::npos,
                 opening.explanation.c_str());
    }

    void worldCoverNamesComeFromItsLegendMetadata() {
        const LoadedRaster raster = load("landcover/worldcover2021_principe_crop.tif");
        QCOMPARE(raster.legendSource.substr(0, 15), std::string("legend metadata"));
        QVERIFY(raster.metadataText.find("ESA WorldCover") != std::string::npos);
        const auto tree = std::find_if(raster.legend.begin(), raster.legend.end(),
                                       [](const LegendEntry& entry) { return entry.value == 10; });
        QVERIFY(tree != raster.legend.end());
        QCOMPARE(tree->name, std::string("Tree cover"));
        QCOMPARE(*tree->colorRgb, 0x006400U); // from the file's palette
    }

    void metadataLegendLines() {
        const auto entries = internal::parseMetadataLegend("10  Tree cover\r\n\nnot a class\n20:Shrubland\n"
                                                           "  30\tGrassland  \n40\n1e2 Moss\n-5 = Below\n");
        QCOMPARE(entries.size(), std::size_t{5});
        QCOMPARE(entries[0].value, 10);
        QCOMPARE(entries[0].name, std::string("Tree cover"));
        QCOMPARE(entries[1].name, std::string("Shrubland"));
        QCOMPARE(entries[2].name, std::string("Grassland"));
        QCOMPARE(entries[3].value, 100);
        QCOMPARE(entries[4].value, -5);
        QCOMPARE(entries[4].name, std::string("Below"));
    }

    void codesAloneRecogniseOnlyProductsWhoseCodesAreTheirOwn_data() {
        QTest::addColumn<QList<int>>("values");
        QTest::addColumn<QString>("crs");
        QTest::addColumn<QString>("preset");
        QTest::newRow("NLCD two-digit codes") << QList<int>{11, 21, 22, 41, 42, 52, 71, 81, 90} << ""
                                              << "nlcd";
        QTest::newRow("Cropland Data Layer in CONUS Albers")
            << QList<int>{1, 5, 24, 36, 111, 121, 122, 141, 176, 190} << "NAD83 / Conus Albers"
            << "cropland-data-layer";
        QTest::newRow("CORINE three-digit codes") << QList<int>{112, 211, 311, 312, 512} << ""
                                                  << "corine";
        QTest::newRow("Copernicus forests") << QList<int>{20, 30, 111, 112, 126} << ""
                                            << "copernicus-glc100";
        QTest::newRow("grid codes in a European CRS")
            << QList<int>{2, 12, 23, 24, 41} << "ETRS89 / LAEA Europe"
            << "corine-grid";
        QTest::newRow("grid codes elsewhere") << QList<int>{2, 12, 23, 24, 41} << "WGS 84 / UTM zone 12N"
                                              << "";
        QTest::newRow("small integers") << QList<int>{1, 2, 3, 4, 5, 6} << ""
                                        << "";
        QTest::newRow("two codes") << QList<int>{11, 90} << ""
                                   << "";
        QTest::newRow("codes no product has") << QList<int>{7, 300, 301} << ""
                                              << "";
    }

    void codesAloneRecogniseOnlyProductsWhoseCodesAreTheirOwn() {
        QFETCH(QList<int>, values);
        QFETCH(QString, crs);
        QFETCH(QString, preset);
        LoadedRaster raster = rasterWithValues(std::vector<std::int32_t>(values.begin(), values.end()));
        raster.sourceCrsName = crs.toStdString();
        QCOMPARE(QString::fromStdString(openingClassTable(raster).preset), preset);
    }

    void aFewStrayPixelsDoNotHideTheProduct() {
        std::map<std::int32_t, std::int64_t> counts = {{11, 5000}, {21, 5000}, {41, 5000}, {90, 5000}};
        counts[250] = 150; // 0.7% of the pixels: a code NLCD does not have
        OpeningClassTable opening = openingClassTable(rasterOf(counts));
        QCOMPARE(opening.preset, std::string("nlcd"));
        QCOMPARE(opening.table.find(250)->name, std::string("Class 250"));
        counts[250] = 500; // 2.4%: no longer NLCD
        QCOMPARE(openingClassTable(rasterOf(counts)).preset, std::string());
    }

    void fileNamesAndMetadataNameProducts() {
        const std::vector<std::int32_t> values = {1, 5, 24, 176};
        QCOMPARE(openingClassTable(rasterWithValues(values, "/data/CDL_2023_19.tif")).preset,
                 std::string("cropland-data-layer"));
        LoadedRaster described = rasterWithValues({2, 12, 23});
        QCOMPARE(openingClassTable(described).preset, std::string());
        described.metadataText = "TIFFTAG_IMAGEDESCRIPTION=CORINE Land Cover 2018\n";
        QCOMPARE(openingClassTable(described).preset, std::string("corine-grid"));
        described.metadataText = "TIFFTAG_IMAGEDESCRIPTION=scorine\n"; // not the word
        QCOMPARE(openingClassTable(described).preset, std::string());
    }

    void aFileNamingItsOwnClassesIsNotTakenForAProduct() {
        LoadedRaster raster = rasterWithValues({10, 20, 30, 80});
        QCOMPARE(openingClassTable(raster).preset, std::string("esa-worldcover"));
        raster.legend = {{10, "Forest", std::nullopt},
                         {20, "Field", std::nullopt},
                         {30, "Lake", std::nullopt},
                         {80, "Village", std::nullopt}};
        raster.legendSource = "category names";
        const OpeningClassTable opening = openingClassTable(raster);
        QCOMPARE(opening.preset, std::string());
        QVERIFY(opening.fromLegendNames);
        QCOMPARE(opening.table.find(30)->name, std::string("Lake"));
        QVERIFY(opening.explanation.find("not recognised") != std::string::npos);
        QVERIFY(opening.explanation.find("category names") != std::string::npos);
    }

    void unknownClassesGetColoursThatStayApart() {
        std::vector<std::int32_t> values;
        for (std::int32_t value = 1; value <= 55; ++value)
            values.push_back(value * 3);
        const OpeningClassTable opening = openingClassTable(rasterWithValues(values));
        QCOMPARE(opening.preset, std::string());
        QVERIFY(!opening.fromLegendNames);
        QVERIFY(opening.explanation.find("55 classes without names") != std::string::npos);
        const auto& rows = opening.table.classes();
        double closest = 1e9;
        for (std::size_t first = 0; first < rows.size(); ++first)
            for (std::size_t second = first + 1; second < rows.size(); ++second)
                closest = std::min(closest, colourDistance(rows[first].colorRgb, rows[second].colorRgb));
        QVERIFY2(closest >= 12.0, std::to_string(closest).c_str()); // no two the same colour
        // Neighbours in the table, which sit side by side in the legend, are clearly apart.
        for (std::size_t index = 1; index < rows.size(); ++index)
            QVERIFY(colourDistance(rows[index - 1].colorRgb, rows[index].colorRgb) >= 60.0);
    }
};

QTEST_GUILESS_MAIN(ProductRecognitionTest)
#include "test_product_recognition.moc"
