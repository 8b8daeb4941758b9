#pragma once

#include "core/parameters/ParameterSpec.hpp"
#include "core/parameters/ParameterValues.hpp"

#include <vector>

namespace mcpp {

// Every declared parameter's value: the given one where there is one, else the default. Throws
// PlanningError (about the parameter) for a key the declaration lacks or a value that does not fit it.
[[nodiscard]] ParameterValues resolveParameters(const std::vector<ParameterSpec>& specs,
                                                const ParameterValues& given);
// The declaration of `key`, or nullptr.
[[nodiscard]] const ParameterSpec* findParameter(const std::vector<ParameterSpec>& specs,
                                                 const std::string& key);
// "a, b, c": the keys, for messages.
[[nodiscard]] std::string parameterKeys(const std::vector<ParameterSpec>& specs);
// What follows a message about a key no spec has: "(did you mean \"rounds\"? parameters: a, b, c)", the
// question only when one key is close.
[[nodiscard]] std::string knownParametersNote(const std::string& typed,
                                              const std::vector<ParameterSpec>& specs);

} // namespace mcpp
