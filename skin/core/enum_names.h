// Enumerations named in text (scene-file keys, command-line options): each enum has one table of
// names, and text is parsed once, at the edge, with one error message for every reader:
//
//   enum class SkinMode { Walk, Table };
//   inline constexpr EnumNames<SkinMode, 2> kSkinModeNames{{{SkinMode::Walk, "walk"}, ...}};
//   const SkinMode mode = parseEnum(text, kSkinModeNames, "skin mode");  // throws on other text
//   enumName(mode, kSkinModeNames)  // "walk"
#pragma once
#include <array>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace hylios {

template <typename E>
struct EnumName {
  E value;
  std::string_view name;
};
template <typename E, std::size_t N>
using EnumNames = std::array<EnumName<E>, N>;

/// The value named `text`, or nothing.
template <typename E, std::size_t N>
std::optional<E> findEnum(std::string_view text, const EnumNames<E, N>& names) {
  for (const EnumName<E>& n : names)
    if (n.name == text) return n.value;
  return std::nullopt;
}

/// The names in table order ("walk", "table"), e.g. for a command-line check or a TOML choice.
template <typename E, std::size_t N>
std::vector<std::string> enumNameList(const EnumNames<E, N>& names) {
  std::vector<std::string> list;
  for (const EnumName<E>& n : names) list.emplace_back(n.name);
  return list;
}

/// "\"walk\" or \"table\"" (or "\"a\", \"b\" or \"c\"").
template <typename E, std::size_t N>
std::string enumChoices(const EnumNames<E, N>& names) {
  std::string text;
  for (std::size_t i = 0; i < N; ++i) {
    if (i > 0) text += i + 1 == N ? " or " : ", ";
    text += "\"" + std::string(names[i].name) + "\"";
  }
  return text;
}

/// The value named `text`; throws std::invalid_argument "<what> must be "walk" or "table", got
/// "x"" for any other text.
template <typename E, std::size_t N>
E parseEnum(std::string_view text, const EnumNames<E, N>& names, const std::string& what) {
  if (const std::optional<E> value = findEnum(text, names)) return *value;
  throw std::invalid_argument(what + " must be " + enumChoices(names) + ", got \"" +
                              std::string(text) + "\"");
}

/// The name of `value` ("" if the table lacks it).
template <typename E, std::size_t N>
std::string_view enumName(E value, const EnumNames<E, N>& names) {
  for (const EnumName<E>& n : names)
    if (n.value == value) return n.name;
  return {};
}

}  // namespace hylios
