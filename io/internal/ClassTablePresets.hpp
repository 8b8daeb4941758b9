#pragma once

#include "core/model/LandCoverClass.hpp"

#include <string>
#include <vector>

namespace mcpp::io::internal {

// How far a product's codes alone identify it: some products' codes are theirs (three-digit CORINE
// codes), others are small integers any map may use (grid codes 1-44), or mean nothing by themselves.
enum class CodeEvidence { Alone, WithCrs, Never };

struct PresetDefinition {
    std::string name;
    std::string description;
    std::vector<LandCoverClass> classes;
    std::string productName;               // for messages: "ESA WorldCover"
    std::vector<std::string> productWords; // words of its metadata or file name, lower case
    CodeEvidence codeEvidence = CodeEvidence::Never;
    std::vector<std::string> crsWords; // words of the CRS names it is distributed in, lower case
};

// Every built-in preset, in menu order. The tables and the reasoning behind their numbers are in
// ClassTablePresets.cpp.
[[nodiscard]] const std::vector<PresetDefinition>& presetDefinitions();

// The generic row for a class no preset or table knows: "Class N", 1 m/s, 10 m, passable; the index-th
// of a sequence of colours chosen to stay apart from each other.
[[nodiscard]] LandCoverClass genericClass(std::int32_t value, std::size_t index = 0);

// The Cropland Data Layer's codes (CroplandDataLayerClasses.cpp).
[[nodiscard]] std::vector<LandCoverClass> croplandDataLayerClasses();

} // namespace mcpp::io::internal
