// docs/scene-format.md and the scene parser agree on the keys: every key a section's tables list
// in their first column is accepted by the parser's tables for that section, and every key the
// parser accepts is named (in backticks) in its section.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "renderer/scene/scene_file.h"

namespace hylios {
namespace {

/// docs/scene-format.md split into "## " sections (heading → text).
std::map<std::string, std::string> docSections() {
  std::ifstream in(std::string(HYLIOS_SOURCE_DIR) + "/docs/scene-format.md");
  std::map<std::string, std::string> sections;
  std::string line, heading;
  while (std::getline(in, line)) {
    if (line.rfind("## ", 0) == 0) {
      heading = line.substr(3);
      continue;
    }
    if (!heading.empty()) sections[heading] += line + "\n";
  }
  return sections;
}

/// The keys in the first column of the section's key tables: `key`, or a table name such as
/// `[camera]`, `[[film.band]]` (→ "camera", "band").
std::set<std::string> tableKeys(const std::string& text) {
  std::set<std::string> keys;
  std::istringstream lines(text);
  std::string line;
  const std::regex row(R"(^\| `\[*([A-Za-z0-9_.]+)\]*` \|)");
  while (std::getline(lines, line)) {
    std::smatch m;
    if (!std::regex_search(line, m, row)) continue;
    std::string key = m[1];
    if (const auto dot = key.rfind('.'); dot != std::string::npos) key = key.substr(dot + 1);
    keys.insert(key);
  }
  return keys;
}

std::set<std::string> parserKeys(const std::vector<std::string>& tables) {
  std::set<std::string> keys;
  for (const std::string& t : tables)
    for (const std::string& k : sceneFileKeys().at(t)) keys.insert(k);
  return keys;
}

struct Section {
  std::string heading;              ///< in docs/scene-format.md
  std::vector<std::string> tables;  ///< sceneFileKeys() tables it documents
};
const std::vector<Section> kSections = {
    {"Top level", {"top level"}},
    {"`[camera]`", {"camera"}},
    {"`[film]` and `[[film.band]]`", {"film", "film.band"}},
    {"`[[material]]`", {"material", "material.freckles", "material.melanin_map"}},
    {"`[[shape]]`", {"shape", "shape.transform"}},
    {"`[[light]]`", {"light"}},
    {"`[integrator]`", {"integrator"}},
};

TEST(SceneFormatDoc, EveryParserTableHasASection) {
  std::set<std::string> covered;
  for (const Section& s : kSections) covered.insert(s.tables.begin(), s.tables.end());
  for (const auto& [table, keys] : sceneFileKeys()) EXPECT_TRUE(covered.count(table)) << table;
}

TEST(SceneFormatDoc, DocumentedKeysAreAccepted) {
  const auto sections = docSections();
  for (const Section& s : kSections) {
    ASSERT_TRUE(sections.count(s.heading))
        << "docs/scene-format.md has no section '## " << s.heading << "'";
    const std::set<std::string> accepted = parserKeys(s.tables);
    for (const std::string& key : tableKeys(sections.at(s.heading)))
      EXPECT_TRUE(accepted.count(key)) << s.heading << ": docs/scene-format.md lists '" << key
                                       << "', the parser does not accept it";
  }
}

TEST(SceneFormatDoc, AcceptedKeysAreDocumented) {
  const auto sections = docSections();
  for (const Section& s : kSections) {
    ASSERT_TRUE(sections.count(s.heading)) << s.heading;
    const std::string& text = sections.at(s.heading);
    for (const std::string& key : parserKeys(s.tables)) {
      const bool named = text.find("`" + key + "`") != std::string::npos ||
                         text.find("`[" + key + "]`") != std::string::npos ||
                         text.find("`[[" + key + "]]`") != std::string::npos ||
                         text.find("." + key + "]]`") != std::string::npos ||
                         text.find("`" + key + " ") != std::string::npos;
      EXPECT_TRUE(named) << s.heading << ": the parser accepts '" << key
                         << "', docs/scene-format.md does not name it";
    }
  }
}

}  // namespace
}  // namespace hylios
