// Presets, class tables made for a raster, reconciliation, and the class table CSV.

#include "io/ClassTableSources.hpp"
#include "io/MissionInputs.hpp"
#include "tests/support/TestData.hpp"

#include <QTemporaryDir>
#include <QTest>
#include <fstream>
#include <set>
#include <sstream>

using namespace mcpp;
using namespace mcpp::io;
using mcpp::test::testDataPath;

namespace {

ClassTable preset(const std::string& name) {
    auto table = presetClassTable(name);
    if (!table)
        qFatal("%s", table.error().c_str());
    return table.value();
}

LoadedRaster load(const std::string& relative) {
    auto raster = loadLandCoverRaster(testDataPath(relative));
    if (!raster)
        qFatal("%s", raster.error().c_str());
    return std::move(raster.value());
}

// Rows of a legend CSV in tests/data/legends, split on commas outside quotes.
std::vector<std::vector<std::string>> readCsv(const std::string& relative) {
    std::ifstream file(testDataPath(relative));
    std::vector<std::vector<std::string>> rows;
    std::string line;
    std::getline(file, line); // header
    while (std::getline(file, line)) {
        std::vector<std::string> fields(1);
        bool quoted = false;
        for (const char character : line) {
            if (character == '"')
                quoted = !quoted;
            else if (character == ',' && !quoted)
                fields.emplace_back();
            else if (character != '\r')
                fields.back() += character;
        }
        rows.push_back(fields);
    }
    return rows;
}

std::uint32_t rgb(int red, int green, int blue) {
    return (static_cast<std::uint32_t>(red) << 16U) | (static_cast<std::uint32_t>(green) << 8U) |
           static_cast<std::uint32_t>(blue);
}

void writeText(const std::string& path, const std::string& text) {
    std::ofstream file(path, std::ios::binary);
    file << text;
}

} // namespace

class ClassTablesTest : public QObject {
    Q_OBJECT

  private slots:
    void everyPresetIsListedAndValid() {
        const std::set<std::string> expected{"esa-worldcover",
                                             "nlcd",
                                             "nlcd-simplified",
                                             "corine",
                                             "corine-grid",
                                             "canada-landcover",
                                             "copernicus-glc100",
                                             "cropland-data-layer",
                                             "paper"};
        std::set<std::string> listed;
        for (const PresetInfo& info : classTablePresets()) {
            listed.insert(info.name);
            QVERIFY(!info.description.empty());
            const ClassTable table = preset(info.name);
            QVERIFY2(!table.validate().has_value(), info.name.c_str());
            QVERIFY(table.size() >= 6);
            for (const LandCoverClass& entry : table.classes()) {
                QVERIFY(!entry.name.empty());
                if (entry.isTraversable())
                    QVERIFY(entry.fieldOfViewMetres >= 5.0 && entry.fieldOfViewMetres <= 20.0);
            }
        }
        QVERIFY(listed == expected);
        auto unknown = presetClassTable("nope");
        QVERIFY(!unknown.ok());
        QVERIFY(unknown.error().find("nope") != std::string::npos);
        QVERIFY(unknown.error().find("esa-worldcover") != std::string::npos);
        QVERIFY(unknown.error().find("did you mean") == std::string::npos); // nothing that close
        // A name typed in other case, or a letter or two off, gets the one it most likely meant.
        for (const char* typed : {"ESA-WorldCover", "esa-worldcovr", "esa_worldcover", "worldcover"}) {
            const auto misspelt = presetClassTable(typed);
            QVERIFY(!misspelt.ok());
            QVERIFY2(misspelt.error().find("did you mean \"esa-worldcover\"?") != std::string::npos,
                     misspelt.error().c_str());
        }
    }

