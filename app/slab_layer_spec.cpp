#include "app/slab_layer_spec.h"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>

namespace hylios {
namespace {

[[noreturn]] void fail(const std::string& spec, const std::string& what) {
  throw std::invalid_argument("--layer '" + spec + "': " + what);
}

double parseNumber(const std::string& spec, const std::string& key, const std::string& text) {
  if (text.empty()) fail(spec, "key '" + key + "' has no value");
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  if (end != begin + text.size() || errno == ERANGE)
    fail(spec, "'" + key + "=" + text + "' is not a number");
  if (std::isnan(value)) fail(spec, "'" + key + "=" + text + "' is NaN");
  if (std::isinf(value) && !(key == "d" && value > 0))
    fail(spec, "'" + key + "=" + text + "' is infinite (only d may be inf)");
  return value;
}

}  // namespace

skin::SlabLayer parseSlabLayerSpec(const std::string& spec) {
  static const char* const kKeys[] = {"n", "mua", "mus", "g", "d"};
  std::map<std::string, double> values;
  std::istringstream tokens(spec);
  std::string token;
  while (std::getline(tokens, token, ',')) {
    const std::size_t eq = token.find('=');
    if (eq == std::string::npos) fail(spec, "token '" + token + "' is not key=value");
    const std::string key = token.substr(0, eq);
    bool known = false;
    for (const char* k : kKeys) known = known || key == k;
    if (!known) fail(spec, "unknown key '" + key + "' (expected n, mua, mus, g, d)");
    if (values.count(key)) fail(spec, "key '" + key + "' given twice");
    values[key] = parseNumber(spec, key, token.substr(eq + 1));
  }
  for (const char* k : kKeys)
    if (!values.count(k)) fail(spec, std::string("missing key '") + k + "'");
  for (const char* k : {"mua", "mus", "d"})
    if (values[k] < 0)
      fail(spec, std::string("'") + k + "' must be >= 0, got " + fmt::format("{:g}", values[k]));
  if (values["n"] <= 0) fail(spec, fmt::format("'n' must be > 0, got {:g}", values["n"]));
  if (!(values["g"] > -1 && values["g"] < 1))
    fail(spec, fmt::format("'g' must be in (-1, 1), got {:g}", values["g"]));
  return {values["n"], values["mua"], values["mus"], values["g"], values["d"]};
}

}  // namespace hylios
