#pragma once

#include "io/PlanExport.hpp"

namespace mcpp::render {

// The renderer lent to io's export catalogue: PNG fitted into pngSide x pngSide pixels, SVG into 1600.
[[nodiscard]] io::ImageWriter planImageWriter(int pngSide);

} // namespace mcpp::render
