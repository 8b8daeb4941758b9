#pragma once

#include "core/parameters/ParameterSpec.hpp"
#include "core/parameters/ParameterValues.hpp"

#include <string>
#include <vector>

namespace mcpp {

// Every declared parameter's value: the given one where there is one, else the default. Throws
// PlanningError (about the parameter) for a key the declaration lacks or a value that does not fit it.
[[nodiscard]] ParameterValues resolveParameters(const std::vector<ParameterSpec>& specs,
                                                const ParameterValues& given);
// The declaration of `key`, or nullptr.
[[nodiscard]] const ParameterSpec* findParameter(const std::vector<ParameterSpec>& specs,
                                                 const std::string& key);
// The switches a parameter needs (ParameterSpec::onlyWith, followed along), outermost first: for MSTC's
// turns slack, balanced then subtree_pieces. A switch the declaration lacks, or a loop, ends the chain.
[[nodiscard]] std::vector<const ParameterSpec*> switchesNeeded(const std::vector<ParameterSpec>& specs,
                                                               const ParameterSpec& spec);
// Whether every switch the parameter needs is on in `values` (one not there counts as its default).
[[nodiscard]] bool parameterInEffect(const std::vector<ParameterSpec>& specs, const ParameterValues& values,
                                     const ParameterSpec& spec);
// "balanced=true and subtree_pieces=true": the switches, as typed.
[[nodiscard]] std::string switchesText(const std::vector<const ParameterSpec*>& switches);
// A sentence for each given parameter, other than its default, that has no effect because a switch it
// needs is off in `resolved`: a setting the user made is not dropped without a word.
[[nodiscard]] std::vector<std::string> parametersWithoutEffect(const std::vector<ParameterSpec>& specs,
                                                               const ParameterValues& given,
                                                               const ParameterValues& resolved);
// "a, b, c": the keys, for messages.
[[nodiscard]] std::string parameterKeys(const std::vector<ParameterSpec>& specs);
// What follows a message about a key no spec has: "(did you mean \"rounds\"? parameters: a, b, c)", the
// question only when one key is close.
[[nodiscard]] std::string knownParametersNote(const std::string& typed,
                                              const std::vector<ParameterSpec>& specs);

} // namespace mcpp
