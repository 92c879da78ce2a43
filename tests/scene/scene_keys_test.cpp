// The key table (libemb/scene/scene_keys.h) against the readers: every shipped scene, the
// scene files of the tests and the scene fuzzer's seeds, and a few scenes that give the rarer
// keys (tests/scene/data/keys/) are loaded with a KeyReadLog; every key the readers read must be
// in the table under its section, with the table's kind of value, range and unit, and the
// fallback the reader used when a key was absent must be the table's default. Every table
// entry must be read by some scene, and every default the table states must have been used.
// A scene whose body file is not there (the engine scenes read `out/*.h5`, made by
// `emb reduce`) stops loading at that part; its keys up to there are checked, and the same
// scene is loaded again with its body-file parts switched to `model: beam` (the one-word
// switch the scenes keep), which reads the rest of it.

#include "libemb/scene/scene_keys.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "libemb/common/error.h"
#include "libemb/scene/key_read_log.h"
#include "libemb/scene/scene.h"

namespace emb::scene {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> SceneFiles() {
  std::vector<fs::path> files;
  const fs::path root(EMB_SOURCE_DIR);
  for (const char* dir :
       {"tools/scenes", "tests/scene/data", "tests/scene/data/keys", "tests/sweep/data"}) {
    if (!fs::is_directory(root / dir)) continue;
    for (const auto& e : fs::directory_iterator(root / dir))
      if (e.path().extension() == ".yaml") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The scene with every body-file part that also names a geometry switched to `model: beam`,
// or "" if it has none.
std::string BeamVariant(const std::string& text) {
  YAML::Node root = YAML::Load(text);
  bool changed = false;
  if (root.IsMap() && root["bodies"] && root["bodies"].IsSequence())
    for (YAML::Node body : root["bodies"])
      if (body.IsMap() && body["body_file"] && body["geometry"]) {
        body["model"] = "beam";
        changed = true;
      }
  if (!changed) return "";
  YAML::Emitter out;
  out << root;
  return out.c_str();
}

// Parses `text` as the scene file `path` and returns what was read (and why loading stopped,
// if it did).
std::vector<KeyRead> ReadKeys(const std::string& text, const fs::path& path, std::string* stop) {
  KeyReadLog log;
  try {
    ParseScene(text, path.string());  // LoadScene less the output-path check
  } catch (const InputError& e) {
    *stop = e.what();
  } catch (const NumericalError& e) {
    *stop = e.what();
  }
  return log.reads();
}

TEST(SceneKeys, TableHoldsEveryKeyTheReadersRead) {
  std::vector<KeyRead> reads;
  const std::vector<fs::path> files = SceneFiles();
  ASSERT_GT(files.size(), 20u);
  for (const fs::path& f : files) {
    const std::string text = ReadSceneText(f.string());
    std::string stop;
    for (KeyRead& r : ReadKeys(text, f, &stop)) reads.push_back(std::move(r));
    if (const std::string beam = BeamVariant(text); !beam.empty()) {
      std::string beam_stop;
      for (KeyRead& r : ReadKeys(beam, f, &beam_stop)) reads.push_back(std::move(r));
      if (!beam_stop.empty())
        std::cout << f.filename() << " as beam: stopped at " << beam_stop << "\n";
    }
    if (!stop.empty()) std::cout << f.filename() << ": stopped at " << stop << "\n";
  }

  // Each disagreement once, with where it was first seen and how often.
  std::map<std::string, std::pair<std::string, int>> problems;
  auto problem = [&](const KeyRead& r, const std::string& what) {
    auto [it, inserted] = problems.try_emplace(r.section + " / " + r.key + ": " + what, r.where, 0);
    ++it->second.second;
  };
  std::set<std::string> sections;
  for (const SceneSection& s : SceneSections()) sections.insert(std::string(s.id));
  std::set<std::pair<std::string, std::string>> seen, defaults_seen;
  for (const KeyRead& r : reads) {
    if (r.ignored) {
      // A key of another model of a body entry: it must be a key of some body section.
      const bool known =
          std::any_of(SceneKeys().begin(), SceneKeys().end(), [&](const SceneKey& k) {
            return k.section.starts_with("bodies") && k.section != r.section && k.key == r.key;
          });
      if (!known) problem(r, "ignored, but no other body section has it");
      continue;
    }
    if (!sections.count(r.section)) problem(r, "the section is not in the table");
    const SceneKey* k = FindSceneKey(r.section, r.key);
    if (!k) {
      problem(r, "read, but not in the key table (libemb/scene/scene_keys*.cpp)");
      continue;
    }
    seen.insert({r.section, r.key});
    if (r.type != KeyType::kAny && k->type != KeyType::kAny && k->type != r.type)
      problem(r, "kind: table '" + std::string(Name(k->type)) + "', reader '" +
                     std::string(Name(r.type)) + "'");
    if (r.range_checked && (k->range != r.range || k->unit != r.unit))
      problem(r, "range: table '" + std::string(k->range) + "' [" + std::string(k->unit) +
                     "], reader '" + r.range + "' [" + r.unit + "]");
    if (!r.range_checked && r.type == KeyType::kNumber && !k->range.empty())
      problem(r, "range: the reader checks none, the table says '" + std::string(k->range) + "'");
    // A word the readers accepted, or used by default, is one of the table's choices (text
    // keys with a range).
    if (r.type == KeyType::kString && !k->range.empty()) {
      const std::string choices = " " + std::string(k->range) + " ";
      for (const std::string& word : {r.value, r.default_used.value_or("")})
        if (!word.empty() && choices.find(" " + word + " ") == std::string::npos)
          problem(
              r, "'" + word + "' is not among the table's choices '" + std::string(k->range) + "'");
    }
    if (r.default_used) {
      defaults_seen.insert({r.section, r.key});
      if (k->default_value != *r.default_used)
        problem(r, "default: table '" + std::string(k->default_value) + "', reader '" +
                       *r.default_used + "'");
    }
  }
  for (const auto& [what, where] : problems)
    ADD_FAILURE() << what << " (" << where.first << ", " << where.second << " reads)";
  for (const SceneKey& k : SceneKeys()) {
    const std::pair<std::string, std::string> id{std::string(k.section), std::string(k.key)};
    EXPECT_TRUE(sections.count(id.first)) << k.section << " / " << k.key << ": unknown section";
    EXPECT_TRUE(seen.count(id)) << k.section << " / " << k.key
                                << ": in the table, but no scene reads it (a stale entry, or "
                                   "give it in a scene of tests/scene/data/keys/)";
    const bool concrete = k.default_value != "required" && k.default_value != "—";
    EXPECT_TRUE(!concrete || defaults_seen.count(id))
        << k.section << " / " << k.key << ": the default '" << k.default_value
        << "' was never used by a scene that leaves the key out";
  }
  // Each section's keys once.
  std::set<std::pair<std::string_view, std::string_view>> unique;
  for (const SceneKey& k : SceneKeys())
    EXPECT_TRUE(unique.insert({k.section, k.key}).second)
        << k.section << " / " << k.key << ": twice";
}

TEST(SceneKeys, FormatDefaultIsShortAndExact) {
  EXPECT_EQ(FormatDefault(1e-6), "1e-6");
  EXPECT_EQ(FormatDefault(0.001), "0.001");
  EXPECT_EQ(FormatDefault(0.5), "0.5");
  EXPECT_EQ(FormatDefault(-1.0), "-1");
  EXPECT_EQ(FormatDefault(210e9), "2.1e11");
  EXPECT_EQ(FormatDefault(true), "true");
  const double v[3] = {0.0, -9.81, 0.0};
  EXPECT_EQ(FormatDefault(v), "[0, -9.81, 0]");
  EXPECT_EQ(FormatIntegerRange(1, 100000), "[1, 100000]");
}

TEST(SceneKeys, NothingIsRecordedWithoutALog) {
  EXPECT_FALSE(KeyReadLogActive());
  {
    KeyReadLog log;
    EXPECT_TRUE(KeyReadLogActive());
    LoadScene(std::string(EMB_SOURCE_DIR) + "/tools/scenes/pendulum.yaml");
    EXPECT_FALSE(log.reads().empty());
  }
  EXPECT_FALSE(KeyReadLogActive());
}

}  // namespace
}  // namespace emb::scene
