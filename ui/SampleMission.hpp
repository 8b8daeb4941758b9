#pragma once

#include <QString>

namespace mcpp::ui {

// The bundled sample mission (samples/zion-nlcd/mission.json): beside or above the executable (build
// trees), in the installed share folder, or in the source tree this was built from. Empty when absent.
[[nodiscard]] QString findSampleMission();

} // namespace mcpp::ui
