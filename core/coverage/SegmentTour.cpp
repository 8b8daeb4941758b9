#include "core/coverage/SegmentTour.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace mcpp {
namespace {

// Candidates each 2-opt move looks at: the passes with an end nearest the leg it would replace.
constexpr int neighboursPerEnd = 8;
// Routes of this many passes or fewer try every reversal, not only those the nearest ends suggest.
constexpr std::size_t everyPairUpTo = 300;
// Full sweeps of 2-opt moves at most; each sweep that improves nothing ends it sooner.
constexpr int maximumSweeps = 30;

double distance(MapPoint a, MapPoint b) {
    // Not std::hypot: its care for overflow costs a third of the tour's time, and map metres never overflow.
    return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y));
}

// The passes' ends in square buckets, for nearest-end searches that grow ring by ring. End e is pass e / 2,
// its `from` when e is even.
class EndBuckets {
  public:
    EndBuckets(const std::vector<SegmentTour::Pass>& passes, MapPoint start) : passes_(passes) {
        double minX = start.x, maxX = start.x, minY = start.y, maxY = start.y;
        for (const SegmentTour::Pass& pass : passes)
            for (const MapPoint point : {pass.from, pass.to}) {
                minX = std::min(minX, point.x);
                maxX = std::max(maxX, point.x);
                minY = std::min(minY, point.y);
                maxY = std::max(maxY, point.y);
            }
        originX_ = minX;
        originY_ = minY;
        const double extent = std::max({maxX - minX, maxY - minY, 1e-9});
        const double perSide = std::max(1.0, std::ceil(std::sqrt(static_cast<double>(passes.size()))));
        side_ = extent / perSide;
        columns_ = static_cast<int>(std::floor((maxX - minX) / side_)) + 1;
        rows_ = static_cast<int>(std::floor((maxY - minY) / side_)) + 1;
        buckets_.resize(static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_));
        for (std::size_t end = 0; end < 2 * passes.size(); ++end)
            buckets_[bucketOf(point(static_cast<int>(end)))].push_back(static_cast<int>(end));
    }

    [[nodiscard]] MapPoint point(int end) const {
        const SegmentTour::Pass& pass = passes_[static_cast<std::size_t>(end / 2)];
        return end % 2 == 0 ? pass.from : pass.to;
    }
    void removePass(int pass) {
        for (const int end : {2 * pass, 2 * pass + 1}) {
            std::vector<int>& bucket = buckets_[bucketOf(point(end))];
            bucket.erase(std::find(bucket.begin(), bucket.end(), end));
        }
    }
    // Up to `count` ends nearest the point, nearest first.
    [[nodiscard]] std::vector<int> nearest(MapPoint from, std::size_t count) const {
        const int column =
            std::clamp(static_cast<int>(std::floor((from.x - originX_) / side_)), 0, columns_ - 1);
        const int row = std::clamp(static_cast<int>(std::floor((from.y - originY_) / side_)), 0, rows_ - 1);
        std::vector<std::pair<double, int>> found;
        for (int ring = 0; ring <= std::max(columns_, rows_); ++ring) {
            addRing(from, column, row, ring, found);
            if (found.size() < count)
                continue;
            const auto kth = found.begin() + static_cast<std::ptrdiff_t>(count) - 1;
            std::nth_element(found.begin(), kth, found.end());
            if (kth->first <= ring * side_)
                break;
        }
        const std::size_t kept = std::min(count, found.size());
        std::partial_sort(found.begin(), found.begin() + static_cast<std::ptrdiff_t>(kept), found.end());
        std::vector<int> ends;
        for (std::size_t i = 0; i < found.size() && i < count; ++i)
            ends.push_back(found[i].second);
        return ends;
    }

  private:
    [[nodiscard]] std::size_t bucketOf(MapPoint at) const {
        const int column =
            std::clamp(static_cast<int>(std::floor((at.x - originX_) / side_)), 0, columns_ - 1);
        const int row = std::clamp(static_cast<int>(std::floor((at.y - originY_) / side_)), 0, rows_ - 1);
        return static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) +
               static_cast<std::size_t>(column);
    }
    void addRing(MapPoint from, int column, int row, int ring,
                 std::vector<std::pair<double, int>>& found) const {
        for (int y = row - ring; y <= row + ring; ++y)
            for (int x = column - ring; x <= column + ring; ++x) {
                const bool onRing = std::max(std::abs(x - column), std::abs(y - row)) == ring;
                if (!onRing || x < 0 || y < 0 || x >= columns_ || y >= rows_)
                    continue;
                for (const int end :
                     buckets_[static_cast<std::size_t>(y) * static_cast<std::size_t>(columns_) +
                              static_cast<std::size_t>(x)])
                    found.emplace_back(distance(from, point(end)), end);
            }
    }

    const std::vector<SegmentTour::Pass>& passes_;
    double originX_ = 0.0;
    double originY_ = 0.0;
    double side_ = 1.0;
    int columns_ = 1;
    int rows_ = 1;
    std::vector<std::vector<int>> buckets_;
};

} // namespace

