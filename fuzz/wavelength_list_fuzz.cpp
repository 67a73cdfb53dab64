// libFuzzer harness: parseWavelengthList (`--wavelengths`) on arbitrary bytes. Bad input must
// throw a std::exception; an accepted list is non-empty, at most a million entries, inside the
// model's 250–2500 nm, and a start:stop:step range strictly ascends.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>
#include <vector>

#include "app/wavelength_list.h"
#include "fuzz/fuzz_check.h"
#include "skin/spectral_database.h"

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
  for (double w : wavelengths)
    fuzz::require(w >= skin::kModelMinWavelengthNm && w <= skin::kModelMaxWavelengthNm,
                  "inside the model's 250–2500 nm");
  // A start:stop:step range is a grid: its wavelengths must strictly ascend (no repeats).
  const bool isRange = std::memchr(data, ':', size) != nullptr;
  for (std::size_t i = 1; isRange && i < wavelengths.size(); ++i)
    fuzz::require(wavelengths[i] > wavelengths[i - 1], "a range strictly ascends");
  return 0;
}
