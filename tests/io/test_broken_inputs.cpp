// Broken files give one clear line naming the file (and the JSON path for missions), never a crash.

#include "BrokenMissions.hpp"
#include "io/ClassTableSources.hpp"
#include "io/LoadedRaster.hpp"
#include "io/Mission.hpp"
#include "tests/support/TestData.hpp"

#include <QTemporaryDir>
#include <QTest>
#include <filesystem>
#include <fstream>
#include <gdal_priv.h>

using namespace mcpp;
using namespace mcpp::io;
using mcpp::test::MissionMutation;
using mcpp::test::missionMutations;
using mcpp::test::missionVersion2Mutations;
using mcpp::test::testDataPath;
using mcpp::test::validMission;
using mcpp::test::validMissionVersion2;

namespace {

void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream file(path, std::ios::binary);
    file << bytes;
}

std::string readBytes(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

void expectOneLineError(const std::string& error, const std::string& mustContain) {
    QVERIFY2(!error.empty(), "empty error");
    QVERIFY2(error.find('\n') == std::string::npos, error.c_str());
    QVERIFY2(error.find(mustContain) != std::string::npos,
             (error + "  [expected: " + mustContain + "]").c_str());
}

} // namespace

class BrokenInputsTest : public QObject {
    Q_OBJECT

  private:
    QTemporaryDir folder_;
    std::string file(const char* name) const { return folder_.filePath(name).toStdString(); }

  private slots:
    void truncatedTiff() {
        const std::string path = file("truncated.tif");
        writeBytes(path, readBytes(testDataPath("landcover/nlcd.tif")).substr(0, 4000));
        auto loaded = loadLandCoverRaster(path);
        QVERIFY(!loaded.ok());
        expectOneLineError(loaded.error(), path);
    }

    void textFileNamedTif() {
        const std::string path = file("notes.tif");
        writeBytes(path, "this is not a raster\n");
        auto loaded = loadLandCoverRaster(path);
        QVERIFY(!loaded.ok());
        expectOneLineError(loaded.error(), path);
        expectOneLineError(loaded.error(), "not a raster");
    }

    void emptyFile() {
        const std::string path = file("empty.tif");
        writeBytes(path, "");
        auto loaded = loadLandCoverRaster(path);
        QVERIFY(!loaded.ok());
        expectOneLineError(loaded.error(), "empty");
    }

    void unreadablePaths() {
        auto missing = loadLandCoverRaster(file("nowhere/map.tif"));
        QVERIFY(!missing.ok());
        expectOneLineError(missing.error(), "not found");
        QVERIFY2(missing.error().find("looked for") == std::string::npos, missing.error().c_str());
        // A relative path is read from the working folder: the message says which file that was.
        const std::filesystem::path here = std::filesystem::current_path();
        std::filesystem::current_path(folder_.path().toStdString());
        auto relative = loadLandCoverRaster("nowhere/map.tif");
        std::filesystem::current_path(here);
        QVERIFY(!relative.ok());
        expectOneLineError(relative.error(),
                           "nowhere/map.tif: file not found (looked for " +
                               (std::filesystem::path(folder_.path().toStdString()) / "nowhere/map.tif")
                                   .lexically_normal()
                                   .string() +
                               ")");
        auto folder = loadLandCoverRaster(folder_.path().toStdString());
        QVERIFY(!folder.ok());
        expectOneLineError(folder.error(), "folder");
        const std::string locked = file("locked.tif");
        std::filesystem::copy_file(testDataPath("landcover/nrcan_landcover2015_example.tif"), locked);
        std::filesystem::permissions(locked, std::filesystem::perms::none);
        if (std::ifstream(locked).good())
            QSKIP("running as root: permissions do not stop reading");
        auto denied = loadLandCoverRaster(locked);
        QVERIFY(!denied.ok());
        expectOneLineError(denied.error(), "cannot be read");
    }

    void rgbImage() {
        const std::string path = file("photo.tif");
        GDALAllRegister();
        GDALDataset* dataset = GetGDALDriverManager()->GetDriverByName("GTiff")->Create(path.c_str(), 8, 8, 3,
                                                                                        GDT_Byte, nullptr);
        QVERIFY(dataset != nullptr);
        const GDALColorInterp colours[3] = {GCI_RedBand, GCI_GreenBand, GCI_BlueBand};
        for (int band = 1; band <= 3; ++band)
            dataset->GetRasterBand(band)->SetColorInterpretation(colours[band - 1]);
        GDALClose(dataset);
        auto loaded = loadLandCoverRaster(path);
        QVERIFY(!loaded.ok());
        expectOneLineError(loaded.error(), "RGB");
        RasterLoadOptions second;
        second.band = 2;
        QVERIFY(!loadLandCoverRaster(path, second).ok());
    }

