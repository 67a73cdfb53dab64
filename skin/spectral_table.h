// A numeric table indexed by wavelength, read from a CSV file (one header row, then one row per
// wavelength, ascending), with linear interpolation between rows.
//
// Every error names the file and, where there is one, the line: a missing file, a row with the
// wrong number of fields, a field that is not a finite number, a wavelength that does not ascend.
// Interpolation outside the table's wavelengths throws; nothing is clamped.
#pragma once
#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace hylios::skin {

class SpectralTableError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What to do with rows that repeat the previous row's wavelength.
enum class DuplicateWavelengths {
  Reject,   ///< an error naming file:line (the default: a table must strictly ascend)
  Average,  ///< replace each run of equal wavelengths by one row holding the mean of every column
};

/// What to do with a row that has a value spelled "NaN" (a source's marker for "no value").
enum class MissingValues {
  Reject,   ///< an error naming file:line (the default)
  DropRow,  ///< skip the row; any other non-numeric field is still an error
};

class SpectralTable {
 public:
  /// Reads `file`. The first column is the wavelength in nm; the header names every column.
  static SpectralTable loadCsv(const std::filesystem::path& file,
                               DuplicateWavelengths duplicates = DuplicateWavelengths::Reject,
                               MissingValues missing = MissingValues::Reject);
  /// Parses CSV text from `in` exactly as loadCsv does; `sourceName` stands for the file in
  /// messages and in sourceName().
  static SpectralTable parseCsv(std::istream& in, const std::string& sourceName,
                                DuplicateWavelengths duplicates = DuplicateWavelengths::Reject,
                                MissingValues missing = MissingValues::Reject);

  /// A table from samples (`columns[c][row]`); `sourceName` appears in error messages.
  /// Throws SpectralTableError unless wavelengths strictly ascend and every column matches them.
  SpectralTable(std::string sourceName, std::vector<std::string> columnNames,
                std::vector<double> wavelengthsNm, std::vector<std::vector<double>> columns);

  const std::string& sourceName() const { return sourceName_; }
  /// Names of the value columns (the wavelength column excluded).
  const std::vector<std::string>& columnNames() const { return columnNames_; }
  std::size_t columnIndex(std::string_view name) const;  ///< throws, listing the names there are
  std::size_t rowCount() const { return wavelengthsNm_.size(); }
  const std::vector<double>& wavelengthsNm() const { return wavelengthsNm_; }
  const std::vector<double>& column(std::size_t columnIdx) const;

  double minWavelengthNm() const { return wavelengthsNm_.front(); }
  double maxWavelengthNm() const { return wavelengthsNm_.back(); }
  bool covers(double wavelengthNm) const;

  /// Linear interpolation of column `columnIdx` at `wavelengthNm`; throws outside the table.
  double interpolate(std::size_t columnIdx, double wavelengthNm) const;

  /// The rows whose wavelength lies in [minNm, maxNm] (throws if fewer than one remains).
  SpectralTable rowsWithin(double minNm, double maxNm) const;

 private:
  std::string sourceName_;
  std::vector<std::string> columnNames_;
  std::vector<double> wavelengthsNm_;
  std::vector<std::vector<double>> columns_;
};

}  // namespace hylios::skin
