// hylios: hyperspectral rendering and simulation of light in human skin (HyLIoS).
#include <CLI/CLI.hpp>

#include <exception>
#include <fstream>
#include <iostream>

#include "app/commands.h"
#include "app/mpi_session.h"

int main(int argc, char** argv) {
  // Under mpirun/srun (a build with MPI): one rank of the job, only rank 0 prints (mpi_session.h).
  const hylios::MpiSession mpi(argc, argv);
  CLI::App app{"hylios — the HyLIoS hyperspectral skin model and renderer (250–2500 nm)"};
  app.require_subcommand(1);
  // Every subcommand, in the order of `hylios --help`.
  for (const auto registerCommand :
       {&hylios::registerCoefficientsCommand, &hylios::registerSlabCommand,
        &hylios::registerSpectrumCommand, &hylios::registerBrdfCommand,
        &hylios::registerForwardProfileCommand, &hylios::registerRadialProfileCommand,
        &hylios::registerRenderCommand, &hylios::registerFigureCommand,
        &hylios::registerGalleryCommand, &hylios::registerImageDiffCommand,
        &hylios::registerFitCommand, &hylios::registerValidateCommand,
        &hylios::registerSweepCommand})
    registerCommand(app);
  // Under MPI only the commands that divide their work run; the others would compute the same
  // thing on every rank (docs/cluster.md).
  auto isCommand = [&app](const char* name) {
    for (const CLI::App* command : app.get_subcommands({}))
      if (command->get_name() == name) return true;
    return false;
  };
  if (hylios::MpiSession::distributed() && argc > 1 && isCommand(argv[1]) &&
      !hylios::MpiSession::dividesWork(argv[1]))
    return hylios::MpiSession::failCommand(
        std::string("'hylios ") + argv[1] +
        "' does not divide its work among MPI ranks; run it as one process, without "
        "mpirun/srun (spectrum, brdf, forward-profile, radial-profile, render and sweep do, "
        "docs/cluster.md)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (hylios::MpiSession::isRoot()) return app.exit(e);
    std::ofstream quiet;  // every rank parsed the same arguments: rank 0 has said it
    return app.exit(e, quiet, quiet);
  } catch (const std::exception& e) {
    return hylios::MpiSession::failCommand(e.what());
  }
  return 0;
}
