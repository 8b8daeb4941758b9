#include "core/model/NeighbourTopology.hpp"

#include <algorithm>

namespace mcpp {

bool NeighbourTopology::areNeighbours(int a, int b) const {
    const auto list = of(a);
    return std::find(list.begin(), list.end(), b) != list.end();
}

} // namespace mcpp