    void waterSnowAndBuiltUpAreNotDrivable() {
        const std::vector<std::pair<std::string, std::vector<std::int32_t>>> blocked{
            {"esa-worldcover", {50, 70, 80}},
            {"nlcd", {11, 12, 23, 24}},
            {"nlcd-simplified", {1}},
            {"corine", {111, 335, 511, 512, 523}},
            {"corine-grid", {1, 34, 40, 41, 44}},
            {"canada-landcover", {17, 18, 19}},
            {"copernicus-glc100", {50, 70, 80, 200}},
            {"cropland-data-layer", {81, 83, 92, 111, 112, 123, 124}}};
        for (const auto& [name, values] : blocked) {
            const ClassTable table = preset(name);
            for (const std::int32_t value : values) {
                QVERIFY2(table.find(value) != nullptr && !table.find(value)->isTraversable(),
                         (name + " " + std::to_string(value)).c_str());
            }
        }
        QVERIFY(preset("corine").find(122)->speedMetresPerSecond >
                preset("corine").find(311)->speedMetresPerSecond);
    }

    void paperPresetNeedsSeveralQuadtreeLevels() {
        const ClassTable table = preset("paper");
        const std::vector<std::string> names{"farm", "road", "grass", "wood", "bare land", "gobi"};
        std::set<double> fovs;
        for (std::int32_t value = 1; value <= 6; ++value) {
            QVERIFY(table.find(value) != nullptr);
            QCOMPARE(table.find(value)->name, names[static_cast<std::size_t>(value - 1)]);
            QVERIFY(table.find(value)->isTraversable());
            fovs.insert(table.find(value)->fieldOfViewMetres);
        }
        QVERIFY(fovs.size() >= 3);
        QCOMPARE(*fovs.begin(), 5.0);
        QCOMPARE(*fovs.rbegin(), 20.0);
    }

    void presetsAgreeWithTheLegendFiles() {
        const ClassTable esa = preset("esa-worldcover");
        for (const auto& row : readCsv("legends/esa_worldcover_v200.csv")) {
            QCOMPARE(esa.find(std::stoi(row[0]))->name, row[1]);
        }
        const ClassTable grid = preset("corine-grid");
        const ClassTable corine = preset("corine");
        for (const auto& row : readCsv("legends/clc_grid_code_legend.csv")) {
            const LandCoverClass* byGrid = grid.find(std::stoi(row[0]));
            const LandCoverClass* byCode = corine.find(std::stoi(row[1]));
            QVERIFY(byGrid != nullptr && byCode != nullptr);
            QCOMPARE(byGrid->name, row[4]);
            QCOMPARE(byCode->name, row[4]);
            const std::string& colour = row[5]; // "230-000-077"
            const std::uint32_t expected = rgb(std::stoi(colour.substr(0, 3)), std::stoi(colour.substr(4, 3)),
                                               std::stoi(colour.substr(8, 3)));
            QCOMPARE(byGrid->colorRgb, expected);
            QCOMPARE(byCode->colorRgb, expected);
            QCOMPARE(byGrid->speedMetresPerSecond, byCode->speedMetresPerSecond);
        }
        const ClassTable canada = preset("canada-landcover");
        for (const auto& row : readCsv("legends/nrcan_canada_landcover_2015.csv")) {
            QCOMPARE(canada.find(std::stoi(row[0]))->name, row[1]);
        }
        const ClassTable nlcd = preset("nlcd");
        for (const auto& row : readCsv("legends/nlcd_from_stars_lc_rat.csv")) {
            const LandCoverClass* entry = nlcd.find(std::stoi(row[0]));
            QVERIFY(entry != nullptr);
            QCOMPARE(entry->colorRgb, rgb(std::stoi(row[2]), std::stoi(row[3]), std::stoi(row[4])));
        }
        const ClassTable simplified = preset("nlcd-simplified");
        for (const auto& row : readCsv("legends/spDataLarge_nlcd_simplified_categories.csv")) {
            if (row[0] == "0")
                continue; // "NA"
            QCOMPARE(simplified.find(std::stoi(row[0]))->name, row[1]);
        }
    }

