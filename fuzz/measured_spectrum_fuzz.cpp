// libFuzzer harness: parseMeasuredSpectrum on arbitrary bytes. The first line is the COLUMN
// selector (name, prefix or 1-based number), the rest the CSV text. Bad input must throw a
// std::exception; a spectrum it returns must ascend, be finite, and interpolate inside its range.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <sstream>
#include <string>

#include "app/measured_spectrum.h"
#include "fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hylios;
  const std::string text = fuzz::asText(data, size);
  const std::size_t newline = text.find('\n');
  if (newline == std::string::npos) return 0;
  std::istringstream csv(text.substr(newline + 1));
  MeasuredSpectrum spectrum;
  try {
    spectrum = parseMeasuredSpectrum(csv, text.substr(0, newline), "fuzz.csv");
  } catch (const std::exception&) {
    return 0;
  }
  const auto& w = spectrum.wavelengthNm;
  fuzz::require(w.size() >= 2 && w.size() == spectrum.value.size(),
                "at least two rows, one value per wavelength");
  for (std::size_t i = 0; i < w.size(); ++i) {
    fuzz::require(std::isfinite(w[i]) && std::isfinite(spectrum.value[i]), "finite samples");
    fuzz::require(i == 0 || w[i] > w[i - 1], "wavelengths strictly ascend");
  }
  bool moderate = std::isfinite(w.back() - w.front());
  for (double v : spectrum.value) moderate = moderate && std::fabs(v) < 1e300;
  if (!moderate) return 0;  // differences could overflow; nothing more to promise
  try {
    fuzz::require(std::isfinite(spectrum.at(w.back())), "value at the last wavelength is finite");
    fuzz::require(std::isfinite(spectrum.at(w.front() + 0.5 * (w.back() - w.front()))),
                  "interpolation inside is finite");
  } catch (const std::exception&) {
    fuzz::require(false, "at() inside the covered range does not throw");
  }
  return 0;
}
