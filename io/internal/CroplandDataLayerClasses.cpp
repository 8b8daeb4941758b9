#include "io/internal/ClassTablePresets.hpp"

namespace mcpp::io::internal {

// USDA NASS Cropland Data Layer codes, names and colours (the CropScape legend and palette; a file's own
// palette still wins on opening, these recognise it and colour a file without one). Field crops are driven
// between rows like any cropland; orchards, vineyards and tree crops like the other products' fruit trees;
// water, ice, built-up land of medium and high intensity, aquaculture and clouds (no data) are walls, as in
// every preset.

namespace {

enum class Group { FieldCrop, TreeCrop, Grass, Shrub, Forest, Wetland, Barren, OpenDeveloped, Wall };

struct CroplandCode {
    std::int32_t value;
    const char* name;
    std::uint32_t color; // the CropScape palette's
    Group group;
};

const std::vector<CroplandCode>& croplandCodes() {
    static const std::vector<CroplandCode> codes = {
        {1, "Corn", 0xffd300, Group::FieldCrop},
        {2, "Cotton", 0xff2626, Group::FieldCrop},
        {3, "Rice", 0x00a8e4, Group::Wetland},
        {4, "Sorghum", 0xff9e0b, Group::FieldCrop},
        {5, "Soybeans", 0x267000, Group::FieldCrop},
        {6, "Sunflower", 0xffff00, Group::FieldCrop},
        {10, "Peanuts", 0x70a500, Group::FieldCrop},
        {11, "Tobacco", 0x00af4b, Group::FieldCrop},
        {12, "Sweet Corn", 0xdda50b, Group::FieldCrop},
        {13, "Pop or Orn Corn", 0xdda50b, Group::FieldCrop},
        {14, "Mint", 0x7ed3ff, Group::FieldCrop},
        {21, "Barley", 0xe2007c, Group::FieldCrop},
        {22, "Durum Wheat", 0x896254, Group::FieldCrop},
        {23, "Spring Wheat", 0xd8b56b, Group::FieldCrop},
        {24, "Winter Wheat", 0xa57000, Group::FieldCrop},
        {25, "Other Small Grains", 0xd69ebc, Group::FieldCrop},
        {26, "Dbl Crop WinWht/Soybeans", 0x707000, Group::FieldCrop},
        {27, "Rye", 0xac007c, Group::FieldCrop},
        {28, "Oats", 0xa05889, Group::FieldCrop},
        {29, "Millet", 0x700049, Group::FieldCrop},
        {30, "Speltz", 0xd69ebc, Group::FieldCrop},
        {31, "Canola", 0xd1ff00, Group::FieldCrop},
        {32, "Flaxseed", 0x7e99ff, Group::FieldCrop},
        {33, "Safflower", 0xd6d600, Group::FieldCrop},
        {34, "Rape Seed", 0xd1ff00, Group::FieldCrop},
        {35, "Mustard", 0x00af4b, Group::FieldCrop},
        {36, "Alfalfa", 0xffa8e3, Group::FieldCrop},
        {37, "Other Hay/Non Alfalfa", 0xa5f58d, Group::Grass},
        {38, "Camelina", 0x00af4b, Group::FieldCrop},
        {39, "Buckwheat", 0xd69ebc, Group::FieldCrop},
        {41, "Sugarbeets", 0xa800e2, Group::FieldCrop},
        {42, "Dry Beans", 0xa50000, Group::FieldCrop},
        {43, "Potatoes", 0x702600, Group::FieldCrop},
        {44, "Other Crops", 0x00af4b, Group::FieldCrop},
        {45, "Sugarcane", 0xaf7cff, Group::FieldCrop},
        {46, "Sweet Potatoes", 0x702600, Group::FieldCrop},
        {47, "Misc Vegs & Fruits", 0xff6666, Group::FieldCrop},
        {48, "Watermelons", 0xff6666, Group::FieldCrop},
        {49, "Onions", 0xffcc66, Group::FieldCrop},
        {50, "Cucumbers", 0xff6666, Group::FieldCrop},
        {51, "Chick Peas", 0x00af4b, Group::FieldCrop},
        {52, "Lentils", 0x00deaf, Group::FieldCrop},
        {53, "Peas", 0x54ff00, Group::FieldCrop},
        {54, "Tomatoes", 0xf2a277, Group::FieldCrop},
        {55, "Caneberries", 0xff6666, Group::TreeCrop},
        {56, "Hops", 0x00af4b, Group::TreeCrop},
        {57, "Herbs", 0x7ed3ff, Group::FieldCrop},
        {58, "Clover/Wildflowers", 0xe8beff, Group::Grass},
        {59, "Sod/Grass Seed", 0xafffde, Group::Grass},
        {60, "Switchgrass", 0x00af4b, Group::Grass},
        {61, "Fallow/Idle Cropland", 0xbfbf77, Group::Grass},
        {63, "Forest", 0x93cc93, Group::Forest},
        {64, "Shrubland", 0xc6d69e, Group::Shrub},
        {65, "Barren", 0xccbfa3, Group::Barren},
        {66, "Cherries", 0xff00ff, Group::TreeCrop},
        {67, "Peaches", 0xff8eaa, Group::TreeCrop},
        {68, "Apples", 0xba004f, Group::TreeCrop},
        {69, "Grapes", 0x704489, Group::TreeCrop},
        {70, "Christmas Trees", 0x007878, Group::TreeCrop},
        {71, "Other Tree Crops", 0xaf9970, Group::TreeCrop},
        {72, "Citrus", 0xffff7e, Group::TreeCrop},
        {74, "Pecans", 0xb5705c, Group::TreeCrop},
        {75, "Almonds", 0x00a682, Group::TreeCrop},
        {76, "Walnuts", 0xead6af, Group::TreeCrop},
        {77, "Pears", 0xaf9970, Group::TreeCrop},
        {81, "Clouds/No Data", 0xf2f2f2, Group::Wall},
        {82, "Developed", 0x999999, Group::Wall},
        {83, "Water", 0x4b70a3, Group::Wall},
        {87, "Wetlands", 0x7eafaf, Group::Wetland},
        {88, "Nonag/Undefined", 0xe8ffbf, Group::Grass},
        {92, "Aquaculture", 0x00ffff, Group::Wall},
        {111, "Open Water", 0x4b70a3, Group::Wall},
        {112, "Perennial Ice/Snow", 0xd3e2f9, Group::Wall},
        {121, "Developed/Open Space", 0x999999, Group::OpenDeveloped},
        {122, "Developed/Low Intensity", 0x999999, Group::Wall},
        {123, "Developed/Med Intensity", 0x999999, Group::Wall},
        {124, "Developed/High Intensity", 0x999999, Group::Wall},
        {131, "Barren", 0xccbfa3, Group::Barren},
        {141, "Deciduous Forest", 0x93cc93, Group::Forest},
        {142, "Evergreen Forest", 0x93cc93, Group::Forest},
        {143, "Mixed Forest", 0x93cc93, Group::Forest},
        {152, "Shrubland", 0xc6d69e, Group::Shrub},
        {176, "Grass/Pasture", 0xe8ffbf, Group::Grass},
        {190, "Woody Wetlands", 0x7eafaf, Group::Wetland},
        {195, "Herbaceous Wetlands", 0x7eafaf, Group::Wetland},
        {204, "Pistachios", 0x00ff8c, Group::TreeCrop},
        {205, "Triticale", 0xd69ebc, Group::FieldCrop},
        {206, "Carrots", 0xff6666, Group::FieldCrop},
        {207, "Asparagus", 0xff6666, Group::FieldCrop},
        {208, "Garlic", 0xff6666, Group::FieldCrop},
        {209, "Cantaloupes", 0xff6666, Group::FieldCrop},
        {210, "Prunes", 0xff8eaa, Group::TreeCrop},
        {211, "Olives", 0x334933, Group::TreeCrop},
        {212, "Oranges", 0xe47026, Group::TreeCrop},
        {213, "Honeydew Melons", 0xff6666, Group::FieldCrop},
        {214, "Broccoli", 0xff6666, Group::FieldCrop},
        {215, "Avocados", 0x66994c, Group::TreeCrop},
        {216, "Peppers", 0xff6666, Group::FieldCrop},
        {217, "Pomegranates", 0xaf9970, Group::TreeCrop},
        {218, "Nectarines", 0xff8eaa, Group::TreeCrop},
        {219, "Greens", 0xff6666, Group::FieldCrop},
        {220, "Plums", 0xff8eaa, Group::TreeCrop},
        {221, "Strawberries", 0xff6666, Group::FieldCrop},
        {222, "Squash", 0xff6666, Group::FieldCrop},
        {223, "Apricots", 0xff8eaa, Group::TreeCrop},
        {224, "Vetch", 0x00af4b, Group::FieldCrop},
        {225, "Dbl Crop WinWht/Corn", 0xffd300, Group::FieldCrop},
        {226, "Dbl Crop Oats/Corn", 0xffd300, Group::FieldCrop},
        {227, "Lettuce", 0xff6666, Group::FieldCrop},
        {228, "Dbl Crop Triticale/Corn", 0xffd300, Group::FieldCrop},
        {229, "Pumpkins", 0xff6666, Group::FieldCrop},
        {230, "Dbl Crop Lettuce/Durum Wht", 0x896254, Group::FieldCrop},
        {231, "Dbl Crop Lettuce/Cantaloupe", 0xff6666, Group::FieldCrop},
        {232, "Dbl Crop Lettuce/Cotton", 0xff2626, Group::FieldCrop},
        {233, "Dbl Crop Lettuce/Barley", 0xe2007c, Group::FieldCrop},
        {234, "Dbl Crop Durum Wht/Sorghum", 0xff9e0b, Group::FieldCrop},
        {235, "Dbl Crop Barley/Sorghum", 0xff9e0b, Group::FieldCrop},
        {236, "Dbl Crop WinWht/Sorghum", 0xa57000, Group::FieldCrop},
        {237, "Dbl Crop Barley/Corn", 0xffd300, Group::FieldCrop},
        {238, "Dbl Crop WinWht/Cotton", 0xa57000, Group::FieldCrop},
        {239, "Dbl Crop Soybeans/Cotton", 0x267000, Group::FieldCrop},
        {240, "Dbl Crop Soybeans/Oats", 0x267000, Group::FieldCrop},
        {241, "Dbl Crop Corn/Soybeans", 0xffd300, Group::FieldCrop},
        {242, "Blueberries", 0x000099, Group::TreeCrop},
        {243, "Cabbage", 0xff6666, Group::FieldCrop},
        {244, "Cauliflower", 0xff6666, Group::FieldCrop},
        {245, "Celery", 0xff6666, Group::FieldCrop},
        {246, "Radishes", 0xff6666, Group::FieldCrop},
        {247, "Turnips", 0xff6666, Group::FieldCrop},
        {248, "Eggplants", 0xff6666, Group::FieldCrop},
        {249, "Gourds", 0xff6666, Group::FieldCrop},
        {250, "Cranberries", 0xff6666, Group::Wetland},
        {254, "Dbl Crop Barley/Soybeans", 0x267000, Group::FieldCrop},
    };
    return codes;
}

struct GroupDefaults {
    double speed;
    double fov;
    bool passable;
};

GroupDefaults defaultsOf(Group group) {
    switch (group) {
    case Group::FieldCrop:
        return {1.0, 10, true};
    case Group::TreeCrop:
        return {0.8, 5, true};
    case Group::Grass:
        return {1.5, 20, true};
    case Group::Shrub:
        return {0.8, 10, true};
    case Group::Forest:
        return {0.5, 5, true};
    case Group::Wetland:
        return {0.3, 5, true};
    case Group::Barren:
        return {1.5, 20, true};
    case Group::OpenDeveloped:
        return {1.2, 10, true};
    case Group::Wall:
        break;
    }
    return {0.0, 10, false};
}

} // namespace

std::vector<LandCoverClass> croplandDataLayerClasses() {
    std::vector<LandCoverClass> classes;
    for (const CroplandCode& code : croplandCodes()) {
        const GroupDefaults defaults = defaultsOf(code.group);
        classes.push_back(LandCoverClass{code.value, code.name, code.color,
                                         defaults.passable ? defaults.speed : 0.0, defaults.fov,
                                         defaults.passable});
    }
    return classes;
}

} // namespace mcpp::io::internal
