// Parses wavelength lists given on the command line: "start:stop:step" (inclusive of stop when it
// falls on the grid) or "400,550,700". Values in nm, inside the model's domain; errors name the
// offending token.
#pragma once
#include <string>
#include <vector>

namespace hylios {

/// Throws std::invalid_argument with a message such as
/// "--wavelengths '250:2500:0': step must be positive", and for a wavelength outside the model's
/// 250–2500 nm (skin::kModelMinWavelengthNm, kModelMaxWavelengthNm).
std::vector<double> parseWavelengthList(const std::string& text);
/// A wavelength as written in CSVs: the shortest text that reads back as the same double
/// ("550.0001", "2499.9975", "550"), so that distinct wavelengths never print alike.
std::string formatWavelength(double nm);

}  // namespace hylios
