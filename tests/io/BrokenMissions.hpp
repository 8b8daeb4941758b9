#pragma once

// Mission texts for test_broken_inputs. They live in BrokenMissions.cpp because moc cannot parse raw string
// literals that contain braces.

#include <vector>

namespace mcpp::test {

extern const char* const validMission;         // version 1: the planner's parameters beside its name
extern const char* const validMissionVersion2; // version 2: under planner.parameters

struct MissionMutation {
    const char* name;
    const char* from; // text in validMission
    const char* to;   // replacement that breaks one field
    const char* path; // JSON path the error must name
};

// One mutation per mission field: each breaks exactly that field.
[[nodiscard]] std::vector<MissionMutation> missionMutations();
// The same for version 2's planner object.
[[nodiscard]] std::vector<MissionMutation> missionVersion2Mutations();

} // namespace mcpp::test
