// Test support for the command tests: a scratch folder removed afterwards (and one holding a
// command's CSV and plot), a CSV reader, runners that parse one command line with a command
// registered on a fresh CLI11 app, and (tests/support/error_message.h) the checks of failures.
#pragma once
#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

#include "tests/support/error_message.h"

namespace hylios::test {

struct ScratchFolder {
  std::filesystem::path path;
  explicit ScratchFolder(const std::string& name)
      : path(std::filesystem::temp_directory_path() /
             ("hylios-" + name + "-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

/// A command's CSV and PNG outputs in a scratch folder of their own: NAME.csv and NAME.png.
struct ScratchOutputs {
  explicit ScratchOutputs(const std::string& name)
      : folder(name), csv(folder.path / (name + ".csv")), png(folder.path / (name + ".png")) {}
  /// " --out CSV --plot PNG", to append to a command line.
  std::string options() const { return " --out " + csv.string() + " --plot " + png.string(); }
  ScratchFolder folder;
  std::filesystem::path csv, png;
};

/// Rows of comma-separated fields (no quoting: the hylios CSVs hold numbers and names only).
inline std::vector<std::vector<std::string>> readCsv(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream stream(line);
    std::string field;
    while (std::getline(stream, field, ',')) fields.push_back(field);
    rows.push_back(fields);
  }
  return rows;
}

/// Parses "name arguments…" with the command registered by `registerCommand`; the command's
/// callback runs (and throws) inside.
inline void runCommandLine(const std::function<void(CLI::App&)>& registerCommand,
                           const std::string& commandLine) {
  CLI::App app;
  registerCommand(app);
  app.parse(commandLine, false);
}

/// Parses "hylios name args…" (each argument as given, no splitting) with the command registered
/// by `registerCommand`; the command's callback runs (and throws) inside.
inline void runCommandArguments(const std::function<void(CLI::App&)>& registerCommand,
                                const std::string& name, const std::vector<std::string>& args) {
  CLI::App app;
  registerCommand(app);
  std::vector<const char*> argv{"hylios", name.c_str()};
  for (const std::string& a : args) argv.push_back(a.c_str());
  app.parse(static_cast<int>(argv.size()), argv.data());
}

/// runCommandLine bound to one command: `run("arguments…")` parses "name arguments…"; `run({...})`
/// takes the arguments one by one.
struct CommandRunner {
  CommandRunner(std::function<void(CLI::App&)> registerCommand, std::string name)
      : registerCommand_(std::move(registerCommand)), name_(std::move(name)) {}
  void operator()(const std::string& arguments) const {
    runCommandLine(registerCommand_, name_ + " " + arguments);
  }
  /// The arguments as given, one each (runCommandArguments).
  void operator()(const std::vector<std::string>& args) const {
    runCommandArguments(registerCommand_, name_, args);
  }

 private:
  std::function<void(CLI::App&)> registerCommand_;
  std::string name_;
};

/// Index of `name` in a CSV header row, or the row's size when missing.
inline std::size_t columnOf(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return i;
  return header.size();
}

}  // namespace hylios::test
