// The files of the bad-input suite: a small valid map and its broken variants, made with GDAL so that
// every case is a real file a user could have.
#include "BadInputCases.hpp"

#include <QDir>
#include <QFile>
#include <cstdint>
#include <functional>
#include <gdal_priv.h>
#include <ogr_spatialref.h>
#include <random>
#include <vector>

namespace mcpp::test {
namespace {

constexpr int kSize = 40;       // pixels a side
constexpr double kPixel = 10.0; // metres
constexpr double kWest = 500000.0;
constexpr double kNorth = 5000400.0;

// The valid map: grass, a forest block in the north-east, a lake in the south-east, a nodata corner.
double goodValue(int column, int row) {
    if (column < 5 && row >= 35)
        return 255;
    if (column >= 30 && row < 10)
        return 2;
    if (column >= 30 && row >= 30)
        return 3;
    return 1;
}

struct RasterSpec {
    GDALDataType type = GDT_Byte;
    int bands = 1;
    std::function<double(int, int)> value = goodValue;
    bool georeferenced = true;
    std::vector<double> transform{kWest, kPixel, 0, kNorth, 0, -kPixel};
    int epsg = 32633; // 0: no CRS
    bool nodata = true;
    // Pixels the mask band (a .msk side file) marks invalid; none when empty.
    std::function<bool(int, int)> masked;
};

QString writeRaster(const QString& path, const RasterSpec& spec) {
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
    GDALDataset* dataset =
        driver->Create(path.toUtf8().constData(), kSize, kSize, spec.bands, spec.type, nullptr);
    if (dataset == nullptr)
        return QStringLiteral("cannot create ") + path;
    if (spec.georeferenced) {
        std::vector<double> transform = spec.transform;
        dataset->SetGeoTransform(transform.data());
    }
    if (spec.epsg != 0) {
        OGRSpatialReference crs;
        crs.importFromEPSG(spec.epsg);
        dataset->SetSpatialRef(&crs);
    }
    std::vector<double> pixels(static_cast<std::size_t>(kSize) * kSize);
    for (int row = 0; row < kSize; ++row)
        for (int column = 0; column < kSize; ++column)
            pixels[static_cast<std::size_t>(row) * kSize + static_cast<std::size_t>(column)] =
                spec.value(column, row);
    const GDALColorInterp colours[3] = {GCI_RedBand, GCI_GreenBand, GCI_BlueBand};
    for (int band = 1; band <= spec.bands; ++band) {
        GDALRasterBand* raster = dataset->GetRasterBand(band);
        if (spec.nodata && spec.type == GDT_Byte)
            raster->SetNoDataValue(255);
        if (spec.bands == 3)
            raster->SetColorInterpretation(colours[band - 1]);
        if (raster->RasterIO(GF_Write, 0, 0, kSize, kSize, pixels.data(), kSize, kSize, GDT_Float64, 0, 0) !=
            CE_None) {
            GDALClose(dataset);
            return QStringLiteral("cannot write ") + path;
        }
    }
    if (spec.masked) {
        if (dataset->CreateMaskBand(GMF_PER_DATASET) != CE_None) {
            GDALClose(dataset);
            return QStringLiteral("cannot create the mask of ") + path;
        }
        std::vector<std::uint8_t> mask(pixels.size());
        for (int row = 0; row < kSize; ++row)
            for (int column = 0; column < kSize; ++column)
                mask[static_cast<std::size_t>(row) * kSize + static_cast<std::size_t>(column)] =
                    spec.masked(column, row) ? 0 : 255;
        GDALRasterBand* maskBand = dataset->GetRasterBand(1)->GetMaskBand();
        if (maskBand->RasterIO(GF_Write, 0, 0, kSize, kSize, mask.data(), kSize, kSize, GDT_Byte, 0, 0) !=
            CE_None) {
            GDALClose(dataset);
            return QStringLiteral("cannot write the mask of ") + path;
        }
    }
    GDALClose(dataset);
    return {};
}

QString writeFile(const QString& path, const QByteArray& bytes) {
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(bytes) != bytes.size())
        return QStringLiteral("cannot write ") + path;
    return {};
}

QByteArray randomBytes(int count, unsigned seed) {
    std::mt19937 random(seed);
    QByteArray bytes(count, '\0');
    for (char& byte : bytes)
        byte = static_cast<char>(random() & 0xFF);
    return bytes;
}

QByteArray classTable(const QByteArray& grassRow) {
    return "value,name,speed_mps,fov_m,passable\n" + grassRow + "\n2,Forest,1,10,true\n3,Water,0,10,false\n";
}

// A mission over good.tif; `robots` and `extra` are spliced into its JSON text.
QByteArray mission(const QByteArray& robots, const QByteArray& version = "2",
                   const QByteArray& raster = "good.tif", const QByteArray& grassSpeed = "2") {
    return R"({"format": "mcpp-mission", "version": )" + version + R"(,
 "raster": {"path": ")" +
           raster + R"(", "band": 1},
 "classes": {"table": [
   {"value": 1, "name": "Grass", "speed_mps": )" +
           grassSpeed + R"(, "fov_m": 20, "passable": true},
   {"value": 2, "name": "Forest", "speed_mps": 1, "fov_m": 10, "passable": true},
   {"value": 3, "name": "Water", "speed_mps": 0, "fov_m": 10, "passable": false}]},
 "robots": [)" +
           robots + R"(],
 "planner": {"name": "mcpp-mlct"}}
)";
}

