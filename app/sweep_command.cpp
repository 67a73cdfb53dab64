// hylios sweep: reflectance curves over a grid or list of specimen overrides (app/sweep_cases.h)
// × wavelengths × incidence angles, one CSV row per case, angle and wavelength. Under MPI the cases
// are handed out to the ranks one at a time (app/mpi_dispatch.h); every case is computed with
// the same seed whoever runs it, and rows are written in case order, so the output's bytes do not
// depend on the number of ranks or threads. Completed cases go to a journal beside the output
// (app/sweep_journal.h) that --resume continues from; the CSV is written atomically at the end.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "app/commands.h"
#include "app/mpi_dispatch.h"
#include "app/mpi_session.h"
#include "app/option_checks.h"
#include "app/progress_bar.h"
#include "app/specimen_options.h"
#include "app/sweep_cases.h"
#include "app/sweep_journal.h"
#include "app/wavelength_list.h"
#include "renderer/scene/data_paths.h"
#include "skin/core/atomic_file.h"
#include "skin/core/content_hash.h"
#include "skin/core/thread_limit.h"
#include "skin/skin_optics.h"
#include "skin/specimen_writer.h"
#include "skin/spectral_simulation.h"

namespace hylios {
namespace {

/// At most this many cases in one sweep (the journal and the table are kept in memory).
constexpr std::size_t kMaxSweepCases = 1000000;

struct SweepArguments {
  SpecimenOptions specimen;
  std::vector<std::string> vary;
  std::string casesFile;
  std::string wavelengths = "250:2500:5";
  std::vector<double> anglesDeg = {45};
  std::uint64_t rays = 100000;
  std::uint64_t seed = 1;
  std::string out;
  int threads = 0;
  bool resume = false;
};

/// Everything a sweep's rows depend on, parsed once on every rank.
struct SweepPlan {
  skin::Specimen base;
  SweepCases cases;
  std::vector<double> wavelengths;
  std::uint64_t definition = 0;  ///< hash of all of the above + angles, rays, seed
};

SweepPlan planSweep(const SweepArguments& args) {
  if (args.vary.empty() == args.casesFile.empty())
    throw std::invalid_argument(
        "give the cases as --vary NAME=LO:HI:STEP (repeatable, a grid) or as --cases FILE, "
        "not both");
  SweepPlan plan;
  plan.base = loadSpecimenWithOverrides(args.specimen);
  plan.cases = args.vary.empty() ? loadSweepCasesFile(args.casesFile, kMaxSweepCases)
                                 : parseSweepGrid(args.vary, kMaxSweepCases);
  plan.wavelengths = parseWavelengthList(args.wavelengths);
  // Every case's specimen and optics are checked now, so a bad value fails before any walk.
  const auto spectra = skin::SpectralDatabase::load(spectraDir());
  for (std::size_t i = 0; i < plan.cases.values.size(); ++i)
    (void)sweepSpecimen(plan.base, plan.cases, i);
  for (double w : plan.wavelengths) (void)skin::computeSkinOptics(plan.base, spectra, w);
  skin::ContentHash hash;
  hash.addString(skin::formatSpecimenToml(plan.base));
  hash.addU64(plan.cases.keys.size());
  for (const auto& key : plan.cases.keys) hash.addString(key);
  hash.addU64(plan.cases.values.size());
  for (const auto& row : plan.cases.values)
    for (double v : row) hash.addDouble(v);
  hash.addU64(plan.wavelengths.size());
  for (double w : plan.wavelengths) hash.addDouble(w);
  hash.addU64(args.anglesDeg.size());
  for (double a : args.anglesDeg) hash.addDouble(a);
  hash.addU64(args.rays).addU64(args.seed).addString("spectral");
  plan.definition = hash.value();
  return plan;
}

std::string csvHeader(const SweepCases& cases) {
  std::string header = "case";
  for (const auto& key : cases.keys) header += "," + key;
  return header +
         ",angle_deg,wavelength_nm,reflectance,reflectance_stderr,surface_reflectance,"
         "subsurface_reflectance,transmittance,absorptance,absorptance_stderr\n";
}

/// The rows of case `index`: per angle, per wavelength.
std::string caseRows(const SweepArguments& args, const SweepPlan& plan,
                     const skin::SpectralDatabase& spectra, std::size_t index) {
  const skin::Specimen specimen = sweepSpecimen(plan.base, plan.cases, index);
  std::vector<skin::SkinOptics> optics;
  for (double w : plan.wavelengths) optics.push_back(skin::computeSkinOptics(specimen, spectra, w));
  std::string prefix = std::to_string(index);
  for (double v : plan.cases.values[index]) prefix += "," + formatWavelength(v);
  std::ostringstream rows;
  char buffer[64];
  auto put = [&](double value) {
    std::snprintf(buffer, sizeof buffer, ",%.6g", value);
    rows << buffer;
  };
  for (double angle : args.anglesDeg) {
    skin::WalkRunOptions run;
    run.incidenceDeg = angle;
    run.rays = args.rays;
    run.seed = args.seed;
    const auto tallies = skin::simulateSkinSpectral(optics, skin::commandSpectralRun(run));
    for (std::size_t i = 0; i < plan.wavelengths.size(); ++i) {
      const skin::SkinTally& t = tallies[i];
      rows << prefix << "," << formatWavelength(angle) << ","
           << formatWavelength(plan.wavelengths[i]);
      put(t.reflectance().mean);
      put(t.reflectance().standardError);
      put(t.surfaceReflectance().mean);
      put(t.subsurfaceReflectance().mean);
      put(t.transmittance().mean);
      put(t.absorptance().mean);
      put(t.absorptance().standardError);
      rows << "\n";
    }
  }
  return rows.str();
}

/// Test hook (tests/app/mpi_commands_test.sh, sweep_command_test.cpp): HYLIOS_TEST_SWEEP_EXIT=
/// RANK:K makes rank RANK end abruptly, as by SIGKILL (no cleanup, no output, status 137), once it
/// has K cases done: journaled on rank 0, computed elsewhere; RANK:K:throw throws instead (an
/// in-process test's stand-in for the kill). Unset: never.
struct TestExit {
  int rank = -1;
  std::size_t afterCases = 0;
  bool throws = false;
  std::size_t done = 0;
  static TestExit fromEnvironment() {
    TestExit exit;
    const char* text = std::getenv("HYLIOS_TEST_SWEEP_EXIT");
    char how[8] = "";
    const int fields =
        text ? std::sscanf(text, "%d:%zu:%7s", &exit.rank, &exit.afterCases, how) : 0;
    if (fields < 2) exit.rank = -1;
    exit.throws = fields == 3 && std::string(how) == "throw";
    return exit;
  }
  void count() {
    if (rank != MpiSession::rank() || ++done < afterCases) return;
    if (throws)
      throw std::runtime_error("HYLIOS_TEST_SWEEP_EXIT: stopped after " + std::to_string(done) +
                               " cases");
    std::cerr << "hylios sweep: HYLIOS_TEST_SWEEP_EXIT: rank " << rank << " ends after " << done
              << " cases" << std::endl;
    std::_Exit(137);
  }
};

void runSweep(const SweepArguments& args) {
  const std::filesystem::path journalPath = sweepJournalPath(args.out);
  shareRootVerdict([&] {
    checkOutputs(
        {{"--out", args.out}, {"journal", journalPath.string()}},
        {inputFile("--specimen", args.specimen.specimen), inputFile("--cases", args.casesFile)});
    std::error_code noJournal;
    if (!args.resume && std::filesystem::exists(journalPath, noJournal))
      throw std::runtime_error("'" + journalPath.string() + "' holds an interrupted sweep into '" +
                               args.out +
                               "'; continue it with the same command and --resume, or delete "
                               "that file to start afresh (nothing was changed)");
  });
  const ThreadLimit threadLimit(args.threads);
  const SweepPlan plan = planSweep(args);
  const std::size_t caseCount = plan.cases.values.size();
  std::map<std::size_t, std::string> rows;
  std::string skipped;  // rank 0 reads the journal and tells the others which cases remain
  if (MpiSession::isRoot() && args.resume) {
    rows = readSweepJournal(journalPath, plan.definition, caseCount);
    for (const auto& entry : rows) skipped += std::to_string(entry.first) + " ";
  }
  broadcastFromRoot(skipped);
  std::vector<bool> done(caseCount, false);
  std::istringstream doneList(skipped);
  std::size_t doneIndex = 0;
  std::size_t resumed = 0;
  while (doneList >> doneIndex) done.at(doneIndex) = true, ++resumed;
  std::vector<std::size_t> remaining;
  for (std::size_t i = 0; i < caseCount; ++i)
    if (!done[i]) remaining.push_back(i);
  std::unique_ptr<SweepJournal> journal;
  std::unique_ptr<ProgressBar> progress;
  if (MpiSession::isRoot()) {
    journal = std::make_unique<SweepJournal>(journalPath, plan.definition, rows);
    std::cout << "sweep: " << caseCount << " cases x " << args.anglesDeg.size() << " angles x "
              << plan.wavelengths.size() << " wavelengths, " << args.rays << " rays each, "
              << MpiSession::size() << (MpiSession::size() == 1 ? " process" : " ranks");
    if (args.resume) std::cout << "; " << resumed << " cases from the journal";
    std::cout << std::endl;
    progress = std::make_unique<ProgressBar>("sweep", caseCount);
    progress->advance(resumed);
  }
  const auto spectra = skin::SpectralDatabase::load(spectraDir());
  TestExit testExit = TestExit::fromEnvironment();
  dispatchAcrossRanks(
      remaining,
      [&](std::size_t index) {
        std::string text = caseRows(args, plan, spectra, index);
        if (!MpiSession::isRoot()) testExit.count();
        return text;
      },
      [&](std::size_t index, const std::string& text) {
        journal->append(index, text);
        rows[index] = text;
        progress->advance();
        testExit.count();
      });
  if (!MpiSession::isRoot()) return;
  progress->finish();
  std::string csv = csvHeader(plan.cases);
  for (const auto& entry : rows) csv += entry.second;
  if (rows.size() != caseCount)
    throw std::logic_error("sweep: " + std::to_string(rows.size()) + " of " +
                           std::to_string(caseCount) + " cases done");
  writeTextAtomically(args.out, csv);
  journal->remove();
  std::cout << "wrote " << args.out << " (" << caseCount << " cases)\n";
}

}  // namespace

void registerSweepCommand(CLI::App& app) {
  auto args = std::make_shared<SweepArguments>();
  CLI::App* command = app.add_subcommand(
      "sweep",
      "Reflectance over a grid or list of specimen overrides x wavelengths x angles (one CSV; "
      "distributed over MPI ranks when started by mpirun/srun; resumable)");
  addSpecimenOptions(*command, args->specimen);
  command->add_option("--vary", args->vary,
                      "NAME=LO:HI:STEP, repeatable: a grid over these quantities (the first "
                      "varies slowest); NAME is a --set key, '_percent' may be left out");
  command->add_option("--cases", args->casesFile,
                      "CSV file of cases: a header of --set keys, then one line of values per "
                      "case ('#' lines are comments)");
  command->add_option("--wavelengths", args->wavelengths, "start:stop:step or a comma list, nm")
      ->capture_default_str();
  command
      ->add_option("--angle", args->anglesDeg,
                   "Incidence angles from the normal, degrees in [0, 90); repeatable or a comma "
                   "list (default 45)")
      ->delimiter(',')
      ->check(finiteRange(0.0, 89.999));
  command->add_option("--rays", args->rays, "Rays per case, angle and wavelength")
      ->check(unsignedRange(1, std::uint64_t{1} << 40))
      ->capture_default_str();
  command
      ->add_option("--seed", args->seed,
                   "Random seed in [0, 2^63-1], the same for every case (same seed, same output "
                   "at any number of threads or ranks)")
      ->check(seedRange());
  command->add_option("--out", args->out, "CSV file to write (its journal: <out>.partial)")
      ->required();
  command->add_option("--threads", args->threads, "Worker threads per process (default: all cores)")
      ->check(CLI::Range(1, 1024));
  command->add_flag("--resume", args->resume,
                    "Continue the interrupted sweep whose journal <out>.partial lies beside --out "
                    "(same command): its completed cases are kept; without a journal, start "
                    "afresh");
  command->callback([args] { runSweep(*args); });
}

}  // namespace hylios
