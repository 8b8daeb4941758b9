#include "io/internal/ClassTablePresets.hpp"

#include <algorithm>
#include <cmath>

namespace mcpp::io::internal {

// Defaults for a generic wheeled ground robot that senses a swath of FOV metres (its footprint side):
//
//   terrain                          speed (m/s)  FOV (m)  passable
//   paved road                       2.0          20       yes
//   bare ground, sand, sparse cover  1.2 - 1.8    20       yes
//   grassland, pasture, lichen       1.2 - 1.5    10 - 20  yes
//   cropland, green urban            0.8 - 1.0    10       yes   (rows and crops slow it and narrow the view)
//   shrubland, heath                 0.7 - 1.0    10       yes
//   forest, orchards, vineyards      0.4 - 0.8    5        yes   (trees block both driving lines and view)
//   wetland, marsh, rice, bog        0.3          5        yes   (slow, soft ground)
//   built-up, industry, airports     0            -        no    (buildings, fences, traffic)
//   water, sea, lagoons, tidal flats 0            -        no
//   permanent snow, ice, glaciers    0            -        no
//   mangroves, salines               0            -        no
//
// FOVs are 5, 10 or 20 m so that maps mixing open and closed land cover need three quadtree levels.
// Impassable rows keep FOV 10 m; it is never used. Names and colours follow each product's legend
// (tests/data/legends, the rasters' own palettes and the producers' documentation).

namespace {

constexpr bool blocked = false;
constexpr bool open = true;

LandCoverClass row(std::int32_t value, const char* name, std::uint32_t color, double speed, double fov,
                   bool passable) {
    return LandCoverClass{value, name, color, passable ? speed : 0.0, fov, passable};
}

std::uint32_t colorFromHsl(double hue, double saturation, double lightness) {
    const double chroma = (1.0 - std::abs(2.0 * lightness - 1.0)) * saturation;
    const double sector = hue / 60.0;
    const double second = chroma * (1.0 - std::abs(std::fmod(sector, 2.0) - 1.0));
    double red = 0.0;
    double green = 0.0;
    double blue = 0.0;
    switch (static_cast<int>(sector) % 6) {
    case 0:
        red = chroma;
        green = second;
        break;
    case 1:
        red = second;
        green = chroma;
        break;
    case 2:
        green = chroma;
        blue = second;
        break;
    case 3:
        green = second;
        blue = chroma;
        break;
    case 4:
        red = second;
        blue = chroma;
        break;
    default:
        red = chroma;
        blue = second;
        break;
    }
    const double base = lightness - chroma / 2.0;
    const auto channel = [base](double part) {
        return static_cast<std::uint32_t>(std::lround(std::clamp(part + base, 0.0, 1.0) * 255.0));
    };
    return (channel(red) << 16U) | (channel(green) << 8U) | channel(blue);
}

LandCoverClass wall(std::int32_t value, const char* name, std::uint32_t color) {
    return LandCoverClass{value, name, color, 0.0, 10.0, blocked};
}

std::vector<LandCoverClass> esaWorldCover() {
    return {
        row(10, "Tree cover", 0x006400, 0.5, 5, open),
        row(20, "Shrubland", 0xffbb22, 0.8, 10, open),
        row(30, "Grassland", 0xffff4c, 1.5, 20, open),
        row(40, "Cropland", 0xf096ff, 1.0, 10, open),
        wall(50, "Built-up", 0xfa0000),
        row(60, "Bare/sparse vegetation", 0xb4b4b4, 1.5, 20, open),
        wall(70, "Snow and ice", 0xf0f0f0),
        wall(80, "Permanent water bodies", 0x0064c8),
        row(90, "Herbaceous wetland", 0x0096a0, 0.3, 5, open),
        wall(95, "Mangroves", 0x00cf75),
        row(100, "Moss and lichen", 0xfae6a0, 1.0, 20, open),
    };
}

std::vector<LandCoverClass> nlcd() {
    return {
        wall(11, "Open Water", 0x476ba1),
        wall(12, "Perennial Snow/Ice", 0xd1defa),
        row(21, "Developed, Open Space", 0xdecaca, 1.2, 10, open),
        row(22, "Developed, Low Intensity", 0xd99482, 0.5, 5, open),
        wall(23, "Developed, Medium Intensity", 0xee0000),
        wall(24, "Developed, High Intensity", 0xab0000),
        row(31, "Barren Land", 0xb3aea3, 1.5, 20, open),
        row(41, "Deciduous Forest", 0x68ab63, 0.5, 5, open),
        row(42, "Evergreen Forest", 0x1c6330, 0.5, 5, open),
        row(43, "Mixed Forest", 0xb5ca8f, 0.5, 5, open),
        row(51, "Dwarf Scrub", 0xaf963c, 1.0, 10, open),
        row(52, "Shrub/Scrub", 0xccba7d, 0.8, 10, open),
        row(71, "Grassland/Herbaceous", 0xe3e3c2, 1.5, 20, open),
        row(72, "Sedge/Herbaceous", 0xd1d182, 1.2, 10, open),
        row(73, "Lichens", 0xa3cc51, 1.0, 20, open),
        row(74, "Moss", 0x82ba9e, 1.0, 20, open),
        row(81, "Hay/Pasture", 0xdcd93d, 1.2, 10, open),
        row(82, "Cultivated Crops", 0xab7028, 1.0, 10, open),
        row(90, "Woody Wetlands", 0xbad9eb, 0.3, 5, open),
        row(95, "Emergent Herbaceous Wetlands", 0x70a3ba, 0.3, 5, open),
    };
}

// The eight NLCD groups of spDataLarge's nlcd.tif (its .aux.xml category names and palette).
std::vector<LandCoverClass> nlcdSimplified() {
    return {
        wall(1, "Water", 0x476ba0),
        wall(2, "Developed", 0xaa0000),
        row(3, "Barren", 0xb2ada3, 1.5, 20, open),
        row(4, "Forest", 0x68aa63, 0.5, 5, open),
        row(5, "Shrubland", 0xa58c30, 0.8, 10, open),
        row(6, "Herbaceous", 0xc9c977, 1.5, 20, open),
        row(7, "Cultivated", 0xdbd83d, 1.0, 10, open),
        row(8, "Wetlands", 0xbad8ea, 0.3, 5, open),
    };
}

struct CorineClass {
    std::int32_t gridCode;
    std::int32_t code;
    const char* name;
    std::uint32_t color;
    double speed;
    double fov;
    bool passable;
};

const std::vector<CorineClass>& corineClasses() {
    static const std::vector<CorineClass> classes = {
        {1, 111, "Continuous urban fabric", 0xe6004d, 0, 10, blocked},
        {2, 112, "Discontinuous urban fabric", 0xff0000, 0, 10, blocked},
        {3, 121, "Industrial or commercial units", 0xcc4df2, 0, 10, blocked},
        {4, 122, "Road and rail networks and associated land", 0xcc0000, 2.0, 20, open},
        {5, 123, "Port areas", 0xe6cccc, 0, 10, blocked},
        {6, 124, "Airports", 0xe6cce6, 0, 10, blocked},
        {7, 131, "Mineral extraction sites", 0xa600cc, 0.8, 10, open},
        {8, 132, "Dump sites", 0xa64d00, 0.5, 10, open},
        {9, 133, "Construction sites", 0xff4dff, 0.5, 10, open},
        {10, 141, "Green urban areas", 0xffa6ff, 1.0, 10, open},
        {11, 142, "Sport and leisure facilities", 0xffe6ff, 1.5, 20, open},
        {12, 211, "Non-irrigated arable land", 0xffffa8, 1.0, 10, open},
        {13, 212, "Permanently irrigated land", 0xffff00, 0.8, 10, open},
        {14, 213, "Rice fields", 0xe6e600, 0.3, 5, open},
        {15, 221, "Vineyards", 0xe68000, 0.8, 5, open},
        {16, 222, "Fruit trees and berry plantations", 0xf2a64d, 0.8, 5, open},
        {17, 223, "Olive groves", 0xe6a600, 0.8, 5, open},
        {18, 231, "Pastures", 0xe6e64d, 1.2, 20, open},
        {19, 241, "Annual crops associated with permanent crops", 0xffe6a6, 1.0, 10, open},
        {20, 242, "Complex cultivation patterns", 0xffe64d, 1.0, 10, open},
        {21, 243, "Land principally occupied by agriculture, with significant areas of natural vegetation",
         0xe6cc4d, 1.0, 10, open},
        {22, 244, "Agro-forestry areas", 0xf2cca6, 0.8, 10, open},
        {23, 311, "Broad-leaved forest", 0x80ff00, 0.5, 5, open},
        {24, 312, "Coniferous forest", 0x00a600, 0.5, 5, open},
        {25, 313, "Mixed forest", 0x4dff00, 0.5, 5, open},
        {26, 321, "Natural grasslands", 0xccf24d, 1.5, 20, open},
        {27, 322, "Moors and heathland", 0xa6ff80, 1.0, 10, open},
        {28, 323, "Sclerophyllous vegetation", 0xa6e64d, 0.8, 10, open},
        {29, 324, "Transitional woodland-shrub", 0xa6f200, 0.7, 5, open},
        {30, 331, "Beaches, dunes, sands", 0xe6e6e6, 1.0, 20, open},
        {31, 332, "Bare rocks", 0xcccccc, 0.8, 20, open},
        {32, 333, "Sparsely vegetated areas", 0xccffcc, 1.2, 20, open},
        {33, 334, "Burnt areas", 0x000000, 1.0, 10, open},
        {34, 335, "Glaciers and perpetual snow", 0xa6e6cc, 0, 10, blocked},
        {35, 411, "Inland marshes", 0xa6a6ff, 0.3, 5, open},
        {36, 412, "Peat bogs", 0x4d4dff, 0.3, 5, open},
        {37, 421, "Salt marshes", 0xccccff, 0.3, 5, open},
        {38, 422, "Salines", 0xe6e6ff, 0, 10, blocked},
        {39, 423, "Intertidal flats", 0xa6a6e6, 0, 10, blocked},
        {40, 511, "Water courses", 0x00ccf2, 0, 10, blocked},
        {41, 512, "Water bodies", 0x80f2e6, 0, 10, blocked},
        {42, 521, "Coastal lagoons", 0x00ffa6, 0, 10, blocked},
        {43, 522, "Estuaries", 0xa6ffe6, 0, 10, blocked},
        {44, 523, "Sea and ocean", 0xe6f2ff, 0, 10, blocked},
    };
    return classes;
}

std::vector<LandCoverClass> corine(bool gridCodes) {
    std::vector<LandCoverClass> classes;
    for (const CorineClass& entry : corineClasses()) {
        classes.push_back(row(gridCodes ? entry.gridCode : entry.code, entry.name, entry.color, entry.speed,
                              entry.fov, entry.passable));
    }
    return classes;
}

// Natural Resources Canada, Land Cover of Canada 2015 (NALCMS legend, colours of the NALCMS palette).
std::vector<LandCoverClass> canadaLandCover() {
    return {
        row(1, "Temperate or sub-polar needleleaf forest", 0x003d00, 0.5, 5, open),
        row(2, "Sub-polar taiga needleleaf forest", 0x949c70, 0.6, 5, open),
        row(5, "Temperate or sub-polar broadleaf deciduous forest", 0x148c3d, 0.5, 5, open),
        row(6, "Mixed forest", 0x5c752b, 0.5, 5, open),
        row(8, "Temperate or sub-polar shrubland", 0xb38a33, 0.8, 10, open),
        row(10, "Temperate or sub-polar grassland", 0xe1cf8a, 1.5, 20, open),
        row(11, "Sub-polar or polar shrubland-lichen-moss", 0x9c7554, 0.8, 10, open),
        row(12, "Sub-polar or polar grassland-lichen-moss", 0xbad48f, 1.2, 20, open),
        row(13, "Sub-polar or polar barren-lichen-moss", 0x408a70, 1.2, 20, open),
        row(14, "Wetland", 0x6ba38a, 0.3, 5, open),
        row(15, "Cropland", 0xe6ae66, 1.0, 10, open),
        row(16, "Barren lands", 0xa8abae, 1.5, 20, open),
        wall(17, "Urban", 0xdc2126),
        wall(18, "Water", 0x4c70a3),
        wall(19, "Snow and Ice", 0xfffaff),
    };
}

// Copernicus Global Land Service, Land Cover 100 m, discrete classification.
std::vector<LandCoverClass> copernicusGlobalLandCover() {
    return {
        wall(0, "Unknown", 0x282828),
        row(20, "Shrubs", 0xffbb22, 0.8, 10, open),
        row(30, "Herbaceous vegetation", 0xffff4c, 1.5, 20, open),
        row(40, "Cultivated and managed vegetation / agriculture", 0xf096ff, 1.0, 10, open),
        wall(50, "Urban / built up", 0xfa0000),
        row(60, "Bare / sparse vegetation", 0xb4b4b4, 1.5, 20, open),
        wall(70, "Snow and ice", 0xf0f0f0),
        wall(80, "Permanent water bodies", 0x0032c8),
        row(90, "Herbaceous wetland", 0x0096a0, 0.3, 5, open),
        row(100, "Moss and lichen", 0xfae6a0, 1.0, 20, open),
        row(111, "Closed forest, evergreen needle leaf", 0x58481f, 0.4, 5, open),
        row(112, "Closed forest, evergreen broad leaf", 0x009900, 0.4, 5, open),
        row(113, "Closed forest, deciduous needle leaf", 0x70663e, 0.4, 5, open),
        row(114, "Closed forest, deciduous broad leaf", 0x00cc00, 0.4, 5, open),
        row(115, "Closed forest, mixed", 0x4e751f, 0.4, 5, open),
        row(116, "Closed forest, unknown", 0x007800, 0.4, 5, open),
        row(121, "Open forest, evergreen needle leaf", 0x666000, 0.6, 5, open),
        row(122, "Open forest, evergreen broad leaf", 0x8db400, 0.6, 5, open),
        row(123, "Open forest, deciduous needle leaf", 0x8d7400, 0.6, 5, open),
        row(124, "Open forest, deciduous broad leaf", 0xa0dc00, 0.6, 5, open),
        row(125, "Open forest, mixed", 0x929900, 0.6, 5, open),
        row(126, "Open forest, unknown", 0x648c00, 0.6, 5, open),
        wall(200, "Open sea", 0x000080),
    };
}

// The six classes of the multi-robot coverage paper's maps. FOVs 5, 10 and 20 m give three quadtree levels.
std::vector<LandCoverClass> paper() {
    return {
        row(1, "farm", 0xe8c547, 1.0, 10, open),      row(2, "road", 0x7a7a7a, 2.0, 20, open),
        row(3, "grass", 0x8fd16b, 1.5, 10, open),     row(4, "wood", 0x2e7d32, 0.5, 5, open),
        row(5, "bare land", 0xc8b496, 1.8, 20, open), row(6, "gobi", 0xd2a05a, 1.2, 20, open),
    };
}

} // namespace

const std::vector<PresetDefinition>& presetDefinitions() {
    using enum CodeEvidence;
    const std::vector<std::string> europe = {"etrs89", "laea", "lv95", "ch1903", "lambert-93", "europe"};
    static const std::vector<PresetDefinition> presets = {
        {"esa-worldcover",
         "ESA WorldCover 10 m (2020, 2021), 11 classes",
         esaWorldCover(),
         "ESA WorldCover",
         {"worldcover"},
         Alone,
         {}},
        {"nlcd",
         "US National Land Cover Database, full two-digit codes",
         nlcd(),
         "the National Land Cover Database (NLCD)",
         {"nlcd", "national land cover database"},
         Alone,
         {}},
        {"nlcd-simplified",
         "NLCD simplified to 8 groups (1 water ... 8 wetlands)",
         nlcdSimplified(),
         "NLCD simplified to 8 groups",
         {},
         Never,
         {}},
        {"corine",
         "CORINE Land Cover, three-digit codes (111-523)",
         corine(false),
         "CORINE Land Cover",
         {"corine", "clc", "code_18", "code_12", "code_06", "code_00"},
         Alone,
         {}},
        {"corine-grid",
         "CORINE Land Cover raster grid codes (1-44)",
         corine(true),
         "CORINE Land Cover (raster grid codes)",
         {"corine", "clc"},
         WithCrs,
         europe},
        {"canada-landcover",
         "Land Cover of Canada 2015 (NRCan, NALCMS legend)",
         canadaLandCover(),
         "Land Cover of Canada (NALCMS legend)",
         {"nalcms", "land cover of canada", "nrcan"},
         WithCrs,
         {"canada", "csrs"}},
        {"copernicus-glc100",
         "Copernicus Global Land Cover 100 m, discrete classification",
         copernicusGlobalLandCover(),
         "Copernicus Global Land Cover",
         {"lc100", "cgls", "copernicus global land"},
         Alone,
         {}},
        {"cropland-data-layer",
         "USDA Cropland Data Layer (CropScape codes)",
         croplandDataLayerClasses(),
         "the Cropland Data Layer",
         {"cropland data layer", "cropscape", "cdl"},
         WithCrs,
         {"conus", "albers"}},
        {"paper",
         "The paper's six classes: farm, road, grass, wood, bare land, gobi (1-6)",
         paper(),
         "the paper's six classes",
         {},
         Never,
         {}},
    };
    return presets;
}

LandCoverClass genericClass(std::int32_t value, std::size_t index) {
    // Hues a golden angle apart, 19 to a round; each round lighter or darker and turned a little, so that
    // even 55 classes keep every two colours apart and neighbours in the table far apart.
    constexpr std::size_t kPerRound = 19;
    const std::size_t round = (index / kPerRound) % 3;
    const double hue = std::fmod(
        static_cast<double>(index % kPerRound) * 137.508 + 40.0 * static_cast<double>(round), 360.0);
    const double lightness[] = {0.55, 0.40, 0.70};
    const double saturation[] = {0.65, 0.75, 0.55};
    const std::size_t step = round;
    return LandCoverClass{value,
                          "Class " + std::to_string(value),
                          colorFromHsl(hue, saturation[step], lightness[step]),
                          1.0,
                          10.0,
                          true};
}

} // namespace mcpp::io::internal
