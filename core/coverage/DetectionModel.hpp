#pragma once

#include "core/model/ClassTable.hpp"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace mcpp {

// How likely a pass is to see a target beside it (seed 001, imperfect extended detection). Within half the
// class's field of view of the path the sensor sees with the class's p0; from there it fades linearly to
// nothing at a whole field of view. A lattice cell at k cells to the side takes the mean over its width.
// Classes are looked up once into profiles, numbered densely, for the inner loops.
class DetectionModel {
  public:
    static constexpr int noProfile = -1;

    // cellSize: side of the lattice cells in metres; defaultProbability: p0 of classes that give none.
    DetectionModel(const ClassTable& classes, double defaultProbability, double cellSize);

    // The profile of a class, or noProfile for one the table lacks.
    [[nodiscard]] int profileOf(std::int32_t classValue) const;
    // p0 of a profile: 0 where targets cannot be seen at all.
    [[nodiscard]] double nearProbability(int profile) const {
        return profile == noProfile ? 0.0 : nearProbability_[static_cast<std::size_t>(profile)];
    }
    // Chance one pass sees a target of the profile `offset` cells to its side (0 = on the path).
    [[nodiscard]] double probability(int profile, int offset) const {
        if (profile == noProfile || offset < -reach_ || offset > reach_)
            return 0.0;
        const int distance = offset < 0 ? -offset : offset;
        return byOffset_[static_cast<std::size_t>(profile * (reach_ + 1) + distance)];
    }
    [[nodiscard]] int profiles() const { return static_cast<int>(nearProbability_.size()); }
    // Passes per lattice cell that parallel passes over land of one profile need for every target to reach
    // the required probability: the fewest m / w over a spacing of w cells and m >= 1 passes per line
    // (fractional: ln(1 - D) / ln(miss)), for the worst-placed target. 0 for a profile whose targets cannot
    // be seen.
    [[nodiscard]] double passesPerCell(int profile, double required) const;
    // The largest offset any class is seen at: a pass's strip is 2 x reach + 1 cells wide.
    [[nodiscard]] int reach() const { return reach_; }
    // The probability of seeing at lateral distance d metres, before averaging over a cell.
    [[nodiscard]] static double atDistance(double nearProbability, double fieldOfViewMetres, double distance);

  private:
    std::unordered_map<std::int32_t, int> profileOfClass_;
    std::vector<double> nearProbability_; // by profile
    std::vector<double> byOffset_;        // profile x (reach + 1) + offset
    int reach_ = 0;
};

} // namespace mcpp
