#include "core/model/RobotNumbers.hpp"

#include <regex>
#include <set>

namespace mcpp {

std::vector<std::size_t> robotNumbersIn(const std::string& message) {
    static const std::regex numbered(R"(\brobot ([0-9]{1,9})\b)");
    std::set<std::size_t> robots;
    for (auto match = std::sregex_iterator(message.begin(), message.end(), numbered);
         match != std::sregex_iterator(); ++match)
        robots.insert(std::stoul((*match)[1].str()));
    return {robots.begin(), robots.end()};
}

} // namespace mcpp
