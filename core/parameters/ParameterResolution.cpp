#include "core/parameters/ParameterResolution.hpp"

#include "core/model/NameSuggestion.hpp"
#include "core/model/PlanningError.hpp"

#include <algorithm>

namespace mcpp {

const ParameterSpec* findParameter(const std::vector<ParameterSpec>& specs, const std::string& key) {
    const auto found =
        std::find_if(specs.begin(), specs.end(), [&](const ParameterSpec& spec) { return spec.key == key; });
    return found == specs.end() ? nullptr : &*found;
}

std::vector<const ParameterSpec*> switchesNeeded(const std::vector<ParameterSpec>& specs,
                                                 const ParameterSpec& spec) {
    std::vector<const ParameterSpec*> switches;
    for (const ParameterSpec* needing = &spec; !needing->onlyWith.empty();) {
        const ParameterSpec* found = findParameter(specs, needing->onlyWith);
        if (found == nullptr || found == &spec ||
            std::find(switches.begin(), switches.end(), found) != switches.end())
            break;
        switches.insert(switches.begin(), found);
        needing = found;
    }
    return switches;
}

bool parameterInEffect(const std::vector<ParameterSpec>& specs, const ParameterValues& values,
                       const ParameterSpec& spec) {
    for (const ParameterSpec* needed : switchesNeeded(specs, spec)) {
        const ParameterValue* given = values.find(needed->key);
        const ParameterValue& value = given != nullptr ? *given : needed->defaultValue;
        if (!std::holds_alternative<bool>(value) || !std::get<bool>(value))
            return false;
    }
    return true;
}

std::string switchesText(const std::vector<const ParameterSpec*>& switches) {
    std::string text;
    for (std::size_t i = 0; i < switches.size(); ++i)
        text += (i == 0 ? "" : i + 1 == switches.size() ? " and " : ", ") + switches[i]->key + "=true";
    return text;
}

std::vector<std::string> parametersWithoutEffect(const std::vector<ParameterSpec>& specs,
                                                 const ParameterValues& given,
                                                 const ParameterValues& resolved) {
    std::vector<std::string> notes;
    for (const ParameterSpec& spec : specs) {
        const ParameterValue* value = given.find(spec.key);
        // Missions write every key: only a value other than the default is the user's own setting.
        if (value == nullptr || *value == spec.defaultValue || parameterInEffect(specs, resolved, spec))
            continue;
        notes.push_back(spec.key + "=" + spec.format(*value) + " has no effect: it needs " +
                        switchesText(switchesNeeded(specs, spec)));
    }
    return notes;
}

std::string parameterKeys(const std::vector<ParameterSpec>& specs) {
    std::string keys;
    for (const ParameterSpec& spec : specs)
        keys += (keys.empty() ? "" : ", ") + spec.key;
    return keys.empty() ? "none" : keys;
}

std::string knownParametersNote(const std::string& typed, const std::vector<ParameterSpec>& specs) {
    std::vector<std::string> keys;
    for (const ParameterSpec& spec : specs)
        keys.push_back(spec.key);
    const auto meant = closestName(typed, keys);
    return "(" + (meant ? "did you mean \"" + *meant + "\"? " : std::string()) +
           "parameters: " + parameterKeys(specs) + ")";
}

ParameterValues resolveParameters(const std::vector<ParameterSpec>& specs, const ParameterValues& given) {
    for (const auto& [key, value] : given.all())
        if (findParameter(specs, key) == nullptr)
            throw PlanningError::aboutParameter(key, "unknown parameter " + knownParametersNote(key, specs));
    ParameterValues resolved;
    for (const ParameterSpec& spec : specs) {
        const ParameterValue* value = given.find(spec.key);
        if (value == nullptr) {
            resolved.set(spec.key, spec.defaultValue);
            continue;
        }
        if (const auto problem = spec.problemWith(*value))
            throw PlanningError::aboutParameter(spec.key, *problem);
        // A whole number given for a real parameter is kept as a real, so equal values compare equal.
        if (spec.type == ParameterType::Real && std::holds_alternative<int>(*value))
            resolved.set(spec.key, static_cast<double>(std::get<int>(*value)));
        else
            resolved.set(spec.key, *value);
    }
    return resolved;
}

} // namespace mcpp
