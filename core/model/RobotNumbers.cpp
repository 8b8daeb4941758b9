#include "core/model/RobotNumbers.hpp"

#include <regex>
#include <set>

namespace mcpp {

std::vector<std::size_t> robotNumbersIn(const std::string& message) {
    // "robot 4", and lists as messages write them: "robots 1, 2 and 5", where "and 3 more" counts robots
    // not named. Only "robots" begins a list: in "robot 2, 30 m away" the 30 is no robot.
    static const std::regex numbered(
        R"(\brobot ([0-9]{1,9})\b|\brobots ([0-9]{1,9}(?:(?:, | and )[0-9]{1,9}(?![0-9]| more))*)\b)");
    static const std::regex number("[0-9]+");
    std::set<std::size_t> robots;
    for (auto match = std::sregex_iterator(message.begin(), message.end(), numbered);
         match != std::sregex_iterator(); ++match) {
        const std::string list = (*match)[1].matched ? (*match)[1].str() : (*match)[2].str();
        for (auto each = std::sregex_iterator(list.begin(), list.end(), number);
             each != std::sregex_iterator(); ++each)
            robots.insert(std::stoul(each->str()));
    }
    return {robots.begin(), robots.end()};
}

} // namespace mcpp
