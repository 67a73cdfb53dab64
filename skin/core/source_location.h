// A position in a text file, for error messages of every parser (scene files, specimen files,
// spectra, measured curves): "file:line:col". Lines and columns are 1-based; 0 where unknown.
#pragma once
#include <string>

namespace hylios {

struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
  std::string str() const {
    return file + ":" + std::to_string(line) + ":" + std::to_string(column);
  }
};

}  // namespace hylios