    void tableForRasterUsesItsLegend() {
        const LoadedRaster nlcd = load("landcover/nlcd.tif");
        const ClassTable table = classTableForRaster(nlcd, "nlcd-simplified");
        QCOMPARE(table.size(), std::size_t{8});
        QCOMPARE(table.find(4)->name, std::string("Forest"));
        QCOMPARE(table.find(4)->colorRgb, 0x68aa63U);
        QVERIFY(!table.find(1)->isTraversable());
        QCOMPARE(table.find(4)->speedMetresPerSecond,
                 preset("nlcd-simplified").find(4)->speedMetresPerSecond);

        const LoadedRaster clc = load("landcover/corine-spain/clc.tif");
        const ClassTable spanish = classTableForRaster(clc, "corine");
        QCOMPARE(spanish.size(), std::size_t{20});
        QCOMPARE(spanish.find(111)->name, std::string("Tejido urbano continuo"));
        QVERIFY(!spanish.find(111)->isTraversable());
        QCOMPARE(spanish.find(323)->speedMetresPerSecond, preset("corine").find(323)->speedMetresPerSecond);
        QVERIFY(!spanish.validate().has_value());
    }

    // A mission's own rows win; its preset fills the values they lack; with neither, the generic table.
    void missionTableMergesOwnRowsAndPreset() {
        const LoadedRaster nlcd = load("landcover/nlcd.tif");
        ClassTable own;
        own.set({4, "Pine forest", 0x112233, 0.4, 50.0, true});
        const ClassTable merged = missionClassTable(own, "nlcd-simplified", nlcd);
        QCOMPARE(merged.size(), std::size_t{8});
        QCOMPARE(merged.find(4)->name, std::string("Pine forest"));
        QCOMPARE(merged.find(4)->speedMetresPerSecond, 0.4);
        QCOMPARE(merged.find(2)->speedMetresPerSecond,
                 preset("nlcd-simplified").find(2)->speedMetresPerSecond);
        QCOMPARE(missionClassTable(own, "", nlcd), own);
        QCOMPARE(missionClassTable({}, "", nlcd), openingClassTable(nlcd).table);
    }

    // A row that gives no colour is not painted grey: it takes the colour of its class from the preset, the
    // raster's palette or the opening table; a row that gives one keeps it, and so does a row whose class
    // the raster does not hold.
    void ownRowsWithoutColourTakeTheMapsColours() {
        const LoadedRaster nlcd = load("landcover/nlcd.tif");
        const ClassesWithoutColour withoutColour{4, 5, 99};
        ClassTable own;
        own.set({4, "Pine forest", 0x808080, 0.4, 50.0, true});
        own.set({5, "Scrub", 0x808080, 0.5, 50.0, true});
        own.set({6, "Grass", 0x123456, 0.9, 50.0, true});
        own.set({99, "Not on the map", 0x808080, 0.9, 50.0, true});
        const ClassTable presetColours = classTableForRaster(nlcd, "nlcd-simplified");
        const ClassTable merged = missionClassTable(own, "nlcd-simplified", nlcd, withoutColour);
        QCOMPARE(merged.find(4)->colorRgb, presetColours.find(4)->colorRgb);
        QCOMPARE(merged.find(5)->colorRgb, presetColours.find(5)->colorRgb);
        QVERIFY(merged.find(4)->colorRgb != 0x808080U);
        QCOMPARE(merged.find(4)->name, std::string("Pine forest")); // only the colour is taken
        QCOMPARE(merged.find(6)->colorRgb, 0x123456U);
        QCOMPARE(merged.find(99)->colorRgb, 0x808080U); // in no table
        // A value the raster does not hold (a class outside the area of interest) takes the preset's.
        std::int32_t presetOnly = -1;
        const ClassTable nlcdPreset = preset("nlcd");
        for (const LandCoverClass& row : nlcdPreset.classes())
            if (presetOnly < 0 && nlcd.classPixelCounts.count(row.value) == 0)
                presetOnly = row.value;
        QVERIFY(presetOnly >= 0);
        ClassTable offTheMap;
        offTheMap.set({presetOnly, "Not here", 0x808080, 0.5, 50.0, true});
        const ClassTable withPreset = missionClassTable(offTheMap, "nlcd", nlcd, {presetOnly});
        QCOMPARE(withPreset.find(presetOnly)->colorRgb, nlcdPreset.find(presetOnly)->colorRgb);
        QVERIFY(withPreset.find(presetOnly)->colorRgb != 0x808080U);
        const ClassTable opening = openingClassTable(nlcd).table;
        const ClassTable withoutPreset = missionClassTable(own, "", nlcd, withoutColour);
        QCOMPARE(withoutPreset.find(5)->colorRgb, opening.find(5)->colorRgb);
        QCOMPARE(withoutPreset.find(6)->colorRgb, 0x123456U);

        ClassesWithoutColour read;
        const auto csv = parseClassTableCsv(
            "value,name,speed_mps,fov_m,passable,color\n4,Forest,1,10,true,\n6,Grass,1,10,true,#123456\n"
            "7,Crops,1,10,true,#abcdef\n",
            "classes.csv", &read);
        QVERIFY2(csv.ok(), csv.ok() ? "" : csv.error().c_str());
        QCOMPARE(read, (ClassesWithoutColour{4}));
        ClassesWithoutColour noColumn;
        QVERIFY(parseClassTableCsv("value,name,speed_mps,fov_m,passable\n4,Forest,1,10,true\n", "c.csv",
                                   &noColumn)
                    .ok());
        QCOMPARE(noColumn, (ClassesWithoutColour{4}));
    }

