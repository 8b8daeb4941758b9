#include "core/parameters/ParameterSpec.hpp"

#include "core/model/NameSuggestion.hpp"
#include "core/parameters/NumberText.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

namespace mcpp {
namespace {

std::string number(double value) {
    std::ostringstream text;
    text.precision(15);
    text << value;
    return text.str();
}

} // namespace

std::string ParameterSpec::expected() const {
    switch (type) {
    case ParameterType::Boolean:
        return "true or false";
    case ParameterType::Choice: {
        std::string words;
        for (const auto& choice : choices)
            words += (words.empty() ? "" : ", ") + choice;
        return "one of: " + words;
    }
    case ParameterType::Integer:
    case ParameterType::Real:
        break;
    }
    const std::string kind = (automatic.empty() ? "" : automatic + " or ") +
                             (type == ParameterType::Integer ? "a whole number" : "a number");
    const bool bounded = std::isfinite(maximum);
    const std::string inUnits = unit.empty() ? "" : " " + unit; // "0 to 600 s": what the numbers count
    if (!std::isfinite(minimum))
        return bounded ? kind + " up to " + number(maximum) + inUnits : kind;
    if (!bounded)
        return kind + " of at least " + number(minimum) + inUnits;
    return kind + " from " + number(minimum) + (maximumIncluded ? " to " : " up to (not including) ") +
           number(maximum) + inUnits;
}

bool ParameterSpec::isAutomatic(const ParameterValue& value) const {
    if (automatic.empty() || type != ParameterType::Real)
        return false;
    const auto* real = std::get_if<double>(&value);
    return real != nullptr && *real == automaticParameterValue;
}

std::optional<std::string> ParameterSpec::problemWith(const ParameterValue& value) const {
    if (isAutomatic(value))
        return std::nullopt;
    const auto wrong = [&] { return "expected " + expected(); };
    switch (type) {
    case ParameterType::Boolean:
        if (!std::holds_alternative<bool>(value))
            return wrong();
        return std::nullopt;
    case ParameterType::Choice: {
        const auto* word = std::get_if<std::string>(&value);
        if (word == nullptr || std::find(choices.begin(), choices.end(), *word) == choices.end())
            return wrong() + (word != nullptr ? ", got \"" + *word + "\"" : std::string());
        return std::nullopt;
    }
    case ParameterType::Integer:
        if (!std::holds_alternative<int>(value))
            return wrong();
        break;
    case ParameterType::Real:
        if (!std::holds_alternative<double>(value) && !std::holds_alternative<int>(value))
            return wrong();
        break;
    }
    const double number = std::holds_alternative<int>(value) ? std::get<int>(value) : std::get<double>(value);
    const bool inRange = std::isfinite(number) && number >= minimum &&
                         (maximumIncluded ? number <= maximum : number < maximum);
    if (!inRange)
        return wrong() + ", got " + mcpp::number(number);
    return std::nullopt;
}

std::optional<ParameterValue> ParameterSpec::parse(std::string_view text, std::string* error) const {
    const std::string_view word = trimmedText(text);
    std::optional<ParameterValue> value;
    switch (type) {
    case ParameterType::Boolean: {
        const std::string lower = lowercase(std::string(word));
        if (lower == "true" || lower == "yes" || lower == "on" || lower == "1")
            value = true;
        if (lower == "false" || lower == "no" || lower == "off" || lower == "0")
            value = false;
        break;
    }
    case ParameterType::Choice:
        value = std::string(word);
        break;
    case ParameterType::Integer: {
        int whole = 0;
        const auto [end, failure] = std::from_chars(word.data(), word.data() + word.size(), whole);
        if (!word.empty() && failure == std::errc() && end == word.data() + word.size())
            value = whole;
        break;
    }
    case ParameterType::Real:
        if (!automatic.empty() && lowercase(std::string(word)) == lowercase(std::string(automatic)))
            value = automaticParameterValue;
        else if (const auto real = parseFiniteNumber(word))
            value = *real;
        break;
    }
    std::optional<std::string> problem = value ? problemWith(*value) : "expected " + expected();
    if (problem && !value)
        *problem += ", got \"" + std::string(word) + "\"";
    if (problem) {
        if (error != nullptr)
            *error = *problem;
        return std::nullopt;
    }
    return value;
}

std::string ParameterSpec::format(const ParameterValue& value) const {
    if (isAutomatic(value))
        return automatic;
    if (const auto* flag = std::get_if<bool>(&value))
        return *flag ? "true" : "false";
    if (const auto* whole = std::get_if<int>(&value))
        return std::to_string(*whole);
    if (const auto* real = std::get_if<double>(&value))
        return number(*real);
    return std::get<std::string>(value);
}

ParameterSpec realParameter(std::string key, std::string label, double defaultValue, double minimum,
                            double maximum, std::string help, std::string unit, bool maximumIncluded) {
    ParameterSpec spec;
    spec.key = std::move(key);
    spec.label = std::move(label);
    spec.type = ParameterType::Real;
    spec.defaultValue = defaultValue;
    spec.minimum = minimum;
    spec.maximum = maximum;
    spec.maximumIncluded = maximumIncluded;
    spec.help = std::move(help);
    spec.unit = std::move(unit);
    return spec;
}

ParameterSpec onlyWith(ParameterSpec spec, std::string switchKey) {
    spec.onlyWith = std::move(switchKey);
    return spec;
}

ParameterSpec integerParameter(std::string key, std::string label, int defaultValue, int minimum, int maximum,
                               std::string help) {
    ParameterSpec spec;
    spec.key = std::move(key);
    spec.label = std::move(label);
    spec.type = ParameterType::Integer;
    spec.defaultValue = defaultValue;
    spec.minimum = minimum;
    spec.maximum = maximum;
    spec.help = std::move(help);
    return spec;
}

ParameterSpec booleanParameter(std::string key, std::string label, bool defaultValue, std::string help) {
    ParameterSpec spec;
    spec.key = std::move(key);
    spec.label = std::move(label);
    spec.type = ParameterType::Boolean;
    spec.defaultValue = defaultValue;
    spec.help = std::move(help);
    return spec;
}

ParameterSpec choiceParameter(std::string key, std::string label, std::string defaultValue,
                              std::vector<std::string> choices, std::string help) {
    ParameterSpec spec;
    spec.key = std::move(key);
    spec.label = std::move(label);
    spec.type = ParameterType::Choice;
    spec.defaultValue = std::move(defaultValue);
    spec.choices = std::move(choices);
    spec.help = std::move(help);
    return spec;
}

} // namespace mcpp
