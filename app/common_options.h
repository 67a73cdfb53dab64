// Options several commands share, each written once with its check: --rays, --wavelength,
// --angle, --seed, --threads.
// (--estimator: app/estimator_option.h; --skin-model and other enum choices: app/enum_option.h.)
#pragma once
#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace hylios {

/// The help of --seed in the commands whose output depends only on the seed.
inline constexpr const char* kSeedHelp =
    "Random seed in [0, 2^63-1] (same seed, same output at any thread count)";

/// Adds --rays N, a decimal integer in [min, max] (default shown).
CLI::Option* addRaysOption(CLI::App& command, std::uint64_t& rays, const std::string& help,
                           std::uint64_t min = 1, std::uint64_t max = std::uint64_t{1} << 40);
/// Adds --wavelength NM, one wavelength in nm (default shown).
CLI::Option* addWavelengthOption(CLI::App& command, double& wavelengthNm);
/// Adds --angle DEG, the incidence angle from the normal in [0, 90) (default shown).
CLI::Option* addAngleOption(CLI::App& command, double& angleDeg);
/// Adds --seed K in [0, 2^63-1] (option_checks.h: seedRange).
CLI::Option* addSeedOption(CLI::App& command, std::uint64_t& seed,
                           const std::string& help = kSeedHelp);
/// Adds --threads N in [1, 1024] ("Worker threads (default: all cores)"; 0, the default, means all
/// cores and is not accepted on the command line).
CLI::Option* addThreadsOption(CLI::App& command, int& threads);

}  // namespace hylios
