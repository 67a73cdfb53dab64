// A 64-bit content hash (FNV-1a, Fowler–Noll–Vo) over a fixed sequence of values, used to key
// cached tables (skin/exit_table.h) by every input they were computed from.
//
// Values are fed as bytes in a fixed, platform-independent order: integers as 8 little-endian
// bytes, doubles as the 8 little-endian bytes of their IEEE-754 bit pattern, strings as their
// length followed by their bytes. FNV-1a: h = 14695981039346656037; for each byte b:
// h = (h XOR b) · 1099511628211 (mod 2^64). Not a cryptographic hash: it detects changed inputs
// and accidental corruption, not deliberate tampering.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace hylios::skin {

class ContentHash {
 public:
  static constexpr std::uint64_t kOffsetBasis = 14695981039346656037ULL;
  static constexpr std::uint64_t kPrime = 1099511628211ULL;

  ContentHash& addBytes(const void* data, std::size_t size);
  ContentHash& addU64(std::uint64_t value);
  ContentHash& addDouble(double value);
  ContentHash& addBool(bool value) { return addU64(value ? 1 : 0); }
  ContentHash& addString(std::string_view text);

  std::uint64_t value() const { return state_; }

 private:
  std::uint64_t state_ = kOffsetBasis;
};

/// FNV-1a 64 of a byte range (the same as ContentHash().addBytes(data, size).value()).
std::uint64_t fnv1a64(const void* data, std::size_t size);

/// 16 lower-case hex digits.
std::string hex64(std::uint64_t value);

}  // namespace hylios::skin
