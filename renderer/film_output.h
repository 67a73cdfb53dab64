// Writing a film: one multi-band OpenEXR in the spectral layout of Fichet, Pacanowski & Wilkie
// (JCGT 10(3), 2021) — channels "S0.<wavelength with comma decimal separator>nm" plus R, G, B
// preview channels, attributes spectralLayoutVersion = "1.0" and emissiveUnits = "W.m^-2.sr^-1",
// and the samples per pixel — and PNG previews beside it: sRGB of a visible range band
// (CIE 1931 2°, D65 white, documented exposure) and, per single UV/IR band, a pseudo-colour image
// with a fixed scale from the scene and a colour bar. Every file is written to a temporary name
// and renamed (never half-written).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "renderer/film.h"

namespace hylios {

/// "S0.365,000000nm" for 365 nm.
std::string spectralChannelName(double wavelengthNm);

/// Writes `exrPath` and the previews; returns every file written (EXR first).
std::vector<std::filesystem::path> writeFilmOutputs(const Film& film, const std::filesystem::path& exrPath);

/// Pastes PNG panels side by side in a grid with their labels under them (a contact sheet).
void writeContactSheet(const std::vector<std::filesystem::path>& panels,
                       const std::vector<std::string>& labels, const std::filesystem::path& out,
                       int columns);

}  // namespace hylios
