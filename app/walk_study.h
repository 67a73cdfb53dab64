// What the commands that walk one specimen share (brdf, forward-profile, radial-profile): the
// options --specimen/--set, --estimator, --rays, --seed, --threads, --out and --plot, and the start
// of a run (outputs checked before any work, the thread limit, the specimen and spectra loaded).
#pragma once
#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "app/option_checks.h"
#include "app/specimen_options.h"
#include "skin/core/thread_limit.h"
#include "skin/estimator.h"
#include "skin/skin_optics.h"
#include "skin/skin_simulation.h"
#include "skin/specimen.h"
#include "skin/spectral_database.h"

namespace hylios {

struct WalkStudyOptions {
  SpecimenOptions specimen;
  skin::Estimator estimator = skin::Estimator::Spectral;
  std::uint64_t rays = 100000;
  std::uint64_t seed = 1;
  int threads = 0;   ///< 0: all cores
  std::string out;   ///< the CSV to write
  std::string plot;  ///< the PNG to write; "": none
};

/// Adds --specimen and --set, --estimator, --rays (`raysHelp`), --seed and --threads.
void addWalkStudyOptions(CLI::App& command, WalkStudyOptions& options, const std::string& raysHelp);
/// Adds --out (required; `outHelp`) and --plot (`plotHelp`).
void addStudyOutputOptions(CLI::App& command, WalkStudyOptions& options, const std::string& outHelp,
                           const std::string& plotHelp);

/// A run's start, in order: the outputs checked (--out, --plot; not one of --specimen's file or
/// `inputs`), the thread limit (held for the life of the object), the specimen with its overrides
/// and the spectral database loaded.
class WalkStudy {
 public:
  explicit WalkStudy(const WalkStudyOptions& options, const std::vector<NamedPath>& inputs = {});

  const skin::Specimen& specimen() const { return specimen_; }
  /// The optics at one wavelength.
  skin::SkinOptics optics(double wavelengthNm) const;
  /// The optics at each wavelength, all computed before any walk (a bad wavelength fails first).
  std::vector<skin::SkinOptics> optics(const std::vector<double>& wavelengths) const;
  /// The options' rays and seed at `incidenceDeg`.
  skin::WalkRunOptions run(double incidenceDeg) const;

 private:
  struct OutputsChecked {
    OutputsChecked(const WalkStudyOptions& options, const std::vector<NamedPath>& inputs);
  };
  const WalkStudyOptions& options_;
  OutputsChecked checked_;
  ThreadLimit threadLimit_;
  skin::Specimen specimen_;
  skin::SpectralDatabase spectra_;
};

}  // namespace hylios