    // A mission's classes.fov_m is one footprint over every class, the mission's own rows included, as
    // --fov gives it: a drone's camera over a ground robot's preset.
    void aMissionsFieldOfViewIsEveryClasss() {
        const LoadedRaster nlcd = load("landcover/nlcd.tif");
        Mission mission;
        mission.preset = "nlcd-simplified";
        mission.classes.set(LandCoverClass{4, "Forest", 0x225522, 0.5, 5.0, true});
        const auto names = [](const MissionField&) { return std::string("classes"); };
        const auto asPreset = missionClasses(mission, nlcd, names);
        QVERIFY(asPreset.ok());
        QCOMPARE(asPreset.value().find(4)->fieldOfViewMetres, 5.0);
        mission.fieldOfViewMetres = 60.0;
        const auto footprint = missionClasses(mission, nlcd, names);
        QVERIFY(footprint.ok());
        QCOMPARE(footprint.value().size(), asPreset.value().size());
        for (const LandCoverClass& landCover : footprint.value().classes())
            QCOMPARE(landCover.fieldOfViewMetres, 60.0);
        QCOMPARE(footprint.value().find(4)->speedMetresPerSecond, 0.5); // the rest of the row as given
    }

    // A preset of another product is refused; one that lacks some classes is planned with a warning that
    // names them and their share; the mission's own rows fill gaps.
    void presetOfAnotherProductIsCaught() {
        const LoadedRaster nlcd = load("landcover/nlcd.tif"); // the eight simplified groups, 1-8
        Mission mission;
        mission.preset = "corine";
        const auto names = [](const MissionField&) { return std::string("--preset"); };
        const auto refused = missionClasses(mission, nlcd, names);
        QVERIFY(!refused.ok());
        QVERIFY2(
            refused.error().find("preset corine has a row for none of the raster's 8 classes (1, 2, 3, 4, 5, "
                                 "6, 7, 8)") != std::string::npos,
            refused.error().c_str());
        QVERIFY(!presetGapWarning(mission, nlcd)); // refused, not warned about

        // Swiss CORINE codes 1-44 beside WorldCover's 10, 20, ... 100: a few match by chance, most of the map
        // does not.
        const LoadedRaster swiss = load("landcover/corine2006_swiss_ls100.tif");
        mission.preset = "esa-worldcover";
        const auto byChance = missionClasses(mission, swiss, names);
        QVERIFY(!byChance.ok());
        QVERIFY2(byChance.error().find("preset esa-worldcover has no row for classes ") !=
                         std::string::npos &&
                     byChance.error().find("of the map: it is most likely another product's legend") !=
                         std::string::npos,
                 byChance.error().c_str());

        mission.preset = "paper"; // values 1-6
        QVERIFY(missionClasses(mission, nlcd, names).ok());
        const auto gap = presetGapWarning(mission, nlcd);
        QVERIFY(gap.has_value());
        QVERIFY2(gap->find("preset paper has no row for classes 7, 8 (") != std::string::npos, gap->c_str());
        QVERIFY2(gap->find("planned as passable at 1 m/s with a 10 m field of view") != std::string::npos,
                 gap->c_str());
        mission.classes.set({7, "Shrub", 0x556b2f, 2.0, 20.0, true});
        mission.classes.set({8, "Wetland", 0x4682b4, 0.5, 20.0, true});
        QVERIFY(!presetGapWarning(mission, nlcd));
        mission.preset = "nlcd-simplified";
        mission.classes = ClassTable{};
        QVERIFY(!presetGapWarning(mission, nlcd));
    }

