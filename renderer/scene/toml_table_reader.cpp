#include "renderer/scene/toml_table_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "skin/core/toml_location.h"

namespace hylios {

bool NumberRange::contains(double v) const {
  const bool aboveMin = minOpen ? v > min : v >= min;
  const bool belowMax = maxOpen ? v < max : v <= max;
  return aboveMin && belowMax;
}

std::string NumberRange::describe() const {
  const bool noMin = std::isinf(min);
  const bool noMax = std::isinf(max);
  if (noMin && noMax) return "must be finite";
  if (noMax) return fmt::format("must be {} {}", minOpen ? ">" : ">=", min);
  if (noMin) return fmt::format("must be {} {}", maxOpen ? "<" : "<=", max);
  return fmt::format("must be in {}{}, {}{}", minOpen ? "(" : "[", min, max, maxOpen ? ")" : "]");
}

SourceLocation locationOf(const TomlSource& source, const toml::node& node) {
  return skin::tomlSourceLocation(source.name, node.source());
}

std::string messageWithoutLocation(const SceneError& error) {
  const std::string text = error.what();
  const std::string prefix = error.where().str() + ": ";
  return text.rfind(prefix, 0) == 0 ? text.substr(prefix.size()) : text;
}

TomlTableReader::TomlTableReader(const toml::table& table, std::string label,
                                 const TomlSource& source, std::vector<std::string> knownKeys)
    : table_(table), label_(std::move(label)), source_(source) {
  for (auto&& [key, value] : table_) {
    const std::string k(key.str());
    if (std::find(knownKeys.begin(), knownKeys.end(), k) != knownKeys.end()) continue;
    std::string list;
    for (const auto& known : knownKeys) list += (list.empty() ? "" : ", ") + known;
    throw SceneError(skin::tomlSourceLocation(source_.name, key.source()),
                     fmt::format("unknown key '{}' in {} (known keys: {})", k, label_, list));
  }
}

SourceLocation TomlTableReader::where() const { return locationOf(source_, table_); }

SourceLocation TomlTableReader::whereValue(const std::string& key) const {
  const toml::node* n = table_.get(key);
  return n ? locationOf(source_, *n) : where();
}

const toml::node* TomlTableReader::node(const std::string& key) {
  const toml::node* n = table_.get(key);
  if (n) read_.insert(key);
  return n;
}

void TomlTableReader::fail(const toml::node& at, const std::string& message) const {
  throw SceneError(locationOf(source_, at), message);
}

void TomlTableReader::failHere(const std::string& message) const {
  throw SceneError(where(), message);
}

const toml::node& TomlTableReader::required(const std::string& key) {
  const toml::node* n = node(key);
  if (!n) failHere(fmt::format("missing key '{}' in {}", key, label_));
  return *n;
}

double TomlTableReader::toNumber(const toml::node& n, const std::string& what,
                                 const NumberRange& range) const {
  if (!n.is_number())
    fail(n, fmt::format("{} must be a number, got {}", what, skin::tomlTypeName(n.type())));
  const double value = n.value<double>().value_or(std::nan(""));
  if (!std::isfinite(value)) fail(n, fmt::format("{} = {} is not finite", what, value));
  if (!range.contains(value)) fail(n, fmt::format("{} = {} {}", what, value, range.describe()));
  return value;
}

double TomlTableReader::number(const std::string& key, const NumberRange& range) {
  return toNumber(required(key), "'" + key + "'", range);
}

double TomlTableReader::number(const std::string& key, const NumberRange& range, double fallback) {
  return has(key) ? number(key, range) : fallback;
}

std::int64_t TomlTableReader::integer(const std::string& key, std::int64_t min, std::int64_t max) {
  const toml::node& n = required(key);
  if (!n.is_integer())
    fail(n, fmt::format("'{}' must be an integer, got {}", key, skin::tomlTypeName(n.type())));
  const std::int64_t value = *n.value<std::int64_t>();
  if (value < min || value > max)
    fail(n, fmt::format("'{}' = {} must be in [{}, {}]", key, value, min, max));
  return value;
}

std::int64_t TomlTableReader::integer(const std::string& key, std::int64_t min, std::int64_t max,
                                      std::int64_t fallback) {
  return has(key) ? integer(key, min, max) : fallback;
}

std::string TomlTableReader::string(const std::string& key) {
  const toml::node& n = required(key);
  if (!n.is_string())
    fail(n, fmt::format("'{}' must be a string, got {}", key, skin::tomlTypeName(n.type())));
  return *n.value<std::string>();
}

std::string TomlTableReader::string(const std::string& key, const std::string& fallback) {
  return has(key) ? string(key) : fallback;
}

std::string TomlTableReader::choice(const std::string& key,
                                    const std::vector<std::string>& choices) {
  const std::string value = string(key);
  if (std::find(choices.begin(), choices.end(), value) != choices.end()) return value;
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "\"" : ", \"") + c + "\"";
  fail(*table_.get(key), fmt::format("'{}' = \"{}\" is not one of {}", key, value, list));
}

