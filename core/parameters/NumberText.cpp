#include "core/parameters/NumberText.hpp"

#include <cctype>
#include <charconv>
#include <cmath>

namespace mcpp {

std::string_view trimmedText(std::string_view text) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front())))
        text.remove_prefix(1);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
        text.remove_suffix(1);
    return text;
}

std::optional<double> parseFiniteNumber(std::string_view text) {
    text = trimmedText(text);
    if (!text.empty() && text.front() == '+')
        text.remove_prefix(1);
    if (text.empty())
        return std::nullopt;
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        return std::nullopt;
    return value;
}

std::optional<double> parseDuration(std::string_view text) {
    text = trimmedText(text);
    const std::size_t unitStart = text.find_first_not_of("0123456789.+-eE");
    std::string_view unit = unitStart == std::string_view::npos ? std::string_view() : text.substr(unitStart);
    unit = trimmedText(unit);
    const double perUnit = unit.empty() || unit == "s" ? 1.0
                           : unit == "min"             ? 60.0
                           : unit == "h"               ? 3600.0
                                                       : 0.0;
    const auto number = parseFiniteNumber(text.substr(0, unitStart));
    if (!number || perUnit == 0.0)
        return std::nullopt;
    return *number * perUnit;
}

} // namespace mcpp
