// Positions and type names for messages about TOML files (specimens, scenes): toml++ reports
// 1-based lines and columns in a source_region, 0 where it has none; these helpers turn that into
// a SourceLocation ("file:line:col") and name a node's type in words ("an integer", "a string").
#pragma once
#include <toml++/toml.h>

#include <string>
#include <string_view>

#include "skin/core/source_location.h"

namespace hylios::skin {

/// The start of `region` in file `source`; line and column 1 where toml++ has no position.
SourceLocation tomlSourceLocation(const std::string& source, const toml::source_region& region);
/// "source:line:col" for the start of `region`.
std::string tomlLocation(const std::string& source, const toml::source_region& region);
/// The type of a node in words, for "must be a number, got a string".
std::string_view tomlTypeName(toml::node_type type);

}  // namespace hylios::skin
