#include "app/common_options.h"

#include "app/option_checks.h"
#include "skin/spectral_database.h"

namespace hylios {

CLI::Option* addRaysOption(CLI::App& command, std::uint64_t& rays, const std::string& help,
                           std::uint64_t min, std::uint64_t max) {
  return command.add_option("--rays", rays, help)
      ->check(unsignedRange(min, max))
      ->capture_default_str();
}

CLI::Option* addWavelengthOption(CLI::App& command, double& wavelengthNm) {
  return command.add_option("--wavelength", wavelengthNm, "Wavelength, nm (250–2500)")
      ->check(finiteRange(skin::kModelMinWavelengthNm, skin::kModelMaxWavelengthNm))
      ->capture_default_str();
}

CLI::Option* addAngleOption(CLI::App& command, double& angleDeg) {
  return command
      .add_option("--angle", angleDeg, "Incidence angle from the normal, degrees [0, 90)")
      ->check(finiteRange(0.0, 89.999))
      ->capture_default_str();
}

CLI::Option* addSeedOption(CLI::App& command, std::uint64_t& seed, const std::string& help) {
  return command.add_option("--seed", seed, help)->check(seedRange());
}

CLI::Option* addThreadsOption(CLI::App& command, int& threads) {
  return command.add_option("--threads", threads, "Worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
}

}  // namespace hylios
