#include "core/model/HumanUnits.hpp"

#include <cmath>
#include <cstdio>

namespace mcpp {
namespace {

std::string nonFinite(double value) {
    if (std::isnan(value))
        return "NaN";
    return value > 0 ? "infinity" : "-infinity";
}

// Fixed-point text with `decimals` decimals, trailing zeros and a bare point removed.
std::string trimmedFixed(double value, int decimals) {
    char text[400];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    std::string result(text);
    if (result.find('.') != std::string::npos) {
        result.erase(result.find_last_not_of('0') + 1);
        if (result.back() == '.')
            result.pop_back();
    }
    return result == "-0" ? "0" : result;
}

} // namespace

std::string formatQuantity(double value, int significant) {
    if (!std::isfinite(value))
        return nonFinite(value);
    if (value == 0.0)
        return "0";
    // Digits before the point decide how many may follow it.
    const int magnitude = static_cast<int>(std::floor(std::log10(std::fabs(value))));
    const int decimals = std::max(0, significant - 1 - magnitude);
    // Round to the significant digits first, so 123456789 at three digits prints as 123000000.
    const double scale = std::pow(10.0, magnitude - significant + 1);
    const double rounded = magnitude >= significant ? std::round(value / scale) * scale : value;
    return trimmedFixed(rounded, std::min(decimals, 20));
}

std::string formatArea(double squareMetres) {
    if (!std::isfinite(squareMetres))
        return nonFinite(squareMetres) + " m2";
    const double size = std::fabs(squareMetres);
    if (size < 1e4)
        return formatQuantity(squareMetres, 3) + " m2";
    if (size < 1e6)
        return formatQuantity(squareMetres / 1e4, 3) + " ha";
    return formatQuantity(squareMetres / 1e6, 3) + " km2";
}

std::string formatDistance(double metres) {
    if (!std::isfinite(metres))
        return nonFinite(metres) + " m";
    if (std::fabs(metres) < 1000.0)
        return formatQuantity(metres, 3) + " m";
    return formatQuantity(metres / 1000.0, 3) + " km";
}

std::string formatPercent(double fraction) {
    if (!std::isfinite(fraction))
        return nonFinite(fraction) + "%";
    const double percent = fraction * 100.0;
    return trimmedFixed(percent, std::fabs(percent) < 1.0 ? 2 : 1) + "%";
}

std::string formatDuration(double seconds) {
    if (!std::isfinite(seconds))
        return nonFinite(seconds) + " s";
    if (seconds < 0)
        return "-" + formatDuration(-seconds);
    if (seconds < 60.0)
        return formatQuantity(seconds, seconds < 10.0 ? 2 : 3) + " s";
    // Minutes still tell robots apart over a few days; over weeks they are noise.
    constexpr long long kDaysWithMinutes = 10;
    // Rounded to the last unit shown, not cut: 1 h 23 min 57 s reads 1 h 24 min.
    constexpr double kMinutesFrom = 3600.0;
    constexpr double kHoursFrom = kDaysWithMinutes * 86400.0 - 1800.0; // days and hours only from there
    // Below the hour, seconds stay: a 59 min 58 s flight on a battery of an hour must not read 1 h.
    const double shownUnit = seconds >= kHoursFrom ? 3600.0 : seconds >= kMinutesFrom - 0.5 ? 60.0 : 1.0;
    const auto total =
        static_cast<long long>(std::llround(seconds / shownUnit)) * static_cast<long long>(shownUnit);
    const long long days = total / 86400;
    const long long hours = total / 3600 % 24;
    const long long minutes = total / 60 % 60;
    const long long rest = total % 60;
    const auto part = [](long long amount, const char* unit) { return std::to_string(amount) + " " + unit; };
    if (days >= kDaysWithMinutes)
        return part(days, "d") + (hours > 0 ? " " + part(hours, "h") : "");
    if (days > 0)
        return part(days, "d") + " " + part(hours, "h") + (minutes > 0 ? " " + part(minutes, "min") : "");
    if (hours > 0)
        return part(hours, "h") + (minutes > 0 ? " " + part(minutes, "min") : "");
    return part(minutes, "min") + (rest > 0 ? " " + part(rest, "s") : "");
}

} // namespace mcpp
