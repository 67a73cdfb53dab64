#include "app/sweep_cases.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace hylios {
namespace {

std::string knownKeys() {
  std::string list;
  for (const auto& k : skin::overrideKeys()) list += (list.empty() ? "" : ", ") + k;
  return list;
}

/// A strict finite number, or false.
bool parseNumber(const std::string& text, double& value) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text.front()))) return false;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return *end == '\0' && std::isfinite(value);
}

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

/// Splits a CSV line at commas, with each field's 1-based column.
std::vector<std::pair<std::string, std::size_t>> fields(const std::string& line) {
  std::vector<std::pair<std::string, std::size_t>> out;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    const std::string raw = line.substr(start, comma == std::string::npos ? comma : comma - start);
    const auto lead = raw.find_first_not_of(" \t");
    out.push_back({trimmed(raw), start + 1 + (lead == std::string::npos ? 0 : lead)});
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

}  // namespace

std::string sweepKey(const std::string& name, const std::string& origin) {
  const auto keys = skin::overrideKeys();
  if (std::find(keys.begin(), keys.end(), name) != keys.end()) return name;
  if (std::find(keys.begin(), keys.end(), name + "_percent") != keys.end())
    return name + "_percent";
  throw std::invalid_argument(
      fmt::format("{}: unknown specimen quantity '{}' (known: {})", origin, name, knownKeys()));
}

std::vector<double> parseSweepRange(const std::string& text, const std::string& origin,
                                    std::size_t maxValues) {
  const auto first = text.find(':');
  const auto second = first == std::string::npos ? first : text.find(':', first + 1);
  if (second == std::string::npos || text.find(':', second + 1) != std::string::npos)
    throw std::invalid_argument(fmt::format("{}: expected LO:HI:STEP, got '{}'", origin, text));
  double lo = 0, hi = 0, step = 0;
  const std::string parts[] = {text.substr(0, first), text.substr(first + 1, second - first - 1),
                               text.substr(second + 1)};
  const char* names[] = {"LO", "HI", "STEP"};
  double* targets[] = {&lo, &hi, &step};
  for (int i = 0; i < 3; ++i)
    if (!parseNumber(parts[i], *targets[i]))
      throw std::invalid_argument(
          fmt::format("{}: {} '{}' is not a finite number", origin, names[i], parts[i]));
  if (!(step > 0)) throw std::invalid_argument(fmt::format("{}: STEP must be positive", origin));
  if (hi < lo) throw std::invalid_argument(fmt::format("{}: HI {} is below LO {}", origin, hi, lo));
  const double span = (hi - lo) / step;
  if (!(span < static_cast<double>(maxValues)))
    throw std::invalid_argument(fmt::format(
        "{}: more than {} values (a sweep of at most that many cases)", origin, maxValues));
  const auto count = static_cast<std::size_t>(std::floor(span + 1e-9)) + 1;
  std::vector<double> values;
  for (std::size_t i = 0; i < count; ++i)
    values.push_back(std::stod(fmt::format("{:.12g}", lo + static_cast<double>(i) * step)));
  return values;
}

SweepCases parseSweepGrid(const std::vector<std::string>& varyTexts, std::size_t maxCases) {
  SweepCases cases;
  std::vector<std::vector<double>> axes;
  for (const std::string& text : varyTexts) {
    const std::string origin = "--vary " + text;
    const auto equals = text.find('=');
    if (equals == std::string::npos || equals == 0)
      throw std::invalid_argument(
          fmt::format("{}: expected NAME=LO:HI:STEP with NAME one of {}", origin, knownKeys()));
    const std::string key = sweepKey(text.substr(0, equals), origin);
    if (std::find(cases.keys.begin(), cases.keys.end(), key) != cases.keys.end())
      throw std::invalid_argument(fmt::format("{}: '{}' is varied twice", origin, key));
    cases.keys.push_back(key);
    axes.push_back(parseSweepRange(text.substr(equals + 1), origin, maxCases));
  }
  std::size_t total = 1;
  for (const auto& axis : axes) {
    if (total > maxCases / axis.size())
      throw std::invalid_argument(fmt::format("the --vary grid has more than {} cases", maxCases));
    total *= axis.size();
  }
  for (std::size_t c = 0; c < total; ++c) {
    std::vector<double> row(axes.size());
    std::size_t rest = c;
    for (std::size_t k = axes.size(); k-- > 0;) {  // the last --vary varies fastest
      row[k] = axes[k][rest % axes[k].size()];
      rest /= axes[k].size();
    }
    std::string origin = "--vary case";
    for (std::size_t k = 0; k < row.size(); ++k)
      origin += fmt::format(" {}={}", cases.keys[k], row[k]);
    cases.values.push_back(std::move(row));
    cases.origins.push_back(origin);
  }
  return cases;
}

SweepCases parseSweepCasesText(const std::string& text, const std::string& sourceName,
                               std::size_t maxCases) {
  SweepCases cases;
  std::istringstream lines(text);
  std::string line;
  std::size_t lineNumber = 0;
  bool header = true;
  while (std::getline(lines, line)) {
    ++lineNumber;
    const std::string content = trimmed(line);
    if (content.empty() || content.front() == '#') continue;
    const auto where = [&](std::size_t column) {
      return fmt::format("{}:{}:{}", sourceName, lineNumber, column);
    };
    const auto row = fields(line);
    if (header) {
      for (const auto& [name, column] : row) {
        if (name.empty()) throw std::invalid_argument(where(column) + ": empty column name");
        const std::string key = sweepKey(name, where(column));
        if (std::find(cases.keys.begin(), cases.keys.end(), key) != cases.keys.end())
          throw std::invalid_argument(fmt::format("{}: '{}' is named twice", where(column), key));
        cases.keys.push_back(key);
      }
      header = false;
      continue;
    }
    if (row.size() != cases.keys.size())
      throw std::invalid_argument(fmt::format("{}: {} values, the header names {} quantities",
                                              where(1), row.size(), cases.keys.size()));
    if (cases.values.size() == maxCases)
      throw std::invalid_argument(fmt::format("{}: more than {} cases", where(1), maxCases));
    std::vector<double> values;
    for (const auto& [field, column] : row) {
      double value = 0;
      if (!parseNumber(field, value))
        throw std::invalid_argument(
            fmt::format("{}: '{}' is not a finite number", where(column), field));
      values.push_back(value);
    }
    cases.values.push_back(std::move(values));
    cases.origins.push_back(where(1));
  }
  if (header) throw std::invalid_argument(sourceName + ": no header line naming the quantities");
  if (cases.values.empty()) throw std::invalid_argument(sourceName + ": no cases after the header");
  return cases;
}

SweepCases loadSweepCasesFile(const std::string& path, std::size_t maxCases) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument("--cases '" + path + "': cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  return parseSweepCasesText(text.str(), path, maxCases);
}

skin::Specimen sweepSpecimen(const skin::Specimen& base, const SweepCases& cases,
                             std::size_t index) {
  skin::Specimen specimen = base;
  for (std::size_t k = 0; k < cases.keys.size(); ++k)
    skin::applyOverride(specimen, {cases.keys[k], cases.values.at(index)[k], cases.origins[index]});
  try {
    skin::validateSpecimen(specimen);
  } catch (const skin::SpecimenError& e) {
    throw skin::SpecimenError(cases.origins[index] + ": " + e.what());
  }
  return specimen;
}

}  // namespace hylios
