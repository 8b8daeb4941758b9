#include "core/coverage/DetectionSegmentSelection.hpp"

#include "core/model/PlanningError.hpp"

#include <algorithm>

namespace mcpp {
namespace {

// What a pass loses for each target it sweeps again that needs nothing more (the seed's lambda): enough to
// keep passes off finished ground, small against what a pass gains on new ground.
constexpr double overlapPenaltyPerTarget = 0.01;
// A target counts as seen at the required probability within this much of it (rounding of C' updates).
constexpr double metTolerance = 1e-9;
// Places already seen enough that a pass flies over rather than ending and starting again beyond them.
constexpr int bridgedGap = 3;
// Rounds before giving up: each round raises some target, so only a defect of the model could use them.
constexpr int maximumRounds = 100000;

} // namespace

LatticePosition DetectionSegmentSelection::along(const LatticeWindow& window, int line, int step,
                                                 bool horizontal) {
    return horizontal ? LatticePosition{window.column + step, window.row + line}
                      : LatticePosition{window.column + line, window.row + step};
}

bool DetectionSegmentSelection::isTarget(const std::vector<char>& own, const DetectionAccumulator& seen,
                                         LatticePosition position) const {
    if (!seen.window().contains(position))
        return false;
    const std::size_t index = seen.window().index(position);
    return own[index] != 0 && model_.nearProbability(seen.profileAt(index)) > 0.0;
}

double DetectionSegmentSelection::passGain(const std::vector<char>& own, const DetectionAccumulator& seen,
                                           LatticePosition position, bool horizontal,
                                           double overlapPenalty) const {
    // The hottest loop of the planner: it walks the strip by index, clipped to the window once.
    const LatticeWindow& window = seen.window();
    const int across = horizontal ? position.row - window.row : position.column - window.column;
    const int width = horizontal ? window.rows : window.columns;
    const int first = std::max(-model_.reach(), -across);
    const int last = std::min(model_.reach(), width - 1 - across);
    const auto stride = static_cast<std::ptrdiff_t>(horizontal ? window.columns : 1);
    const auto centre = static_cast<std::ptrdiff_t>(window.index(position));
    const double* probability = seen.probabilities().data();
    double gain = 0.0;
    for (int offset = first; offset <= last; ++offset) {
        const auto index = static_cast<std::size_t>(centre + offset * stride);
        if (own[index] == 0)
            continue;
        // Land whose targets cannot be seen has chance 0 everywhere: no target.
        const double chance = model_.probability(seen.profileAt(index), offset);
        if (chance <= 0.0)
            continue;
        const double before = probability[index];
        if (before >= required_ - metTolerance)
            gain -= overlapPenalty;
        else
            gain += std::min(required_, before + (1.0 - before) * chance) - before;
    }
    return gain;
}

DetectionSegmentSelection::LineGains DetectionSegmentSelection::lineGains(const std::vector<char>& own,
                                                                          const DetectionAccumulator& seen,
                                                                          int line, bool horizontal,
                                                                          double overlapPenalty) const {
    const LatticeWindow& window = seen.window();
    const int steps = horizontal ? window.columns : window.rows;
    LineGains gains;
    bool inStretch = false;
    int ownSince = 0; // the first step of the unbroken run of the robot's places up to here
    for (int step = 0; step < steps; ++step) {
        const LatticePosition position = along(window, line, step, horizontal);
        // A pass needs room to run in its heading: a place with no neighbour along the line is passed
        // across it, and seen by the other heading's passes.
        const bool canRun =
            own[window.index(position)] != 0 && (isOwn(own, window, line, step - 1, horizontal) ||
                                                 isOwn(own, window, line, step + 1, horizontal));
        if (own[window.index(position)] == 0)
            ownSince = step + 1;
        const double gain = canRun ? passGain(own, seen, position, horizontal, overlapPenalty) : 0.0;
        // A pass stops at the first place it gains nothing (the seed's H = -infinity there).
        if (gain <= 0.0) {
            inStretch = false;
            continue;
        }
        // Flying on over a short gap costs less than the two turns and the way round of a new pass.
        const bool bridges = !gains.stretches.empty() &&
                             step - gains.stretches.back().last - 1 <= bridgedGap &&
                             gains.stretches.back().last >= ownSince;
        if (!inStretch && !bridges)
            gains.stretches.push_back({step, step});
        gains.stretches.back().last = step;
        gains.total += gain;
        inStretch = true;
    }
    return gains;
}

DetectionSegmentSelection::Round DetectionSegmentSelection::bestRound(const std::vector<char>& own,
                                                                      const DetectionAccumulator& seen,
                                                                      const std::vector<char>& nearUnmet,
                                                                      bool horizontal,
                                                                      double overlapPenalty) const {
    const LatticeWindow& window = seen.window();
    const int lines = horizontal ? window.rows : window.columns;
    // Lines whose strips do not overlap: a strip is the line and `reach` on each side.
    const int spacing = 2 * model_.reach() + 1;
    Round round;
    round.horizontal = horizontal;
    round.gains.reserve(static_cast<std::size_t>(lines));
    std::vector<double> best(static_cast<std::size_t>(lines) + 1, 0.0); // best[i]: over the first i lines
    std::vector<char> taken(static_cast<std::size_t>(lines), 0);
    for (int line = 0; line < lines; ++line) {
        // A pass along a line out of reach of every unmet target gains nothing.
        round.gains.push_back(nearUnmet[static_cast<std::size_t>(line)] != 0
                                  ? lineGains(own, seen, line, horizontal, overlapPenalty)
                                  : LineGains{});
        const auto index = static_cast<std::size_t>(line);
        const double with =
            round.gains[index].total + best[static_cast<std::size_t>(std::max(0, line + 1 - spacing))];
        taken[index] = with > best[index] ? 1 : 0;
        best[index + 1] = std::max(best[index], with);
    }
    round.total = best.back();
    for (int line = lines - 1; line >= 0;) {
        if (taken[static_cast<std::size_t>(line)] != 0) {
            round.lines.push_back(line);
            line -= spacing;
        } else {
            --line;
        }
    }
    return round;
}

bool DetectionSegmentSelection::isOwn(const std::vector<char>& own, const LatticeWindow& window, int line,
                                      int step, bool horizontal) {
    const int steps = horizontal ? window.columns : window.rows;
    return step >= 0 && step < steps && own[window.index(along(window, line, step, horizontal))] != 0;
}

DetectionSegmentSelection::UnmetLines
DetectionSegmentSelection::unmetLines(const std::vector<char>& own, const DetectionAccumulator& seen) const {
    const LatticeWindow& window = seen.window();
    const int reach = model_.reach();
    UnmetLines unmet{0, std::vector<char>(static_cast<std::size_t>(window.rows), 0),
                     std::vector<char>(static_cast<std::size_t>(window.columns), 0)};
    const auto mark = [reach](std::vector<char>& lines, int line) {
        const int last = std::min(static_cast<int>(lines.size()) - 1, line + reach);
        for (int near = std::max(0, line - reach); near <= last; ++near)
            lines[static_cast<std::size_t>(near)] = 1;
    };
    for (int row = 0; row < window.rows; ++row)
        for (int column = 0; column < window.columns; ++column) {
            const LatticePosition position{window.column + column, window.row + row};
            if (!isTarget(own, seen, position) || seen.at(position) >= required_ - metTolerance)
                continue;
            ++unmet.targets;
            mark(unmet.rows, row);
            mark(unmet.columns, column);
        }
    return unmet;
}

std::size_t DetectionSegmentSelection::unmetTargets(const std::vector<char>& own,
                                                    const DetectionAccumulator& seen) const {
    return unmetLines(own, seen).targets;
}

std::vector<DetectionSegment> DetectionSegmentSelection::select(const std::vector<char>& own,
                                                                DetectionAccumulator& seen,
                                                                const ProgressReporter& progress) const {
    std::vector<DetectionSegment> segments;
    const LatticeWindow window = seen.window();
    const auto better = [](const Round& a, const Round& b) { return a.total < b.total; };
    for (int roundNumber = 0;; ++roundNumber) {
        const UnmetLines unmet = unmetLines(own, seen);
        if (unmet.targets == 0)
            break;
        if (roundNumber == maximumRounds)
            throw PlanningError::aboutParameter("required_probability",
                                                "the detection passes stopped gaining before every target "
                                                "reached it");
        progress.throwIfCancelled();
        Round round = std::max(bestRound(own, seen, unmet.rows, true, overlapPenaltyPerTarget),
                               bestRound(own, seen, unmet.columns, false, overlapPenaltyPerTarget), better);
        // Where every pass would sweep more finished ground than it gains, drop the penalty: the last
        // targets must be reached all the same, and each one gains on its own centre.
        if (round.total <= 0.0)
            round = std::max(bestRound(own, seen, unmet.rows, true, 0.0),
                             bestRound(own, seen, unmet.columns, false, 0.0), better);
        // Only a region of one place has no pass to run: the robot stands there and looks both ways.
        if (round.total <= 0.0)
            break;
        for (const int line : round.lines)
            for (Stretch stretch : round.gains[static_cast<std::size_t>(line)].stretches) {
                // A pass of one place is flown in its heading from a neighbour along the line.
                if (stretch.first == stretch.last) {
                    if (isOwn(own, window, line, stretch.last + 1, round.horizontal))
                        ++stretch.last;
                    else
                        --stretch.first;
                }
                segments.push_back({along(window, line, stretch.first, round.horizontal),
                                    along(window, line, stretch.last, round.horizontal), round.horizontal});
                for (int step = stretch.first; step <= stretch.last; ++step)
                    seen.addPass(along(window, line, step, round.horizontal), round.horizontal);
            }
    }
    return segments;
}

} // namespace mcpp