    void unknownClassesGetTheGenericRow() {
        const LoadedRaster nrcan = load("landcover/nrcan_landcover2015_example.tif");
        const ClassTable generic = classTableForRaster(nrcan);
        QCOMPARE(generic.size(), std::size_t{13});
        const LandCoverClass* first = generic.find(1);
        QCOMPARE(first->name, std::string("Class 1"));
        QVERIFY(first->colorRgb != generic.find(2)->colorRgb); // not one flat grey
        QCOMPARE(first->speedMetresPerSecond, 1.0);
        QCOMPARE(first->fieldOfViewMetres, 10.0);
        QVERIFY(first->passable);
        const ClassTable canada = classTableForRaster(nrcan, "canada-landcover");
        QCOMPARE(canada.find(18)->name, std::string("Water"));
        QVERIFY(!canada.find(18)->isTraversable());
    }

    void reconcileReportsOrBlocksMissingClasses() {
        LoadedRaster raster = load("landcover/nrcan_landcover2015_example.tif");
        ClassTable table = classTableForRaster(raster, "canada-landcover");
        QVERIFY(reconcileRasterWithTable(raster, table, false).ok());
        table.remove(18);
        table.remove(19);
        Status refused = reconcileRasterWithTable(raster, table, false);
        QVERIFY(!refused.ok());
        QVERIFY(refused.error().find("18, 19") != std::string::npos);
        QVERIFY(refused.error().find("nrcan_landcover2015_example.tif") != std::string::npos);

        const std::int64_t water = raster.classPixelCounts.at(18) + raster.classPixelCounts.at(19);
        QVERIFY(reconcileRasterWithTable(raster, table, true).ok());
        QCOMPARE(raster.classPixelCounts.count(18), std::size_t{0});
        QCOMPARE(
            std::count(raster.grid.outside.begin(), raster.grid.outside.end(), ClassGrid::outsideUnlisted),
            water);
        QVERIFY(raster.warnings.back().find("18, 19") != std::string::npos);
        QVERIFY(reconcileRasterWithTable(raster, table, false).ok());
    }

