#include "core/outlines/OutlineTracer.hpp"

#include "core/outlines/LabelPatches.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>

namespace mcpp {

std::int64_t doubledSignedArea(const OutlineRing& ring) {
    // Shoelace formula with y = -row, so that counter-clockwise on the map (north up) is positive.
    std::int64_t sum = 0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const GridVertex& a = ring[i];
        const GridVertex& b = ring[(i + 1) % ring.size()];
        sum += static_cast<std::int64_t>(a.column) * -b.row - static_cast<std::int64_t>(b.column) * -a.row;
    }
    return sum;
}

namespace {

// The sides of a pixel in the order a counter-clockwise walk around it passes them.
enum Side : int { Bottom = 0, Right = 1, Top = 2, Left = 3 };
// Where each side faces, in (column, row) steps; rows grow southwards.
constexpr std::array<int, 4> outwardColumn{0, 1, 0, -1};
constexpr std::array<int, 4> outwardRow{1, 0, -1, 0};
// The way a walk goes along each side with the pixel on its left.
constexpr std::array<int, 4> aheadColumn{1, 0, -1, 0};
constexpr std::array<int, 4> aheadRow{0, -1, 0, 1};
// The corner each side's walk ends at, from the pixel's north-west corner.
constexpr std::array<int, 4> endColumn{1, 1, 0, 0};
constexpr std::array<int, 4> endRow{1, 0, 0, 1};

std::uint64_t key(GridVertex vertex) {
    return static_cast<std::uint64_t>(static_cast<std::uint32_t>(vertex.column)) << 32U |
           static_cast<std::uint32_t>(vertex.row);
}

bool inside(const OutlineRing& ring, double x, double y) {
    // Even-odd rule on the map-oriented coordinates (column, -row); the point is never on an edge.
    bool result = false;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
        const double xi = ring[i].column, yi = -ring[i].row, xj = ring[j].column, yj = -ring[j].row;
        if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi)
            result = !result;
    }
    return result;
}

class Tracer {
  public:
    explicit Tracer(const LabelGrid& grid) : grid_(grid), patches_(grid), visited_(grid.labels.size(), 0) {
        polygons_.reserve(static_cast<std::size_t>(patches_.count()));
        for (int patch = 0; patch < patches_.count(); ++patch)
            polygons_.push_back(OutlinePolygon{patches_.label(patch), {}, {}, patches_.pixels(patch)});
        pending_.resize(polygons_.size());
    }

    std::vector<OutlinePolygon> run() {
        for (int row = 0; row < grid_.rows; ++row) {
            int column = 0;
            while (column < grid_.columns) {
                column = skipInterior(column, row);
                for (const int stop = std::min(grid_.columns, column + chunk); column < stop; ++column)
                    traceFrom(column, row);
            }
        }
        return assemble();
    }

  private:
    struct Pending {
        std::vector<OutlineRing> exteriors;
        std::vector<OutlineRing> holes;
    };

    // Pixels looked at together when skipping a region's inside.
    static constexpr int chunk = 32;

    void traceFrom(int column, int row) {
        const std::int32_t label = grid_.labels[grid_.index(column, row)];
        if (label == LabelGrid::noLabel)
            return;
        for (int side = 0; side < 4; ++side) {
            if (isBoundary(column, row, side, label) && !isVisited(column, row, side))
                traceRing(column, row, side, label);
        }
    }

    // The first column at or after `column` to look at: chunks of pixels whose four neighbours all hold
    // their own label have no side on an outline. Most of a large plan's pixels are such, and a chunk is
    // compared without a branch a pixel; the first and last row and column are always looked at.
    [[nodiscard]] int skipInterior(int column, int row) const {
        if (row == 0 || row + 1 == grid_.rows || column == 0)
            return column;
        const LabelGrid::Label* here = grid_.labels.data() + grid_.index(0, row);
        const LabelGrid::Label* above = here - grid_.columns;
        const LabelGrid::Label* below = here + grid_.columns;
        while (column + chunk < grid_.columns) {
            unsigned differs = 0;
            for (int c = column; c < column + chunk; ++c)
                differs |= static_cast<unsigned>(here[c] != here[c - 1]) |
                           static_cast<unsigned>(here[c] != here[c + 1]) |
                           static_cast<unsigned>(here[c] != above[c]) |
                           static_cast<unsigned>(here[c] != below[c]);
            if (differs != 0)
                break;
            column += chunk;
        }
        return column;
    }

    [[nodiscard]] bool same(int column, int row, std::int32_t label) const {
        return grid_.contains(column, row) && grid_.labels[grid_.index(column, row)] == label;
    }
    [[nodiscard]] bool isBoundary(int column, int row, int side, std::int32_t label) const {
        return !same(column + outwardColumn[side], row + outwardRow[side], label);
    }
    [[nodiscard]] bool isVisited(int column, int row, int side) const {
        return (visited_[grid_.index(column, row)] >> side & 1U) != 0;
    }

