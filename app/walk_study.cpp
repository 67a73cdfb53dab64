#include "app/walk_study.h"

#include "app/common_options.h"
#include "app/estimator_option.h"
#include "app/mpi_session.h"
#include "renderer/scene/data_paths.h"

namespace hylios {

void addWalkStudyOptions(CLI::App& command, WalkStudyOptions& options,
                         const std::string& raysHelp) {
  addSpecimenOptions(command, options.specimen);
  addEstimatorOption(command, options.estimator);
  addRaysOption(command, options.rays, raysHelp);
  addSeedOption(command, options.seed);
  addThreadsOption(command, options.threads);
}

void addStudyOutputOptions(CLI::App& command, WalkStudyOptions& options, const std::string& outHelp,
                           const std::string& plotHelp) {
  command.add_option("--out", options.out, outHelp)->required();
  command.add_option("--plot", options.plot, plotHelp);
}

WalkStudy::OutputsChecked::OutputsChecked(const WalkStudyOptions& options,
                                          const std::vector<NamedPath>& inputs) {
  std::vector<NamedPath> all = {inputFile("--specimen", options.specimen.specimen)};
  all.insert(all.end(), inputs.begin(), inputs.end());
  // Under MPI: checked on rank 0, every rank stops with its verdict (app/mpi_session.h).
  shareRootVerdict([&] {
    checkOutputs({{"--out", options.out}, {"--plot", options.plot, true}}, all);
  });
}

WalkStudy::WalkStudy(const WalkStudyOptions& options, const std::vector<NamedPath>& inputs)
    : options_(options),
      checked_(options, inputs),
      threadLimit_(options.threads),
      specimen_(loadSpecimenWithOverrides(options.specimen)),
      spectra_(skin::SpectralDatabase::load(spectraDir())) {}

skin::SkinOptics WalkStudy::optics(double wavelengthNm) const {
  return skin::computeSkinOptics(specimen_, spectra_, wavelengthNm);
}

std::vector<skin::SkinOptics> WalkStudy::optics(const std::vector<double>& wavelengths) const {
  std::vector<skin::SkinOptics> result;
  for (double w : wavelengths) result.push_back(optics(w));
  return result;
}

skin::WalkRunOptions WalkStudy::run(double incidenceDeg) const {
  return skin::WalkRunOptions{incidenceDeg, options_.rays, options_.seed, {}, {}};
}

}  // namespace hylios
