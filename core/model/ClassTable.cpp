#include "core/model/ClassTable.hpp"

#include "core/model/HumanUnits.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace mcpp {

ClassTable::ClassTable(std::vector<LandCoverClass> classes) {
    for (auto& landCoverClass : classes)
        set(landCoverClass);
}

void ClassTable::set(const LandCoverClass& landCoverClass) {
    auto existing = std::find_if(classes_.begin(), classes_.end(),
                                 [&](const LandCoverClass& c) { return c.value == landCoverClass.value; });
    if (existing != classes_.end()) {
        *existing = landCoverClass;
    } else {
        classes_.push_back(landCoverClass);
    }
}

void ClassTable::setEveryFieldOfView(double metres) {
    for (LandCoverClass& landCover : classes_)
        landCover.fieldOfViewMetres = metres;
}

bool ClassTable::remove(std::int32_t value) {
    const auto before = classes_.size();
    std::erase_if(classes_, [value](const LandCoverClass& c) { return c.value == value; });
    return classes_.size() != before;
}

const LandCoverClass* ClassTable::find(std::int32_t value) const {
    for (const auto& landCoverClass : classes_) {
        if (landCoverClass.value == value)
            return &landCoverClass;
    }
    return nullptr;
}

std::optional<std::string> ClassTable::validate() const {
    std::set<std::int32_t> seen;
    for (const auto& c : classes_) {
        std::ostringstream where;
        where << "class " << c.value << (c.name.empty() ? "" : " (" + c.name + ")");
        if (!seen.insert(c.value).second)
            return where.str() + ": value appears twice in the class table";
        if (!std::isfinite(c.speedMetresPerSecond))
            return where.str() + ": speed is not a number";
        if (c.speedMetresPerSecond < 0.0)
            return where.str() + ": speed " + formatQuantity(c.speedMetresPerSecond) + " m/s is negative";
        if (c.speedMetresPerSecond > kMaximumSpeedMetresPerSecond)
            return where.str() + ": speed " + formatQuantity(c.speedMetresPerSecond) +
                   " m/s is beyond any robot (at most " + formatQuantity(kMaximumSpeedMetresPerSecond) +
                   " m/s)";
        if (!std::isfinite(c.fieldOfViewMetres))
            return where.str() + ": field of view is not a number";
        if (c.isTraversable() && c.fieldOfViewMetres <= 0.0)
            return where.str() + ": field of view " + formatQuantity(c.fieldOfViewMetres) +
                   " m must be greater than zero for a passable class";
        if (c.fieldOfViewMetres > kMaximumFieldOfViewMetres)
            return where.str() + ": field of view " + formatQuantity(c.fieldOfViewMetres) +
                   " m is beyond any sensor (at most " + formatDistance(kMaximumFieldOfViewMetres) + ")";
        if (c.detectionProbability && !(*c.detectionProbability >= 0.0 && *c.detectionProbability <= 1.0))
            return where.str() + ": detection probability " + formatQuantity(*c.detectionProbability) +
                   " is not between 0 and 1";
    }
    return std::nullopt;
}

} // namespace mcpp