const QByteArray kTwoRobots = R"({"name": "north", "start": [500055, 5000345]},
            {"name": "south", "start": [500155, 5000195]})";

QString writeRasters(const QDir& dir) {
    const auto path = [&](const char* name) { return dir.filePath(QString::fromLatin1(name)); };
    QString error = writeRaster(path("good.tif"), {});
    RasterSpec fractional;
    fractional.type = GDT_Float32;
    fractional.nodata = false;
    fractional.value = [](int, int) { return 1.5; };
    RasterSpec whole = fractional;
    whole.value = [](int column, int row) {
        return goodValue(column, row) == 255 ? 1 : goodValue(column, row);
    };
    RasterSpec rgb;
    rgb.bands = 3;
    RasterSpec rotated;
    rotated.transform = {kWest, kPixel, 2, kNorth, 2, -kPixel};
    RasterSpec ungeoreferenced;
    ungeoreferenced.georeferenced = false;
    ungeoreferenced.epsg = 0;
    RasterSpec noCrs;
    noCrs.epsg = 0;
    RasterSpec masked;
    masked.masked = [](int column, int row) { return column < 10 && row < 10; };
    RasterSpec allNodata;
    allNodata.value = [](int, int) { return 255; };
    RasterSpec allWater;
    allWater.value = [](int, int) { return 3; };
    RasterSpec huge;
    huge.type = GDT_Float64;
    huge.nodata = false;
    huge.value = [](int, int) { return 1e12; };
    RasterSpec geocentric;
    geocentric.epsg = 4978;
    RasterSpec eastToWest;
    eastToWest.transform = {kWest, -kPixel, 0, kNorth, 0, -kPixel};
    RasterSpec degrees; // 40 x 40 pixels of 0.0001 degrees from 10 E, 45.004 N
    degrees.epsg = 4326;
    degrees.transform = {10.0, 0.0001, 0, 45.004, 0, -0.0001};
    const std::vector<std::pair<const char*, RasterSpec>> variants{{"float-fraction.tif", fractional},
                                                                   {"degrees.tif", degrees},
                                                                   {"float-whole.tif", whole},
                                                                   {"rgb.tif", rgb},
                                                                   {"rotated.tif", rotated},
                                                                   {"ungeoreferenced.tif", ungeoreferenced},
                                                                   {"no-crs.tif", noCrs},
                                                                   {"masked.tif", masked},
                                                                   {"all-nodata.tif", allNodata},
                                                                   {"all-water.tif", allWater},
                                                                   {"huge-value.tif", huge},
                                                                   {"geocentric.tif", geocentric},
                                                                   {"east-to-west.tif", eastToWest}};
    for (const auto& [name, spec] : variants)
        if (error.isEmpty())
            error = writeRaster(path(name), spec);
    if (!error.isEmpty())
        return error;
    QFile good(path("good.tif"));
    if (!good.open(QIODevice::ReadOnly))
        return QStringLiteral("cannot read good.tif back");
    const QByteArray goodBytes = good.readAll();
    for (const QString& written :
         {writeFile(path("truncated.tif"), goodBytes.left(goodBytes.size() / 2)),
          writeFile(path("empty.tif"), {}), writeFile(path("random.tif"), randomBytes(4096, 7)),
          writeFile(path("text.tif"), "this is a note, not a raster\n")})
        if (!written.isEmpty())
            return written;
    return dir.mkpath(QStringLiteral("folder.tif")) ? QString() : QStringLiteral("cannot make folder.tif");
}

