#include "skin/core/content_hash.h"

#include <cstring>

namespace hylios::skin {

ContentHash& ContentHash::addBytes(const void* data, std::size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    state_ ^= bytes[i];
    state_ *= kPrime;
  }
  return *this;
}

ContentHash& ContentHash::addU64(std::uint64_t value) {
  unsigned char bytes[8];
  for (int i = 0; i < 8; ++i) bytes[i] = static_cast<unsigned char>(value >> (8 * i));
  return addBytes(bytes, sizeof bytes);
}

ContentHash& ContentHash::addDouble(double value) {
  std::uint64_t bits = 0;
  static_assert(sizeof bits == sizeof value, "IEEE-754 binary64 expected");
  std::memcpy(&bits, &value, sizeof bits);
  return addU64(bits);
}

ContentHash& ContentHash::addString(std::string_view text) {
  addU64(text.size());
  return addBytes(text.data(), text.size());
}

std::uint64_t fnv1a64(const void* data, std::size_t size) {
  return ContentHash().addBytes(data, size).value();
}

std::string hex64(std::uint64_t value) {
  static const char* digits = "0123456789abcdef";
  std::string text(16, '0');
  for (int i = 15; i >= 0; --i, value >>= 4)
    text[static_cast<std::size_t>(i)] = digits[value & 0xf];
  return text;
}

}  // namespace hylios::skin
