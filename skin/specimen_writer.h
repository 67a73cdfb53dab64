// Writes a specimen as a specimen file (the layout of scenes/specimens/S1.toml) that
// loadSpecimen/parseSpecimen read back: every key of the schema in skin/specimen.cpp, units in the
// key names, fractions written as percent. Used by `hylios fit` to save a fitted specimen.
#pragma once
#include <string>

#include "skin/specimen.h"

namespace hylios::skin {

/// The TOML text of `specimen`. `header` (may be empty, may span lines) is written first as
/// comment lines. Numbers are written in the shortest form that reads back to the same double
/// (percent keys: 100 × the stored fraction, which reads back within one rounding).
/// The epidermal Table 2 values ([epidermis]) are taken from the stratum basale.
std::string formatSpecimenToml(const Specimen& specimen, const std::string& header = "");

}  // namespace hylios::skin
