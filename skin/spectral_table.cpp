#include "skin/spectral_table.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <utility>

namespace hylios::skin {
namespace {

std::string_view trim(std::string_view s) {
  const auto isSpace = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (!s.empty() && isSpace(s.front())) s.remove_prefix(1);
  while (!s.empty() && isSpace(s.back())) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> splitFields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(
        trim(line.substr(start, comma == std::string_view::npos ? comma : comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

/// Parses a whole field as a finite number, or returns false.
bool parseNumber(std::string_view field, double& value) {
  if (field.empty()) return false;
  const std::string text(field);
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && errno != ERANGE && std::isfinite(value);
}

bool isNanMarker(std::string_view field) {
  return field.size() == 3 && (field[0] == 'n' || field[0] == 'N') &&
         (field[1] == 'a' || field[1] == 'A') && (field[2] == 'n' || field[2] == 'N');
}

struct ParsedRow {
  double wavelengthNm;
  std::vector<double> values;
  std::size_t line;
};

/// Folds each run of equal wavelengths into one row holding the mean of every column.
std::vector<ParsedRow> averageDuplicates(const std::vector<ParsedRow>& rows) {
  std::vector<ParsedRow> merged;
  std::size_t runLength = 0;
  for (const ParsedRow& row : rows) {
    if (!merged.empty() && merged.back().wavelengthNm == row.wavelengthNm) {
      ParsedRow& sum = merged.back();
      ++runLength;
      for (std::size_t c = 0; c < row.values.size(); ++c)
        sum.values[c] += (row.values[c] - sum.values[c]) / static_cast<double>(runLength);
    } else {
      merged.push_back(row);
      runLength = 1;
    }
  }
  return merged;
}

}  // namespace

SpectralTable SpectralTable::loadCsv(const std::filesystem::path& file,
                                     DuplicateWavelengths duplicates, MissingValues missing) {
  const std::string name = file.string();
  std::ifstream in(file);
  if (!in) throw SpectralTableError(fmt::format("{}: cannot open the spectral table file", name));
  return parseCsv(in, name, duplicates, missing);
}

SpectralTable SpectralTable::parseCsv(std::istream& in, const std::string& name,
                                      DuplicateWavelengths duplicates, MissingValues missing) {
  std::vector<std::string> header;
  std::vector<ParsedRow> rows;
  std::string line;
  for (std::size_t lineNo = 1; std::getline(in, line); ++lineNo) {
    if (trim(line).empty()) continue;
    const std::vector<std::string_view> fields = splitFields(line);
    if (header.empty()) {
      if (fields.size() < 2)
        throw SpectralTableError(fmt::format(
            "{}:{}: the header must name a wavelength column and at least one value column", name,
            lineNo));
      for (std::string_view f : fields) {
        if (f.empty())
          throw SpectralTableError(fmt::format("{}:{}: empty column name in header", name, lineNo));
        header.emplace_back(f);
      }
      continue;
    }
    if (fields.size() != header.size())
      throw SpectralTableError(fmt::format("{}:{}: {} fields, but the header has {} columns", name,
                                           lineNo, fields.size(), header.size()));
    if (missing == MissingValues::DropRow && std::any_of(fields.begin(), fields.end(), isNanMarker))
      continue;
    ParsedRow row{0.0, std::vector<double>(fields.size() - 1), lineNo};
    for (std::size_t c = 0; c < fields.size(); ++c) {
      double value = 0;
      if (!parseNumber(fields[c], value))
        throw SpectralTableError(fmt::format("{}:{}: '{}' in column '{}' is not a finite number",
                                             name, lineNo, fields[c], header[c]));
      (c == 0 ? row.wavelengthNm : row.values[c - 1]) = value;
    }
    if (!rows.empty()) {
      const ParsedRow& previous = rows.back();
      const bool equal = row.wavelengthNm == previous.wavelengthNm;
      if (row.wavelengthNm < previous.wavelengthNm ||
          (equal && duplicates == DuplicateWavelengths::Reject))
        throw SpectralTableError(
            fmt::format("{}:{}: wavelength {} nm does not ascend (line {} has {} nm)", name, lineNo,
                        row.wavelengthNm, previous.line, previous.wavelengthNm));
    }
    rows.push_back(std::move(row));
  }
  if (header.empty()) throw SpectralTableError(fmt::format("{}: the file is empty", name));
  if (rows.empty())
    throw SpectralTableError(fmt::format("{}: no data rows after the header", name));
  if (duplicates == DuplicateWavelengths::Average) rows = averageDuplicates(rows);

  std::vector<double> wavelengths;
  std::vector<std::vector<double>> columns(header.size() - 1);
  for (const ParsedRow& row : rows) {
    wavelengths.push_back(row.wavelengthNm);
    for (std::size_t c = 0; c < row.values.size(); ++c) columns[c].push_back(row.values[c]);
  }
  return SpectralTable(name, std::vector<std::string>(header.begin() + 1, header.end()),
                       std::move(wavelengths), std::move(columns));
}

SpectralTable::SpectralTable(std::string sourceName, std::vector<std::string> columnNames,
                             std::vector<double> wavelengthsNm,
                             std::vector<std::vector<double>> columns)
    : sourceName_(std::move(sourceName)),
      columnNames_(std::move(columnNames)),
      wavelengthsNm_(std::move(wavelengthsNm)),
      columns_(std::move(columns)) {
  if (wavelengthsNm_.empty())
    throw SpectralTableError(
        fmt::format("{}: a spectral table needs at least one row", sourceName_));
  if (columns_.size() != columnNames_.size() || columns_.empty())
    throw SpectralTableError(fmt::format("{}: {} value columns but {} column names", sourceName_,
                                         columns_.size(), columnNames_.size()));
  for (std::size_t c = 0; c < columns_.size(); ++c)
    if (columns_[c].size() != wavelengthsNm_.size())
      throw SpectralTableError(fmt::format("{}: column '{}' has {} values for {} wavelengths",
                                           sourceName_, columnNames_[c], columns_[c].size(),
                                           wavelengthsNm_.size()));
  for (std::size_t i = 1; i < wavelengthsNm_.size(); ++i)
    if (!(wavelengthsNm_[i] > wavelengthsNm_[i - 1]))
      throw SpectralTableError(fmt::format("{}: wavelength {} nm (row {}) does not ascend",
                                           sourceName_, wavelengthsNm_[i], i + 1));
}

std::size_t SpectralTable::columnIndex(std::string_view name) const {
  const auto it = std::find(columnNames_.begin(), columnNames_.end(), name);
  if (it == columnNames_.end())
    throw SpectralTableError(fmt::format("{}: no column '{}' (columns: {})", sourceName_, name,
                                         fmt::join(columnNames_, ", ")));
  return static_cast<std::size_t>(it - columnNames_.begin());
}

const std::vector<double>& SpectralTable::column(std::size_t columnIdx) const {
  if (columnIdx >= columns_.size())
    throw SpectralTableError(fmt::format("{}: column index {} out of range ({} value columns)",
                                         sourceName_, columnIdx, columns_.size()));
  return columns_[columnIdx];
}

bool SpectralTable::covers(double wavelengthNm) const {
  return wavelengthNm >= minWavelengthNm() && wavelengthNm <= maxWavelengthNm();
}

double SpectralTable::interpolate(std::size_t columnIdx, double wavelengthNm) const {
  const std::vector<double>& values = column(columnIdx);
  if (!covers(wavelengthNm))
    throw SpectralTableError(fmt::format("{}: {} nm is outside the table's {}–{} nm", sourceName_,
                                         wavelengthNm, minWavelengthNm(), maxWavelengthNm()));
  const auto upper = std::lower_bound(wavelengthsNm_.begin(), wavelengthsNm_.end(), wavelengthNm);
  const auto i = static_cast<std::size_t>(upper - wavelengthsNm_.begin());
  if (wavelengthsNm_[i] == wavelengthNm) return values[i];
  const double t =
      (wavelengthNm - wavelengthsNm_[i - 1]) / (wavelengthsNm_[i] - wavelengthsNm_[i - 1]);
  return values[i - 1] + t * (values[i] - values[i - 1]);
}

SpectralTable SpectralTable::rowsWithin(double minNm, double maxNm) const {
  std::vector<double> wavelengths;
  std::vector<std::vector<double>> columns(columns_.size());
  for (std::size_t i = 0; i < wavelengthsNm_.size(); ++i) {
    if (wavelengthsNm_[i] < minNm || wavelengthsNm_[i] > maxNm) continue;
    wavelengths.push_back(wavelengthsNm_[i]);
    for (std::size_t c = 0; c < columns_.size(); ++c) columns[c].push_back(columns_[c][i]);
  }
  if (wavelengths.empty())
    throw SpectralTableError(fmt::format("{}: no rows within {}–{} nm", sourceName_, minNm, maxNm));
  return SpectralTable(sourceName_, columnNames_, std::move(wavelengths), std::move(columns));
}

}  // namespace hylios::skin
