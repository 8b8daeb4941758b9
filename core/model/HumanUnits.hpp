#pragma once

#include <string>

// Numbers in messages as a person would write them: no exponents, no six trailing decimals, areas and
// durations in the unit that suits their size.
namespace mcpp {

// At most `significant` significant digits, trailing zeros dropped, never an exponent: 30, 0.3168, 2.5e7 as
// 25000000. NaN and infinities print as "NaN", "infinity" and "-infinity".
[[nodiscard]] std::string formatQuantity(double value, int significant = 6);
// m2 below one hectare, ha below one square kilometre, km2 above; three significant digits ("850 m2",
// "27.5 ha", "275 km2").
[[nodiscard]] std::string formatArea(double squareMetres);
// m below a kilometre, km above, three significant digits.
[[nodiscard]] std::string formatDistance(double metres);
// A fraction (0.5) as a percentage ("50%"); one decimal at most, two for values under 1%.
[[nodiscard]] std::string formatPercent(double fraction);
// "45 s", "12 min 5 s", "3 h 12 min", "1 d 9 h 54 min" (minutes kept under ten days), "371 d 5 h"; rounded to
// the last unit shown.
[[nodiscard]] std::string formatDuration(double seconds);

} // namespace mcpp
