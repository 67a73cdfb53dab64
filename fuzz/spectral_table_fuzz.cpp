// libFuzzer harness: skin::SpectralTable::parseCsv on arbitrary bytes. The first byte picks the
// duplicate/missing-value policies; the rest is the CSV text. Bad input must throw a
// std::exception; a table it returns must have finite, strictly ascending wavelengths, finite
// values, and interpolate to finite values inside its range.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <sstream>

#include "fuzz/fuzz_check.h"
#include "skin/spectral_table.h"

namespace {

void checkTable(const hylios::skin::SpectralTable& table) {
  using hylios::fuzz::require;
  const auto& w = table.wavelengthsNm();
  require(!w.empty() && w.size() == table.rowCount(), "a table has rows");
  for (std::size_t i = 0; i < w.size(); ++i) {
    require(std::isfinite(w[i]), "wavelengths are finite");
    require(i == 0 || w[i] > w[i - 1], "wavelengths strictly ascend");
  }
  for (std::size_t c = 0; c < table.columnNames().size(); ++c) {
    const auto& column = table.column(c);
    require(column.size() == w.size(), "every column has one value per wavelength");
    bool moderate = std::isfinite(table.maxWavelengthNm() - table.minWavelengthNm());
    for (double v : column) {
      require(std::isfinite(v), "values are finite");
      moderate = moderate && std::fabs(v) < 1e300;
    }
    // With moderate numbers (no overflow in differences) interpolation must give a number.
    if (!moderate) continue;
    const double middle =
        table.minWavelengthNm() + 0.5 * (table.maxWavelengthNm() - table.minWavelengthNm());
    require(std::isfinite(table.interpolate(c, middle)), "interpolation inside is finite");
    require(std::isfinite(table.interpolate(c, table.maxWavelengthNm())),
            "interpolation at the last wavelength is finite");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hylios;
  if (size == 0) return 0;
  const auto duplicates =
      (data[0] & 1) ? skin::DuplicateWavelengths::Average : skin::DuplicateWavelengths::Reject;
  const auto missing = (data[0] & 2) ? skin::MissingValues::DropRow : skin::MissingValues::Reject;
  std::istringstream csv(fuzz::asText(data + 1, size - 1));
  try {
    const skin::SpectralTable table =
        skin::SpectralTable::parseCsv(csv, "fuzz.csv", duplicates, missing);
    checkTable(table);
  } catch (const std::exception&) {
    // rejected with a message: fine
  }
  return 0;
}