    void rotatedGeotransform() {
        const std::string path = file("rotated.tif");
        GDALDataset* dataset = GetGDALDriverManager()->GetDriverByName("GTiff")->Create(path.c_str(), 4, 4, 1,
                                                                                        GDT_Byte, nullptr);
        double transform[6] = {0, 10, 2, 0, 2, -10};
        dataset->SetGeoTransform(transform);
        GDALClose(dataset);
        auto loaded = loadLandCoverRaster(path);
        QVERIFY(!loaded.ok());
        expectOneLineError(loaded.error(), "rotated");
    }

    void validMissionLoads() {
        const std::string path = file("valid.json");
        writeBytes(path, validMission);
        auto loaded = loadMission(path);
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().c_str());
        writeBytes(path, validMissionVersion2);
        auto second = loadMission(path);
        QVERIFY2(second.ok(), second.ok() ? "" : second.error().c_str());
        QCOMPARE(second.value().planner.parameters.real("purity_tolerance"), 0.02);
        QCOMPARE(second.value().planner.parameters.boolean("closed_tour"), false);
        QCOMPARE(second.value().planner.parameters.boolean("snap_starts_to_free_cells"),
                 false); // the default
    }

    void missionWithAWrongTypeInEveryField_data() {
        QTest::addColumn<QString>("from");
        QTest::addColumn<QString>("to");
        QTest::addColumn<QString>("path");
        QTest::addColumn<int>("version");
        for (const MissionMutation& mutation : missionMutations()) {
            QTest::newRow(mutation.name)
                << QString(mutation.from) << QString(mutation.to) << QString(mutation.path) << 1;
        }
        for (const MissionMutation& mutation : missionVersion2Mutations()) {
            QTest::newRow(mutation.name)
                << QString(mutation.from) << QString(mutation.to) << QString(mutation.path) << 2;
        }
    }

    void missionWithAWrongTypeInEveryField() {
        QFETCH(QString, from);
        QFETCH(QString, to);
        QFETCH(QString, path);
        QFETCH(int, version);
        std::string text = version == 1 ? validMission : validMissionVersion2;
        const std::string original = from.toStdString();
        const auto position = text.find(original);
        QVERIFY2(position != std::string::npos, qPrintable(from));
        text.replace(position, original.size(), to.toStdString());
        const std::string file = this->file("broken.json");
        writeBytes(file, text);
        auto loaded = loadMission(file);
        QVERIFY2(!loaded.ok(), qPrintable(to));
        expectOneLineError(loaded.error(), file + ": " + path.toStdString() + ":");
    }

    void missionThatIsNotJson() {
        const std::string path = file("garbage.json");
        writeBytes(path, "{\n  \"format\": \"mcpp-mission\",\n  \"version\": 1,,\n}");
        auto loaded = loadMission(path);
        QVERIFY(!loaded.ok());
        expectOneLineError(loaded.error(), "line 3");
        writeBytes(path, "");
        QVERIFY(!loadMission(path).ok());
        writeBytes(path, "[1, 2]");
        QVERIFY(!loadMission(path).ok());
        QVERIFY(!loadMission(file("absent.json")).ok());
        writeBytes(path, "{\"format\": \"mcpp-mission\", \"version\": 1, \"raster\": {\"path\": \"a.tif\"}}");
        auto noRobots = loadMission(path);
        QVERIFY(!noRobots.ok());
        expectOneLineError(noRobots.error(), "robots: missing");
    }

    void brokenLegendFilesBesideARasterAreOnlyWarnings() {
        const std::filesystem::path folder = folder_.filePath("legend").toStdString();
        std::filesystem::create_directories(folder);
        std::filesystem::copy_file(testDataPath("landcover/nrcan_landcover2015_example.tif"),
                                   folder / "map.tif");
        writeBytes((folder / "map.qml").string(), "<qgis><renderer-v2><categories><category value=");
        auto loaded = loadLandCoverRaster((folder / "map.tif").string());
        QVERIFY(loaded.ok());
        QVERIFY(!loaded.value().warnings.empty());
        QVERIFY(loaded.value().legend.empty());
        // A good CSV legend beside it is used.
        std::filesystem::remove(folder / "map.qml");
        std::filesystem::copy_file(testDataPath("legends/nrcan_canada_landcover_2015.csv"),
                                   folder / "map.csv");
        auto withCsv = loadLandCoverRaster((folder / "map.tif").string());
        QVERIFY(withCsv.ok());
        QCOMPARE(withCsv.value().legendSource, std::string("csv"));
        QCOMPARE(withCsv.value().legend.size(), std::size_t{15});
    }
};

QTEST_GUILESS_MAIN(BrokenInputsTest)
#include "test_broken_inputs.moc"