std::vector<SegmentTour::Visit> SegmentTour::nearestFirst(const std::vector<Pass>& passes, MapPoint start) {
    EndBuckets buckets(passes, start);
    std::vector<Visit> visits;
    MapPoint at = start;
    while (visits.size() < passes.size()) {
        const int end = buckets.nearest(at, 1).front();
        const int pass = end / 2;
        visits.push_back({pass, end % 2 == 1});
        buckets.removePass(pass);
        at = buckets.point(end % 2 == 1 ? 2 * pass : 2 * pass + 1);
    }
    return visits;
}

namespace {

// 2-opt over an open route of passes, each flown in either direction.
class TwoOpt {
  public:
    TwoOpt(const std::vector<SegmentTour::Pass>& passes, MapPoint start,
           std::vector<SegmentTour::Visit> visits)
        : passes_(passes), start_(start), visits_(std::move(visits)), positionOf_(passes.size()) {
        for (std::size_t position = 0; position < visits_.size(); ++position)
            positionOf_[static_cast<std::size_t>(visits_[position].pass)] = position;
    }

    std::vector<SegmentTour::Visit> improve() {
        const EndBuckets buckets(passes_, start_);
        const bool everyPair = visits_.size() <= everyPairUpTo;
        for (int sweep = 0; sweep < maximumSweeps; ++sweep) {
            bool improved = false;
            for (std::size_t first = 0; first < visits_.size(); ++first) {
                if (everyPair) {
                    for (std::size_t last = first; last < visits_.size(); ++last)
                        improved = tryReversing(first, last) || improved;
                    continue;
                }
                for (const int end : buckets.nearest(before(first), neighboursPerEnd))
                    improved =
                        tryReversing(first, positionOf_[static_cast<std::size_t>(end / 2)]) || improved;
            }
            if (!improved)
                break;
        }
        return visits_;
    }

  private:
    [[nodiscard]] MapPoint entry(std::size_t position) const {
        const SegmentTour::Visit& visit = visits_[position];
        const SegmentTour::Pass& pass = passes_[static_cast<std::size_t>(visit.pass)];
        return visit.reversed ? pass.to : pass.from;
    }
    [[nodiscard]] MapPoint exit(std::size_t position) const {
        const SegmentTour::Visit& visit = visits_[position];
        const SegmentTour::Pass& pass = passes_[static_cast<std::size_t>(visit.pass)];
        return visit.reversed ? pass.from : pass.to;
    }
    [[nodiscard]] MapPoint before(std::size_t position) const {
        return position == 0 ? start_ : exit(position - 1);
    }
    bool tryReversing(std::size_t first, std::size_t last) {
        if (last < first || gainOfReversing(first, last) <= 1e-9)
            return false;
        reverse(first, last);
        return true;
    }
    // Metres saved by flying visits first..last in the opposite order, each the other way.
    [[nodiscard]] double gainOfReversing(std::size_t first, std::size_t last) const {
        double saved = distance(before(first), entry(first)) - distance(before(first), exit(last));
        if (last + 1 < visits_.size())
            saved += distance(exit(last), entry(last + 1)) - distance(entry(first), entry(last + 1));
        return saved;
    }
    void reverse(std::size_t first, std::size_t last) {
        std::reverse(visits_.begin() + static_cast<std::ptrdiff_t>(first),
                     visits_.begin() + static_cast<std::ptrdiff_t>(last) + 1);
        for (std::size_t position = first; position <= last; ++position) {
            visits_[position].reversed = !visits_[position].reversed;
            positionOf_[static_cast<std::size_t>(visits_[position].pass)] = position;
        }
    }

    const std::vector<SegmentTour::Pass>& passes_;
    MapPoint start_;
    std::vector<SegmentTour::Visit> visits_;
    std::vector<std::size_t> positionOf_; // by pass
};

} // namespace

std::vector<SegmentTour::Visit> SegmentTour::order(const std::vector<Pass>& passes, MapPoint start) {
    if (passes.empty())
        return {};
    return TwoOpt(passes, start, nearestFirst(passes, start)).improve();
}

double SegmentTour::legMetres(const std::vector<Pass>& passes, MapPoint start,
                              const std::vector<Visit>& visits) {
    double metres = 0.0;
    MapPoint at = start;
    for (const Visit& visit : visits) {
        const Pass& pass = passes[static_cast<std::size_t>(visit.pass)];
        metres += distance(at, visit.reversed ? pass.to : pass.from);
        at = visit.reversed ? pass.from : pass.to;
    }
    return metres;
}

} // namespace mcpp
