// Strict reading of one TOML table for the scene file: typed getters that record which keys were
// read, so that a key nobody read is an error. Every error is a SceneError at the position of
// the offending key or value (file:line:col).
//
// Two kinds of stray key: one that no variant of the table knows (a typo: "unknown key", listed
// with the keys there are) is refused as soon as the reader is made; one that another variant
// uses but this one does not ("radius" on a mesh) is refused by finish().
#pragma once
#include <glm/glm.hpp>
#include <toml++/toml.h>

#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "renderer/scene/scene.h"

namespace hylios {

/// Admissible values of a number, with the phrase used in messages.
struct NumberRange {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool minOpen = false;  ///< min itself excluded
  bool maxOpen = false;  ///< max itself excluded

  static NumberRange any() { return {}; }
  static NumberRange positive() { return {0, std::numeric_limits<double>::infinity(), true}; }
  static NumberRange nonNegative() { return {0, std::numeric_limits<double>::infinity()}; }
  static NumberRange closed(double lo, double hi) { return {lo, hi}; }
  bool contains(double v) const;
  std::string describe() const;  ///< e.g. "must be in (0, 180)"
};

/// The scene extent limit (docs/scene-format.md, "Limits"): every coordinate, direction
/// component, size and distance a scene file gives is at most this many scene units in
/// magnitude, so that every ray the renderer makes stays well inside Embree's single-precision
/// range (|x| < 1.8e18) and its relative precision.
constexpr double kMaxSceneCoordinate = 1e7;
/// [-kMaxSceneCoordinate, kMaxSceneCoordinate].
inline NumberRange sceneCoordinateRange() {
  return NumberRange::closed(-kMaxSceneCoordinate, kMaxSceneCoordinate);
}
/// (0, kMaxSceneCoordinate].
inline NumberRange sceneSizeRange() { return {0, kMaxSceneCoordinate, true, false}; }
/// [0, kMaxSceneCoordinate].
inline NumberRange sceneLengthRange() { return NumberRange::closed(0, kMaxSceneCoordinate); }

/// The file a table came from: its name in messages and the folder relative paths resolve in.
struct TomlSource {
  std::string name;
  std::filesystem::path baseDir;
};

/// Position of a node in `source`.
SourceLocation locationOf(const TomlSource& source, const toml::node& node);
/// SceneError's message without its "file:line:col: " prefix.
std::string messageWithoutLocation(const SceneError& error);

class TomlTableReader {
 public:
  /// `label` names the table in messages ("[camera]", "[[shape]] 'head'"); `knownKeys` lists
  /// every key any variant of the table accepts. Throws for a key outside `knownKeys`.
  TomlTableReader(const toml::table& table, std::string label, const TomlSource& source,
                  std::vector<std::string> knownKeys);

  const std::string& label() const { return label_; }
  const TomlSource& source() const { return source_; }
  SourceLocation where() const;                             ///< the table's own position
  SourceLocation whereValue(const std::string& key) const;  ///< the value's, else the table's
  bool has(const std::string& key) const { return table_.get(key) != nullptr; }

  /// The node under `key` (nullptr if absent), marked as read.
  const toml::node* node(const std::string& key);
  [[noreturn]] void fail(const toml::node& at, const std::string& message) const;
  [[noreturn]] void failHere(const std::string& message) const;  ///< at the table

  double number(const std::string& key, const NumberRange& range);  ///< required
  double number(const std::string& key, const NumberRange& range, double fallback);
  std::int64_t integer(const std::string& key, std::int64_t min, std::int64_t max);
  std::int64_t integer(const std::string& key, std::int64_t min, std::int64_t max,
                       std::int64_t fallback);
  std::string string(const std::string& key);  ///< required
  std::string string(const std::string& key, const std::string& fallback);
  /// Required and not "" ("'key' must not be empty" at the value otherwise).
  std::string nonEmptyString(const std::string& key);
  /// One of `choices`; the message lists them.
  std::string choice(const std::string& key, const std::vector<std::string>& choices);
  bool boolean(const std::string& key, bool fallback);
  /// Required; three finite numbers in sceneCoordinateRange() (positions and directions alike).
  glm::dvec3 vec3(const std::string& key);
  glm::dvec3 vec3(const std::string& key, const glm::dvec3& fallback);
  /// An array of finite numbers in `range`; `size` 0 = any length (at least one element).
  std::vector<double> numbers(const std::string& key, std::size_t size, const NumberRange& range);
  /// A file that must exist; relative paths resolve against the source's folder.
  std::filesystem::path existingFile(const std::string& key);
  /// A table (inline or not); nullptr if absent.
  const toml::table* table(const std::string& key);

  /// Throws for a key that was never read: "'radius' is not used by <variant>".
  void finish(const std::string& variant) const;

  /// Checks that `node` is a finite number in `range`; `what` names it in messages.
  double toNumber(const toml::node& node, const std::string& what, const NumberRange& range) const;

 private:
  const toml::node& required(const std::string& key);

  const toml::table& table_;
  std::string label_;
  TomlSource source_;
  std::set<std::string> read_;
};

}  // namespace hylios
