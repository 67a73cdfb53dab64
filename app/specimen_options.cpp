#include "app/specimen_options.h"

#include <cmath>
#include <cstdlib>

#include "renderer/scene/data_paths.h"

namespace hylios {
namespace {

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const auto& word : words) text += (text.empty() ? "" : ", ") + word;
  return text;
}

skin::SpecimenOverride parseOverride(const std::string& text) {
  const std::string origin = "--set " + text;
  const auto equals = text.find('=');
  if (equals == std::string::npos || equals == 0)
    throw skin::SpecimenError(origin + ": expected KEY=VALUE with KEY one of " +
                              joined(skin::overrideKeys()));
  const std::string valueText = text.substr(equals + 1);
  char* end = nullptr;
  const double value = std::strtod(valueText.c_str(), &end);
  if (valueText.empty() || *end != '\0' || !std::isfinite(value))
    throw skin::SpecimenError(origin + ": '" + valueText + "' is not a finite number");
  return {text.substr(0, equals), value, origin};
}

}  // namespace

void addSpecimenOptions(CLI::App& command, SpecimenOptions& options) {
  command
      .add_option("--specimen", options.specimen,
                  "Specimen S1..S4 (paper Table 1) or a specimen file path")
      ->capture_default_str();
  addOverrideOption(command, options);
}

void addOverrideOption(CLI::App& command, SpecimenOptions& options) {
  command.add_option("--set", options.overrides,
                     "Override KEY=VALUE, repeatable; keys: " + joined(skin::overrideKeys()));
}

skin::Specimen loadSpecimenWithOverrides(const SpecimenOptions& options) {
  skin::Specimen specimen = skin::loadSpecimen(options.specimen, specimenDir());
  applyOverrides(specimen, options.overrides);
  return specimen;
}

void applyOverrides(skin::Specimen& specimen, const std::vector<std::string>& overrides) {
  for (const auto& text : overrides) skin::applyOverride(specimen, parseOverride(text));
}

}  // namespace hylios