    void csvRoundTrip() {
        QTemporaryDir folder;
        const std::string path = folder.filePath("classes.csv").toStdString();
        ClassTable table = preset("nlcd"); // names with commas
        table.set(LandCoverClass{7, "Quote \"here\"", 0x123456, 0.25, 7.5, true});
        // One class with its own detection probability: the column is written, empty for the others.
        LandCoverClass forest{8, "Under trees", 0x225522, 0.5, 5.0, true};
        forest.detectionProbability = 0.35;
        table.set(forest);
        QVERIFY(saveClassTableCsv(table, path).ok());
        auto loaded = loadClassTableCsv(path);
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().c_str());
        QVERIFY(loaded.value() == table);
        QCOMPARE(*loaded.value().find(8)->detectionProbability, 0.35);
        QVERIFY(!loaded.value().find(7)->detectionProbability);
    }

    void csvWithoutColorColumnAndOtherOrder() {
        QTemporaryDir folder;
        const std::string path = folder.filePath("simple.csv").toStdString();
        writeText(path, "name,value,passable,fov_m,speed_mps\nfield,1,yes,10,1.5\nlake,2,no,10,0\n");
        auto loaded = loadClassTableCsv(path);
        QVERIFY(loaded.ok());
        QCOMPARE(loaded.value().find(1)->name, std::string("field"));
        QCOMPARE(loaded.value().find(1)->colorRgb, 0x808080U);
        QVERIFY(!loaded.value().find(2)->passable);
    }

    void csvErrorsNameLineAndColumn() {
        QTemporaryDir folder;
        const std::string path = folder.filePath("bad.csv").toStdString();
        const std::vector<std::pair<std::string, std::vector<std::string>>> cases{
            {"value,name,speed_mps,fov_m\n1,a,1,10\n", {"line 1", "passable"}},
            {"value,name,speed_mps,fov_m,passable,colour,weight\n", {"line 1", "column 7", "weight"}},
            {"value,name,speed_mps,fov_m,passable\n1,a,fast,10,true\n", {"line 2", "speed_mps", "fast"}},
            {"value,name,speed_mps,fov_m,passable\n1,a,1,10,true\n2,b,1,10,maybe\n",
             {"line 3", "passable", "maybe"}},
            {"value,name,speed_mps,fov_m,passable\n1.5,a,1,10,true\n", {"line 2", "value"}},
            {"value,name,speed_mps,fov_m,passable\n1,a,1,10,true\n1,b,1,10,true\n", {"line 3", "repeats"}},
            {"value,name,speed_mps,fov_m,passable\n1,a,1,10\n", {"line 2", "expected 5 fields"}},
            {"value,name,speed_mps,fov_m,passable,color\n1,a,1,10,true,red\n", {"line 2", "color"}},
            {"value,name,speed_mps,fov_m,passable\n1,\"a,1,10,true\n", {"line 2", "quote"}},
            {"value,name,speed_mps,fov_m,passable\n1,a,1,0,true\n", {"line 2", "fov_m"}},
            {"", {"line 1", "header"}},
            // A legend is not a class table: said with where one comes from.
            {"value,name\n1,forest\n", {"line 1", "speed_mps", "a legend of names does not", "--preset"}},
            {"GRID_CODE,CLC_CODE,LABEL3\n1,111,Continuous urban fabric\n",
             {"line 1", "GRID_CODE", "a legend of names does not"}},
        };
        for (const auto& [text, fragments] : cases) {
            writeText(path, text);
            auto loaded = loadClassTableCsv(path);
            QVERIFY2(!loaded.ok(), text.c_str());
            const std::string& error = loaded.error();
            QVERIFY2(error.rfind(path, 0) == 0, error.c_str());
            QVERIFY2(error.find('\n') == std::string::npos, error.c_str());
            for (const std::string& fragment : fragments)
                QVERIFY2(error.find(fragment) != std::string::npos, error.c_str());
        }
        writeText(path, "value,name,speed_mps,fov_m\n1,a,1,10\n"); // a table short of one column
        QVERIFY(loadClassTableCsv(path).error().find("legend") == std::string::npos);
        QVERIFY(!loadClassTableCsv(folder.filePath("missing.csv").toStdString()).ok());
    }
};

QTEST_GUILESS_MAIN(ClassTablesTest)
#include "test_class_tables.moc"
