#pragma once

// Mission texts for test_broken_inputs. They live in BrokenMissions.cpp because moc cannot parse raw string
// literals that contain braces.

#include <vector>

namespace mcpp::test {

extern const char* const validMission;

struct MissionMutation {
    const char* name;
    const char* from; // text in validMission
    const char* to;   // replacement that breaks one field
    const char* path; // JSON path the error must name
};

// One mutation per mission field: each breaks exactly that field.
[[nodiscard]] std::vector<MissionMutation> missionMutations();

} // namespace mcpp::test
