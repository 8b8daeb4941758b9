#pragma once

#include "core/model/LandCoverClass.hpp"

#include <string>
#include <vector>

namespace mcpp::io::internal {

struct PresetDefinition {
    std::string name;
    std::string description;
    std::vector<LandCoverClass> classes;
};

// Every built-in preset, in menu order. The tables and the reasoning behind their numbers are in
// ClassTablePresets.cpp.
[[nodiscard]] const std::vector<PresetDefinition>& presetDefinitions();

// The generic row for a class no preset or table knows: "Class N", grey, 1 m/s, 10 m, passable.
[[nodiscard]] LandCoverClass genericClass(std::int32_t value);

} // namespace mcpp::io::internal
