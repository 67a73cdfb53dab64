// Parses wavelength lists given on the command line: "start:stop:step" (inclusive of stop when it
// falls on the grid) or "400,550,700". Values in nm; errors name the offending token.
#pragma once
#include <string>
#include <vector>

namespace hylios {

/// Throws std::invalid_argument with a message such as
/// "--wavelengths '250:2500:0': step must be positive".
std::vector<double> parseWavelengthList(const std::string& text);

}  // namespace hylios
