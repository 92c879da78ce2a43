#pragma once
/// @file
/// The table of every key a scene file may hold: section, key, kind of value, unit, range,
/// default and meaning. It is declarative — the readers (scene_loader.cpp and the readers it
/// calls) still read the keys one by one through MapReader — and it is held to them by a
/// test: while a KeyReadLog (key_read_log.h) is alive the readers record every key they
/// read, and `tests/scene/scene_keys_test.cpp` loads every shipped scene and fails on a key
/// read that is not in the table, a range, unit or kind that differs, a fallback that is not
/// the table's default, and a table entry no scene reads. The scene reference of the
/// documentation (docs/reference/scene-keys.md) is printed from this table by
/// `emb_scene_keys` (tools/docs/), and a test compares the committed page with that output.

#include <span>
#include <string_view>

namespace emb::scene {

/// The kind of value a key holds.
enum class KeyType {
  kNumber,   ///< a finite number
  kInteger,  ///< a whole number
  kBool,     ///< true or false
  kString,   ///< a name or word
  kVector3,  ///< [x, y, z]
  kNumbers,  ///< a list of numbers
  kList,     ///< a list (of maps or names)
  kMap,      ///< a map of keys
  kAny,      ///< a value parsed by its own reader (the meaning says which forms)
};

/// "number", "integer", "true/false", "text", "[x, y, z]", "list of numbers", "list", "map",
/// "see meaning".
std::string_view Name(KeyType t);

/// One key of one section.
struct SceneKey {
  std::string_view section;  ///< SceneSection::id
  std::string_view key;
  KeyType type;
  std::string_view unit;  ///< SI unit of a number ("s", "N m/rad"); empty for none
  /// The range the reader checks: NumberRange::Describe() without the unit ("> 0",
  /// "in (0, 1)") for numbers, "[lo, hi]" for integers; empty if the reader checks none
  /// (then any finite number; the meaning says what later checks refuse).
  std::string_view range;
  /// What the reader uses when the key is absent, as FormatDefault (key_read_log.h) prints
  /// it; "required" if the key must be given; "—" if absent means "not used" (the meaning
  /// says what happens then).
  std::string_view default_value;
  std::string_view meaning;
};

/// A section: a map of keys in the scene file.
struct SceneSection {
  std::string_view id;  ///< e.g. "forces: bushing"
  /// Where the map sits in the file, e.g. "an entry of `forces:` with `type: bushing`".
  std::string_view where;
  std::string_view about;  ///< one or two sentences
};

/// Every section, in the order of the reference.
std::span<const SceneSection> SceneSections();
/// Every key, grouped by section in that order.
std::span<const SceneKey> SceneKeys();
/// The key `key` of section `section`, or nullptr.
const SceneKey* FindSceneKey(std::string_view section, std::string_view key);

}  // namespace emb::scene
