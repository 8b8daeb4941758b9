// libFuzzer harness: any bytes as a mission file give a mission or an error naming the file, never a crash.
#include "io/Mission.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const auto mission = mcpp::io::parseMission(text, "fuzz.json");
    if (!mission && mission.error().rfind("fuzz.json", 0) != 0)
        std::abort(); // every error names the file first
    if (mission) {
        // What was read writes back and reads again to the same mission.
        const auto again = mcpp::io::parseMission(mcpp::io::missionToJson(mission.value()), "fuzz.json");
        if (!again || !(again.value() == mission.value()))
            std::abort();
    }
    return 0;
}