    // Walks the boundary with the patch on the left, turning left first: at a corner where two pixels of the
    // label meet only diagonally the walk keeps to the pixel it is on, so patches join through sides only.
    void traceRing(int startColumn, int startRow, int startSide, std::int32_t label) {
        OutlineRing corners;
        std::vector<bool> pinched; // the corner is one where the walk may pass again
        int column = startColumn, row = startRow, side = startSide;
        do {
            visited_[grid_.index(column, row)] |= static_cast<std::uint8_t>(1U << side);
            const int aheadC = column + aheadColumn[side], aheadR = row + aheadRow[side];
            const int diagonalC = aheadC + outwardColumn[side], diagonalR = aheadR + outwardRow[side];
            const GridVertex end{column + endColumn[side], row + endRow[side]};
            if (!same(aheadC, aheadR, label)) {
                corners.push_back(end);
                pinched.push_back(same(diagonalC, diagonalR, label));
                side = (side + 1) & 3;
            } else if (!same(diagonalC, diagonalR, label)) {
                column = aheadC;
                row = aheadR;
            } else {
                corners.push_back(end);
                pinched.push_back(false);
                column = diagonalC;
                row = diagonalR;
                side = (side + 3) & 3;
            }
        } while (column != startColumn || row != startRow || side != startSide);
        splitAndFile(corners, pinched, patches_.patchAt(startColumn, startRow));
    }

    // Cuts the walk into simple rings at the corners it passed twice, and files each as exterior or hole.
    void splitAndFile(const OutlineRing& corners, const std::vector<bool>& pinched, int patch) {
        OutlineRing stack;
        std::unordered_map<std::uint64_t, std::size_t> position;
        for (std::size_t i = 0; i < corners.size(); ++i) {
            const GridVertex vertex = corners[i];
            if (pinched[i]) {
                const auto found = position.find(key(vertex));
                if (found != position.end() && found->second < stack.size() &&
                    stack[found->second] == vertex) {
                    const auto from = static_cast<std::ptrdiff_t>(found->second);
                    file(OutlineRing(stack.begin() + from, stack.end()), patch);
                    stack.resize(found->second + 1);
                    continue;
                }
                position[key(vertex)] = stack.size();
            }
            stack.push_back(vertex);
        }
        file(std::move(stack), patch);
    }

    void file(OutlineRing ring, int patch) {
        Pending& pending = pending_[static_cast<std::size_t>(patch)];
        if (doubledSignedArea(ring) > 0)
            pending.exteriors.push_back(std::move(ring));
        else
            pending.holes.push_back(std::move(ring));
    }

    std::vector<OutlinePolygon> assemble() {
        std::vector<OutlinePolygon> result;
        result.reserve(polygons_.size());
        for (std::size_t id = 0; id < polygons_.size(); ++id) {
            Pending& pending = pending_[id];
            OutlinePolygon& polygon = polygons_[id];
            if (pending.exteriors.size() == 1) {
                polygon.exterior = std::move(pending.exteriors.front());
                polygon.holes = std::move(pending.holes);
                result.push_back(std::move(polygon));
                continue;
            }
            // Not expected for patches joined through sides; kept correct all the same.
            const std::size_t first = result.size();
            for (OutlineRing& exterior : pending.exteriors)
                result.push_back(OutlinePolygon{polygon.label, std::move(exterior), {}, 0});
            for (OutlineRing& hole : pending.holes)
                result[first + containingExterior(result, first, hole)].holes.push_back(std::move(hole));
            result[first].pixels = polygon.pixels;
        }
        return result;
    }

    // The polygon among result[first...] whose exterior holds the hole: tested at a point just inside the
    // hole, half a pixel to the right of its first edge.
    static std::size_t containingExterior(const std::vector<OutlinePolygon>& result, std::size_t first,
                                          const OutlineRing& hole) {
        const GridVertex a = hole[0], b = hole[1];
        const int dx = (b.column > a.column) - (b.column < a.column);
        const int dy = (a.row > b.row) - (a.row < b.row); // map y = -row
        const double x = a.column + 0.5 * dx + 0.5 * dy;
        const double y = -a.row + 0.5 * dy - 0.5 * dx;
        for (std::size_t i = first; i < result.size(); ++i) {
            if (inside(result[i].exterior, x, y))
                return i - first;
        }
        return 0;
    }

    const LabelGrid& grid_;
    LabelPatches patches_;
    std::vector<std::uint8_t> visited_;
    std::vector<OutlinePolygon> polygons_;
    std::vector<Pending> pending_;
};

} // namespace

std::vector<OutlinePolygon> traceOutlines(const LabelGrid& grid) {
    return Tracer(grid).run();
}

} // namespace mcpp
