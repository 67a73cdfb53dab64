// Command-line options whose value is one of an enum's names (skin/core/enum_names.h): CLI11
// checks the text with parseEnum's message ("--skin-model must be "walk" or "table", got "x"")
// and the command gets the enum, so no command compares strings. For --skin-model, and for any
// other estimator choice (e.g. --estimator).
#pragma once
#include <CLI/CLI.hpp>

#include <cstddef>
#include <optional>
#include <string>

#include "skin/core/enum_names.h"

namespace hylios {

/// CLI11 check: the text names a value of `names` (the message is parseEnum's).
template <typename E, std::size_t N>
CLI::Validator enumCheck(const EnumNames<E, N>& names, const std::string& option) {
  return CLI::Validator(
      [&names, option](std::string& text) -> std::string {
        try {
          parseEnum(text, names, option);
          return {};
        } catch (const std::invalid_argument& e) {
          return e.what();
        }
      },
      "{" + enumChoices(names) + "}");
}

/// Adds `option` storing the named value in `value` (left as it is when the option is absent).
template <typename E, std::size_t N, typename Target>
CLI::Option* addEnumOption(CLI::App& command, const std::string& option, Target& value,
                           const EnumNames<E, N>& names, const std::string& help) {
  return command
      .add_option_function<std::string>(
          option,
          [&value, &names, option](const std::string& text) {
            value = parseEnum(text, names, option);
          },
          help)
      ->check(enumCheck(names, option));
}

}  // namespace hylios
