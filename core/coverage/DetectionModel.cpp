#include "core/coverage/DetectionModel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace mcpp {
namespace {

// Samples across a cell's width when averaging the profile: the profile is piecewise linear, so the
// midpoint rule is within p0 / (8 x samples^2) of the exact mean.
constexpr int samplesPerCell = 64;

double meanOverCell(double nearProbability, double fieldOfView, double cellSize, int offset) {
    double sum = 0.0;
    for (int sample = 0; sample < samplesPerCell; ++sample) {
        const double across = (offset - 0.5 + (sample + 0.5) / samplesPerCell) * cellSize;
        sum += DetectionModel::atDistance(nearProbability, fieldOfView, std::abs(across));
    }
    return sum / samplesPerCell;
}

// The cell means of one class, from the path outwards, up to the last one above 0.
std::vector<double> cellMeans(const LandCoverClass& landCover, double nearProbability, double cellSize) {
    std::vector<double> means;
    if (!landCover.isTraversable() || nearProbability <= 0.0)
        return means;
    for (int offset = 0;; ++offset) {
        const double mean = meanOverCell(nearProbability, landCover.fieldOfViewMetres, cellSize, offset);
        if (mean <= 0.0)
            return means;
        means.push_back(mean);
    }
}

} // namespace

DetectionModel::DetectionModel(const ClassTable& classes, double defaultProbability, double cellSize) {
    std::vector<std::vector<double>> means;
    for (const LandCoverClass& landCover : classes.classes()) {
        const double near = landCover.detectionProbability.value_or(defaultProbability);
        profileOfClass_[landCover.value] = static_cast<int>(nearProbability_.size());
        means.push_back(cellMeans(landCover, near, cellSize));
        nearProbability_.push_back(means.back().empty() ? 0.0 : near);
        reach_ = std::max(reach_, static_cast<int>(means.back().size()) - 1);
    }
    byOffset_.assign(means.size() * static_cast<std::size_t>(reach_ + 1), 0.0);
    for (std::size_t profile = 0; profile < means.size(); ++profile)
        std::copy(means[profile].begin(), means[profile].end(),
                  byOffset_.begin() +
                      static_cast<std::ptrdiff_t>(profile * static_cast<std::size_t>(reach_ + 1)));
}

double DetectionModel::atDistance(double nearProbability, double fieldOfViewMetres, double distance) {
    const double half = fieldOfViewMetres / 2.0;
    if (distance <= half)
        return nearProbability;
    if (distance >= fieldOfViewMetres)
        return 0.0;
    return nearProbability * (fieldOfViewMetres - distance) / half;
}

double DetectionModel::passesPerCell(int profile, double required) const {
    if (nearProbability(profile) <= 0.0)
        return 0.0;
    double best = std::numeric_limits<double>::infinity();
    for (int spacing = 1; spacing <= 2 * reach_ + 1; ++spacing) {
        // The target between lines that sees them worst: its chance of being missed by one pass of each.
        double worstMiss = 0.0;
        for (int first = 0; first < spacing; ++first) {
            double miss = 1.0;
            for (int offset = first - spacing * (reach_ / spacing + 1); offset <= reach_; offset += spacing)
                miss *= 1.0 - probability(profile, offset);
            worstMiss = std::max(worstMiss, miss);
        }
        if (worstMiss >= 1.0)
            break; // lines this far apart leave some target unseen
        // Fractional: the greedy adds single passes where one round falls short, not a whole round.
        const double passes = worstMiss <= 0.0 ? 1.0 : std::log(1.0 - required) / std::log(worstMiss);
        best = std::min(best, std::max(1.0, passes) / spacing);
    }
    return best;
}

int DetectionModel::profileOf(std::int32_t classValue) const {
    const auto found = profileOfClass_.find(classValue);
    return found == profileOfClass_.end() ? noProfile : found->second;
}

} // namespace mcpp
