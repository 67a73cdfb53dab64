// hylios: hyperspectral rendering and simulation of light in human skin (HyLIoS).
#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>

#include "app/commands.h"

int main(int argc, char** argv) {
  CLI::App app{"hylios — the HyLIoS hyperspectral skin model and renderer (250–2500 nm)"};
  app.require_subcommand(1);
  hylios::registerCoefficientsCommand(app);
  hylios::registerSlabCommand(app);
  hylios::registerSpectrumCommand(app);
  hylios::registerBrdfCommand(app);
  hylios::registerForwardProfileCommand(app);
  hylios::registerRadialProfileCommand(app);
  hylios::registerRenderCommand(app);
  hylios::registerFigureCommand(app);
  hylios::registerGalleryCommand(app);
  hylios::registerImageDiffCommand(app);
  hylios::registerFitCommand(app);
  hylios::registerValidateCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "hylios: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
