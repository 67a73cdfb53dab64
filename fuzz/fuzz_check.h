// Shared by the libFuzzer harnesses: turns a broken promise of a parser (NaN accepted, order
// violated, …) into a crash that libFuzzer records, with a message saying which promise.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <string>

namespace hylios::fuzz {

/// Aborts (a fuzzer finding) unless `holds`; `promise` names what the parser guarantees.
inline void require(bool holds, const char* promise) {
  if (holds) return;
  std::fprintf(stderr, "fuzz finding: parser broke its promise: %s\n", promise);
  std::abort();
}

inline std::string asText(const unsigned char* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

}  // namespace hylios::fuzz
