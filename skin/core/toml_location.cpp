#include "skin/core/toml_location.h"

namespace hylios::skin {

SourceLocation tomlSourceLocation(const std::string& source, const toml::source_region& region) {
  SourceLocation location{source, 1, 1};
  if (region.begin.line != 0) location.line = static_cast<int>(region.begin.line);
  if (region.begin.column != 0) location.column = static_cast<int>(region.begin.column);
  return location;
}

std::string tomlLocation(const std::string& source, const toml::source_region& region) {
  return tomlSourceLocation(source, region).str();
}

std::string_view tomlTypeName(toml::node_type type) {
  switch (type) {
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a floating-point number";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time";
    case toml::node_type::date_time:
      return "a date-time";
    default:
      return "nothing";
  }
}

}  // namespace hylios::skin
