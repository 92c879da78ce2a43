#pragma once
/// @file
/// Strict reading of YAML scene nodes: every map is read through a MapReader that knows
/// which keys the caller asked for, so an unknown key is an error with file:line and a
/// did-you-mean; wrong types and missing keys name the key and the line. Each reader belongs
/// to a section of the key table (scene_keys.h); while a KeyReadLog (key_read_log.h) is
/// alive, every key it marks as known is recorded there with what its getter checks.

#include <yaml-cpp/yaml.h>

#include <Eigen/Dense>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "libemb/common/number_check.h"
#include "libemb/common/error.h"
#include "libemb/scene/scene_keys.h"

namespace emb::scene {

/// "scene.yaml:12" for a node (line numbers 1-based).
std::string Where(const std::string& file, const YAML::Node& node);

/// Reads one YAML map. Call Finish() after the last Get to reject unknown keys.
class MapReader {
 public:
  /// @throws InputError if `node` is not a map. `what` names it in messages ("body 'crank'");
  /// `section` is its section of the key table (SceneSection::id, e.g. "analysis").
  MapReader(const YAML::Node& node, std::string file, std::string what, std::string section);

  /// The section the keys read from now on belong to (e.g. "forces: bushing" once the
  /// force's type is known).
  void set_section(std::string section) { section_ = std::move(section); }
  const std::string& section() const { return section_; }

  bool Has(const std::string& key) const;
  /// The child node (marks the key as known). @throws InputError if missing.
  YAML::Node Require(const std::string& key);
  /// The child node or an undefined node (marks the key as known).
  YAML::Node Optional(const std::string& key);

  double GetDouble(const std::string& key);
  double GetDouble(const std::string& key, double fallback);
  /// The number at `key`, finite and in `range` (number_check.h), with file:line, the key
  /// and the unit in the message otherwise.
  double GetDouble(const std::string& key, const NumberRange& range);
  double GetDouble(const std::string& key, double fallback, const NumberRange& range);
  /// An integer in [lo, hi] (default: any int).
  int GetInt(const std::string& key, int fallback, long long lo = std::numeric_limits<int>::min(),
             long long hi = std::numeric_limits<int>::max());
  bool GetBool(const std::string& key, bool fallback);
  std::string GetString(const std::string& key);
  std::string GetString(const std::string& key, const std::string& fallback);
  Eigen::Vector3d GetVector3(const std::string& key);
  Eigen::Vector3d GetVector3(const std::string& key, const Eigen::Vector3d& fallback);
  std::vector<double> GetDoubles(const std::string& key);
  /// Accepts `key` without reading it: a key of another `model:` of a body entry, which may
  /// stay so that one word switches the model.
  void Ignore(const std::string& key);

  /// @throws InputError naming the first key not asked for, with a did-you-mean among the
  /// asked ones.
  void Finish() const;

  const std::string& file() const { return file_; }
  const std::string& what() const { return what_; }
  const YAML::Node& node() const { return node_; }

 private:
  // The value at `key` (undefined if absent), without marking it known.
  YAML::Node Lookup(const std::string& key) const;
  // Require and Optional without recording (the typed getters record themselves).
  YAML::Node RequireNode(const std::string& key);
  YAML::Node OptionalNode(const std::string& key);
  // Records the read in this thread's KeyReadLog, if one is alive. `n` is the key's value
  // (undefined if absent), `range` the getter's check (or nullptr), `fallback` the default
  // text used when the key is absent (or nullptr: the getter has none), `integer_range` the
  // range text of an integer getter, `value` the word a text getter read.
  void Note(const std::string& key, KeyType type, const YAML::Node& n,
            const NumberRange* range = nullptr, const std::string* fallback = nullptr,
            const std::string* integer_range = nullptr, const std::string* value = nullptr) const;

  YAML::Node node_;
  std::string file_, what_, section_;
  std::set<std::string> known_;
};

/// @throws InputError "file:line: key 'k' given twice (first at line n)" for the first map
/// anywhere under `root` that holds a key twice (yaml-cpp keeps both and reads the first,
/// so a second value would be ignored without a word).
void CheckUniqueKeys(const YAML::Node& root, const std::string& file);

/// "file:line: '<section>': expected a list" as an InputError.
[[noreturn]] void ThrowNotAList(const YAML::Node& list, const std::string& file,
                                const std::string& section);
/// ReadNamedList's re-throw of the error of entry `name` of kind `kind` (see there).
[[noreturn]] void RethrowWithPlace(const InputError& e, const std::string& file,
                                   const YAML::Node& node, const std::string& kind,
                                   const std::string& name);

/// Reads `list`, the scene section `section` ("joints", "sensors", ...): a list of maps, each
/// with a `name`. For each entry `read(r, name, node)` gets a MapReader named
/// "<kind> '<name>'" whose `name` key is read (the callback reads the rest and calls
/// r.Finish()). An InputError from the callback that does not already start with the file
/// (the YAML readers' messages say file:line) is re-thrown as "file:line: <message>", with
/// "<kind> '<name>': " in front unless the message quotes the name already.
/// @throws InputError "file:line: '<section>': expected a list" if `list` is not a list.
template <class Read>
void ReadNamedList(const YAML::Node& list, const std::string& file, const std::string& section,
                   const std::string& kind, Read&& read) {
  if (!list.IsSequence()) ThrowNotAList(list, file, section);
  for (const auto& node : list) {
    MapReader r0(node, file, kind, section);
    const std::string name = r0.GetString("name");
    MapReader r(node, file, kind + " '" + name + "'", section);
    r.GetString("name");
    try {
      read(r, name, node);
    } catch (const InputError& e) {
      RethrowWithPlace(e, file, node, kind, name);
    }
  }
}

/// Scalar conversions with file:line in the message.
double AsDouble(const YAML::Node& n, const std::string& file, const std::string& what);
std::vector<double> AsDoubles(const YAML::Node& n, const std::string& file,
                              const std::string& what);

}  // namespace emb::scene
