// Positions and type names for messages about TOML files (specimens, scenes): toml++ reports
// 1-based lines and columns in a source_region, 0 where it has none; these helpers turn that into
// "file:line:col" and name a node's type in words ("an integer", "a string").
#pragma once
#include <toml++/toml.h>

#include <string>
#include <string_view>

namespace hylios::skin {

struct TomlPosition {
  int line = 1;    ///< 1-based; 1 where toml++ has no position
  int column = 1;  ///< 1-based; 1 where toml++ has no position
};

TomlPosition tomlPosition(const toml::source_region& region);
/// "source:line:col" for the start of `region`.
std::string tomlLocation(const std::string& source, const toml::source_region& region);
/// The type of a node in words, for "must be a number, got a string".
std::string_view tomlTypeName(toml::node_type type);

}  // namespace hylios::skin