QString writeClassTables(const QDir& dir) {
    const std::vector<std::pair<const char*, QByteArray>> tables{
        {"good.csv", classTable("1,Grass,2,20,true")},
        {"bad-header.csv", "value,name,speed,fov_m,passable\n1,Grass,2,20,true\n"},
        {"negative-speed.csv", classTable("1,Grass,-1,20,true")},
        {"zero-speed.csv", classTable("1,Grass,0,20,true")},
        {"nan-speed.csv", classTable("1,Grass,nan,20,true")},
        {"absurd-speed.csv", classTable("1,Grass,1e9,20,true")},
        {"zero-fov.csv", classTable("1,Grass,2,0,true")},
        {"detection-above-one.csv",
         "value,name,speed_mps,fov_m,passable,detection_probability\n1,Grass,2,20,true,1.2\n"},
        {"negative-fov.csv", classTable("1,Grass,2,-5,true")},
        {"nan-fov.csv", classTable("1,Grass,2,nan,true")},
        {"absurd-fov.csv", classTable("1,Grass,2,1e12,true")},
        {"tiny-fov.csv", classTable("1,Grass,2,0.0001,true")},
        {"duplicate.csv", classTable("1,Grass,2,20,true\n1,Meadow,2,20,true")},
        {"lacks-forest.csv", "value,name,speed_mps,fov_m,passable\n1,Grass,2,20,true\n3,Water,0,10,false\n"},
        {"empty.csv", ""},
        {"header-only.csv", "value,name,speed_mps,fov_m,passable\n"},
        {"bad-passable.csv", classTable("1,Grass,2,20,maybe")},
        {"short-row.csv", classTable("1,Grass,2")},
        {"binary.csv", randomBytes(2048, 11)},
        {"text-value.csv", classTable("one,Grass,2,20,true")}};
    for (const auto& [name, text] : tables)
        if (QString error = writeFile(dir.filePath(QString::fromLatin1(name)), text); !error.isEmpty())
            return error;
    return {};
}

QString writeMissions(const QDir& dir) {
    const QByteArray good = mission(kTwoRobots);
    QByteArray wrongFormat = good;
    wrongFormat.replace("mcpp-mission", "qgis-project");
    QByteArray wrongType = mission(kTwoRobots, "2", "good.tif", "\"fast\"");
    const std::vector<std::pair<const char*, QByteArray>> missions{
        {"good.json", good},
        {"truncated.json", good.left(good.size() / 2)},
        {"binary.json", randomBytes(3000, 13)},
        {"empty.json", ""},
        {"future.json", mission(kTwoRobots, "99")},
        {"wrong-format.json", wrongFormat},
        {"no-start.json", mission(R"({"name": "lost"})")},
        {"text-start.json", mission(R"({"name": "typo", "start": ["500055", "north"]})")},
        {"raster-missing.json", mission(kTwoRobots, "2", "absent.tif")},
        {"wrong-type.json", wrongType},
        {"robot-on-water.json", mission(R"({"name": "swimmer", "start": [500355, 5000045]})")},
        {"array.json", "[1, 2, 3]\n"}};
    for (const auto& [name, text] : missions)
        if (QString error = writeFile(dir.filePath(QString::fromLatin1(name)), text); !error.isEmpty())
            return error;
    if (!dir.mkpath(QStringLiteral("folder.json")))
        return QStringLiteral("cannot make folder.json");
    return writeFile(dir.filePath(QStringLiteral("a-file")), "not a folder\n");
}

} // namespace

QString writeBadInputFixtures(const QString& folder) {
    GDALAllRegister();
    const QDir dir(folder);
    for (const auto& write : {writeRasters, writeClassTables, writeMissions})
        if (QString error = write(dir); !error.isEmpty())
            return error;
    return {};
}

QStringList expandArguments(const BadInputCase& badInput, const QString& folder, const QString& out) {
    QStringList expanded;
    for (QString argument : badInput.arguments)
        expanded << argument.replace(QStringLiteral("{dir}"), folder).replace(QStringLiteral("{out}"), out);
    return expanded;
}

} // namespace mcpp::test
