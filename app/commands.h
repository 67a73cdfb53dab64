// The hylios subcommands. Each lives in its own <name>_command.cpp and registers itself on the
// CLI11 app; main.cpp calls every register function.
#pragma once
#include <CLI/CLI.hpp>

namespace hylios {

void registerCoefficientsCommand(CLI::App& app);    // coefficients_command.cpp
void registerSlabCommand(CLI::App& app);            // slab_command.cpp
void registerSpectrumCommand(CLI::App& app);        // spectrum_command.cpp
void registerBrdfCommand(CLI::App& app);            // brdf_command.cpp
void registerForwardProfileCommand(CLI::App& app);  // forward_profile_command.cpp
void registerRadialProfileCommand(CLI::App& app);   // radial_profile_command.cpp
void registerRenderCommand(CLI::App& app);          // render_command.cpp
void registerFigureCommand(CLI::App& app);          // figure_command.cpp
void registerGalleryCommand(CLI::App& app);         // gallery_command.cpp
void registerImageDiffCommand(CLI::App& app);       // image_diff_command.cpp
void registerFitCommand(CLI::App& app);             // fit_command.cpp
void registerValidateCommand(CLI::App& app);        // validate_command.cpp
void registerSweepCommand(CLI::App& app);           // sweep_command.cpp

}  // namespace hylios
