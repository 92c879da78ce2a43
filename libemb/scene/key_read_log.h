#pragma once
/// @file
/// What the scene readers read, key by key, for the test that holds the key table
/// (scene_keys.h) to the code. While a KeyReadLog is alive on a thread, every key a
/// MapReader (yaml_reader.h) marks as known on that thread is recorded with its section, the
/// kind of value its getter takes, the range and unit its number is checked against, and the
/// fallback the reader used when the key was absent. Without a log nothing is recorded and
/// the readers behave exactly as they do with one.

#include <optional>
#include <string>
#include <vector>

#include "libemb/common/number_check.h"
#include "libemb/scene/scene_keys.h"

namespace emb::scene {

/// One key read by a MapReader.
struct KeyRead {
  std::string section;  ///< the reader's section (scene_keys.h), e.g. "analysis"
  std::string key;
  /// The getter's kind of value; KeyType::kAny for a node handed to other code (Require,
  /// Optional), which parses it itself.
  KeyType type{KeyType::kAny};
  bool range_checked{false};  ///< the getter checked the number against a range
  std::string range;          ///< that range without its unit (NumberRange::Describe)
  std::string unit;           ///< that range's unit
  /// The value used because the key was absent, formatted as FormatDefault does; empty when
  /// the key was present or the getter has no fallback.
  std::optional<std::string> default_used;
  /// The word a text getter read (empty otherwise), held against the table's choices.
  std::string value;
  /// Accepted and not used: a key of another `model:` in a body entry (one-word switch).
  bool ignored{false};
  std::string where;  ///< "scene.yaml:12"
};

/// Records the keys read on this thread while it lives (not nestable).
class KeyReadLog {
 public:
  /// @throws InternalError if another log is alive on this thread.
  KeyReadLog();
  ~KeyReadLog();
  KeyReadLog(const KeyReadLog&) = delete;
  KeyReadLog& operator=(const KeyReadLog&) = delete;

  const std::vector<KeyRead>& reads() const { return reads_; }

 private:
  std::vector<KeyRead> reads_;
};

/// True while a KeyReadLog is alive on this thread (MapReader skips the formatting otherwise).
bool KeyReadLogActive();
/// Appends to this thread's log; does nothing without one.
void NoteKeyRead(KeyRead read);

/// The default texts of the key table: the shortest decimal that reads back as `v`, with a
/// short exponent ("0.001", "1e-06" -> "1e-6", "5e+08" -> "5e8").
std::string FormatDefault(double v);
/// "true" / "false".
std::string FormatDefault(bool v);
/// "[x, y, z]" with the numbers as above.
std::string FormatDefault(const double (&v)[3]);
/// The range text of an integer getter: "[lo, hi]", or "" for any int.
std::string FormatIntegerRange(long long lo, long long hi);

}  // namespace emb::scene
