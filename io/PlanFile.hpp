#pragma once

#include "core/model/Plan.hpp"
#include "io/Mission.hpp"
#include "io/Result.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mcpp::io {

// A plan saved beside its mission (mission.json -> mission.mcpp-plan), so that reopening the mission shows
// the plan without planning again. The file names the inputs it was planned from by a fingerprint; a plan
// whose inputs have changed since is not restored.

// Where the plan of a mission file is kept.
[[nodiscard]] std::string planFilePath(const std::string& missionPath);

// A fingerprint of what a plan depends on, from the mission as its file holds it: the raster file (path,
// band, size, time of last change), the area files likewise, the class table, the starts, the planner and its
// parameters. Robot names and export settings are left out: they do not change a plan.
// Empty when a file's size or time cannot be read: such a plan is neither saved nor restored.
[[nodiscard]] std::string planInputsFingerprint(const Mission& mission, const std::string& missionPath);

// The paths, sizes and times of last change of input files (empty paths allowed), or empty when one cannot
// be read: kept when the files are read, compared before a plan is saved, so that a plan made from files
// since rewritten is not saved as theirs.
[[nodiscard]] std::string inputFilesIdentity(const std::vector<std::string>& paths);

// Writes the plan with the fingerprint of its inputs (atomic). Layers of the plan are not saved.
[[nodiscard]] Status savePlanFile(const Plan& plan, const std::string& fingerprint, const std::string& path);

// The plan in the file when its fingerprint is `fingerprint`; nothing when it was planned from other
// inputs. A file that cannot be read or is damaged is an error naming it.
[[nodiscard]] Result<std::optional<Plan>> loadPlanFile(const std::string& path,
                                                       const std::string& fingerprint);

// The version of the plan files this writes (MCPP-PLAN 8).
inline constexpr int planFormatVersion = 8;

// The plan from the bytes after a plan file's two header lines (for readers of other sources and the fuzzer);
// `path` names the source in errors. formatVersion: that of the file's first line, MCPP-PLAN 3 (paths hold
// every waypoint they walked), 4 (no times in the field), 5 (no take-off points), 6 (no kind of bound), 7
// (no land beyond every flight's reach) or 8 (this version's).
[[nodiscard]] Result<Plan> parsePlanBody(std::string_view compressed, const std::string& path,
                                         int formatVersion = planFormatVersion);

} // namespace mcpp::io
