// A value's bytes appended to, or read back from, a byte string (native byte order): the state
// that tallies and films send between processes of the same machine type (app/mpi_session.h).
#pragma once
#include <cstddef>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace hylios::skin {

template <class T>
void putBytes(std::string& bytes, const T& value) {
  static_assert(std::is_trivially_copyable_v<T>);
  bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}

/// The value at `offset` (moved past it). Throws std::invalid_argument naming `reader` when the
/// bytes end early.
template <class T>
T takeBytes(const std::string& bytes, std::size_t& offset, const char* reader) {
  static_assert(std::is_trivially_copyable_v<T>);
  if (offset > bytes.size() || bytes.size() - offset < sizeof(T))
    throw std::invalid_argument(std::string(reader) + ": the state ends early (byte " +
                                std::to_string(offset) + " of " + std::to_string(bytes.size()) +
                                ")");
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof value);
  offset += sizeof value;
  return value;
}

}  // namespace hylios::skin
