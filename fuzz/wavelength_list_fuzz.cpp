// libFuzzer harness: parseWavelengthList (`--wavelengths`) on arbitrary bytes. Bad input must
// throw a std::exception; an accepted list is non-empty, at most a million entries, finite and > 0.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <vector>

#include "fuzz/fuzz_check.h"
#include "renderer/wavelength_list.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hylios;
  std::vector<double> wavelengths;
  try {
    wavelengths = parseWavelengthList(fuzz::asText(data, size));
  } catch (const std::exception&) {
    return 0;
  }
  fuzz::require(!wavelengths.empty() && wavelengths.size() <= 1000000,
                "between 1 and a million wavelengths");
  for (double w : wavelengths) fuzz::require(std::isfinite(w) && w > 0, "finite and > 0 nm");
  return 0;
}