std::string TomlTableReader::nonEmptyString(const std::string& key) {
  std::string value = string(key);
  if (value.empty()) throw SceneError(whereValue(key), fmt::format("'{}' must not be empty", key));
  return value;
}

bool TomlTableReader::boolean(const std::string& key, bool fallback) {
  const toml::node* n = node(key);
  if (!n) return fallback;
  if (!n->is_boolean())
    fail(*n, fmt::format("'{}' must be a boolean, got {}", key, skin::tomlTypeName(n->type())));
  return *n->value<bool>();
}

std::vector<double> TomlTableReader::numbers(const std::string& key, std::size_t size,
                                             const NumberRange& range) {
  const toml::node& n = required(key);
  const toml::array* array = n.as_array();
  const std::string shape =
      size == 0 ? "an array of numbers" : fmt::format("an array of {} numbers", size);
  if (!array)
    fail(n, fmt::format("'{}' must be {}, got {}", key, shape, skin::tomlTypeName(n.type())));
  if ((size != 0 && array->size() != size) || array->empty())
    fail(n, fmt::format("'{}' must be {}, got {} element(s)", key, shape, array->size()));
  std::vector<double> values;
  for (std::size_t i = 0; i < array->size(); ++i)
    values.push_back(toNumber(*array->get(i), fmt::format("'{}'[{}]", key, i), range));
  return values;
}

glm::dvec3 TomlTableReader::vec3(const std::string& key) {
  const std::vector<double> v = numbers(key, 3, sceneCoordinateRange());
  return {v[0], v[1], v[2]};
}

glm::dvec3 TomlTableReader::vec3(const std::string& key, const glm::dvec3& fallback) {
  return has(key) ? vec3(key) : fallback;
}

std::filesystem::path TomlTableReader::existingFile(const std::string& key) {
  const std::string text = string(key);
  if (text.empty()) fail(*table_.get(key), fmt::format("'{}' must not be empty", key));
  std::filesystem::path path = text;
  if (path.is_relative()) path = source_.baseDir / path;
  path = path.lexically_normal();
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status))
    fail(*table_.get(key),
         fmt::format("'{}': file '{}' does not exist (looked for '{}')", key, text, path.string()));
  if (std::filesystem::is_directory(status))
    fail(*table_.get(key),
         fmt::format("'{}': '{}' is a folder, not a file ('{}')", key, text, path.string()));
  if (!std::filesystem::is_regular_file(status))
    fail(*table_.get(key),
         fmt::format("'{}': '{}' is not a regular file ('{}')", key, text, path.string()));
  return path;
}

const toml::table* TomlTableReader::table(const std::string& key) {
  const toml::node* n = node(key);
  if (!n) return nullptr;
  if (!n->is_table())
    fail(*n, fmt::format("'{}' must be a table, got {}", key, skin::tomlTypeName(n->type())));
  return n->as_table();
}

void TomlTableReader::finish(const std::string& variant) const {
  for (auto&& [key, value] : table_) {
    const std::string k(key.str());
    if (read_.count(k)) continue;
    throw SceneError(skin::tomlSourceLocation(source_.name, key.source()),
                     fmt::format("key '{}' is not used by {}", k, variant));
  }
}

}  // namespace hylios
