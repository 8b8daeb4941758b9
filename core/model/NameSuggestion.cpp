#include "core/model/NameSuggestion.hpp"

#include <algorithm>
#include <cctype>

namespace mcpp {

std::string lowercase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char letter) { return static_cast<char>(std::tolower(letter)); });
    return text;
}

namespace {

// Letters to insert, delete or change to turn one text into the other.
std::size_t editDistance(const std::string& from, const std::string& to) {
    std::vector<std::size_t> previous(to.size() + 1);
    std::vector<std::size_t> current(to.size() + 1);
    for (std::size_t j = 0; j <= to.size(); ++j)
        previous[j] = j;
    for (std::size_t i = 1; i <= from.size(); ++i) {
        current[0] = i;
        for (std::size_t j = 1; j <= to.size(); ++j) {
            const std::size_t change = previous[j - 1] + (from[i - 1] == to[j - 1] ? 0 : 1);
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, change});
        }
        std::swap(previous, current);
    }
    return previous[to.size()];
}

} // namespace

std::optional<std::string> closestName(const std::string& typed, const std::vector<std::string>& known) {
    const std::string wanted = lowercase(typed);
    // A part of a name ("worldcover" for "esa-worldcover") means that name when it is the only one so.
    if (wanted.size() >= 3) {
        std::vector<std::string> holding;
        for (const std::string& name : known)
            if (lowercase(name).find(wanted) != std::string::npos)
                holding.push_back(name);
        if (holding.size() == 1)
            return holding.front();
    }
    std::optional<std::string> best;
    std::size_t bestDistance = std::max<std::size_t>(2, wanted.size() / 4) + 1;
    for (const std::string& name : known) {
        const std::size_t distance = editDistance(wanted, lowercase(name));
        if (distance < bestDistance) {
            best = name;
            bestDistance = distance;
        }
    }
    if (best)
        return best;
    // A name with more around it ("robots" in "robots_list") means that name when it holds no other.
    std::vector<std::string> held;
    for (const std::string& name : known)
        if (name.size() >= 4 && wanted.find(lowercase(name)) != std::string::npos)
            held.push_back(name);
    if (held.size() == 1)
        return held.front();
    return std::nullopt;
}

} // namespace mcpp
