#include "skin/core/toml_location.h"

#include "skin/core/enum_names.h"

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
  static constexpr EnumNames<toml::node_type, 9> kNames{
      {{toml::node_type::table, "a table"},
       {toml::node_type::array, "an array"},
       {toml::node_type::string, "a string"},
       {toml::node_type::integer, "an integer"},
       {toml::node_type::floating_point, "a floating-point number"},
       {toml::node_type::boolean, "a boolean"},
       {toml::node_type::date, "a date"},
       {toml::node_type::time, "a time"},
       {toml::node_type::date_time, "a date-time"}}};
  const std::string_view name = enumName(type, kNames);
  return name.empty() ? "nothing" : name;
}

}  // namespace hylios::skin
