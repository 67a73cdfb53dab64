// Spectra in scene files: the `emission` table of a light and the `reflectance` of a diffuse
// material (number or table), read strictly into EmissionDesc (docs/scene-format.md), and the
// check that a spectrum is defined at every wavelength the film's bands ask for.
#pragma once
#include <toml++/toml.h>

#include <string>

#include "renderer/scene/scene.h"
#include "renderer/scene/toml_table_reader.h"

namespace hylios {

/// A spectrum table: `type` = constant | d65 | blackbody | led | tabulated, and its parameters.
EmissionDesc readSpectrum(const toml::table& table, const std::string& label,
                          const TomlSource& source);
/// The required `emission` table of a light.
EmissionDesc readEmission(TomlTableReader& light);
/// The required `reflectance` of a diffuse material: a number in [0, 1] or a spectrum table that
/// stays within [0, 1] ("d65" refused).
EmissionDesc readReflectance(TomlTableReader& material);
/// Throws SceneError (at the spectrum) unless `emission` is defined at every channel wavelength
/// and both ends of every band of `film`.
void checkCoversBands(const EmissionDesc& emission, const FilmDesc& film);

}  // namespace hylios
