#include "libemb/scene/yaml_reader.h"

#include <cmath>
#include <map>

#include "libemb/common/did_you_mean.h"
#include "libemb/common/error.h"
#include "libemb/scene/key_read_log.h"

namespace emb::scene {

std::string Where(const std::string& file, const YAML::Node& node) {
  const YAML::Mark m = node.Mark();
  if (m.line < 0) return file;
  return file + ":" + std::to_string(m.line + 1);
}

void ThrowNotAList(const YAML::Node& list, const std::string& file, const std::string& section) {
  EMB_THROW(InputError, Where(file, list) << ": '" << section << "': expected a list");
}

void RethrowWithPlace(const InputError& e, const std::string& file, const YAML::Node& node,
                      const std::string& kind, const std::string& name) {
  const std::string msg = e.what();
  if (msg.rfind(file, 0) == 0) throw e;  // a YAML reader's message: file:line already
  const bool named = msg.find("'" + name + "'") != std::string::npos;
  EMB_THROW(InputError, Where(file, node)
                            << ": " << (named ? "" : kind + " '" + name + "': ") << msg);
}

MapReader::MapReader(const YAML::Node& node, std::string file, std::string what,
                     std::string section)
    : node_(node), file_(std::move(file)), what_(std::move(what)), section_(std::move(section)) {
  EMB_THROW_IF(!node_.IsMap(), Where(file_, node_)
                                   << ": " << what_ << ": expected a map of key: value, got "
                                   << (node_.IsSequence() ? "a list"
                                       : node_.IsNull()   ? "nothing"
                                                          : "a scalar"));
}

// Const lookups only: yaml-cpp's non-const operator[] would insert the key.
YAML::Node MapReader::Lookup(const std::string& key) const {
  const YAML::Node& n = node_;
  return n[key];
}

bool MapReader::Has(const std::string& key) const { return static_cast<bool>(Lookup(key)); }

void MapReader::Note(const std::string& key, KeyType type, const YAML::Node& n,
                     const NumberRange* range, const std::string* fallback,
                     const std::string* integer_range, const std::string* value) const {
  if (!KeyReadLogActive()) return;
  KeyRead read;
  read.section = section_;
  read.key = key;
  read.type = type;
  if (range) {
    read.range_checked = true;
    NumberRange bare = *range;
    bare.unit.clear();
    read.range = bare.Describe();
    read.unit = range->unit;
  } else if (integer_range) {
    read.range_checked = true;
    read.range = *integer_range;
  }
  if (!n && fallback) read.default_used = *fallback;
  if (value) read.value = *value;
  read.where = n ? Where(file_, n) : Where(file_, node_);
  NoteKeyRead(std::move(read));
}

YAML::Node MapReader::Require(const std::string& key) {
  YAML::Node n = RequireNode(key);
  Note(key, KeyType::kAny, n);
  return n;
}

YAML::Node MapReader::Optional(const std::string& key) {
  YAML::Node n = OptionalNode(key);
  Note(key, KeyType::kAny, n);
  return n;
}

void MapReader::Ignore(const std::string& key) {
  known_.insert(key);
  if (!KeyReadLogActive()) return;
  KeyRead read;
  read.section = section_;
  read.key = key;
  read.ignored = true;
  read.where = Where(file_, node_);
  NoteKeyRead(std::move(read));
}

YAML::Node MapReader::RequireNode(const std::string& key) {
  known_.insert(key);
  const YAML::Node& map = node_;
  const YAML::Node n = map[key];
  if (!n) {
    // A typo of the required key is more helpful to name than the missing key alone.
    for (const auto& kv : node_) {
      const std::string other = kv.first.Scalar();
      if (!DidYouMean(other, {key}).empty())
        EMB_THROW(InputError, Where(file_, kv.first) << ": " << what_ << ": unknown key '" << other
                                                     << "'" << DidYouMean(other, {key}));
    }
    EMB_THROW(InputError, Where(file_, node_)
                              << ": " << what_ << ": missing required key '" << key << "'");
  }
  return n;
}

YAML::Node MapReader::OptionalNode(const std::string& key) {
  known_.insert(key);
  const YAML::Node& map = node_;
  return map[key];
}

double AsDouble(const YAML::Node& n, const std::string& file, const std::string& what) {
  double v = 0.0;
  bool ok = n.IsScalar();
  if (ok) {
    try {
      v = n.as<double>();
    } catch (const YAML::Exception&) {
      ok = false;
    }
  }
  EMB_THROW_IF(!ok || !std::isfinite(v),
               Where(file, n) << ": " << what << ": expected a number, got '"
                              << (n.IsScalar() ? n.Scalar() : std::string("a non-scalar")) << "'");
  return v;
}

std::vector<double> AsDoubles(const YAML::Node& n, const std::string& file,
                              const std::string& what) {
  EMB_THROW_IF(!n.IsSequence(), Where(file, n) << ": " << what << ": expected a list of numbers");
  std::vector<double> v;
  for (const auto& x : n) v.push_back(AsDouble(x, file, what));
  return v;
}

double MapReader::GetDouble(const std::string& key) {
  const YAML::Node n = RequireNode(key);
  Note(key, KeyType::kNumber, n);
  return AsDouble(n, file_, what_ + " '" + key + "'");
}
double MapReader::GetDouble(const std::string& key, double fallback) {
  const YAML::Node n = OptionalNode(key);
  if (KeyReadLogActive()) {
    const std::string text = FormatDefault(fallback);
    Note(key, KeyType::kNumber, n, nullptr, &text);
  }
  return n ? AsDouble(n, file_, what_ + " '" + key + "'") : fallback;
}
double MapReader::GetDouble(const std::string& key, const NumberRange& range) {
  const YAML::Node n = RequireNode(key);
  Note(key, KeyType::kNumber, n, &range);
  return CheckNumber(Where(file_, n) + ": " + what_ + " '" + key + "'",
                     AsDouble(n, file_, what_ + " '" + key + "'"), range);
}
double MapReader::GetDouble(const std::string& key, double fallback, const NumberRange& range) {
  const YAML::Node n = OptionalNode(key);
  if (KeyReadLogActive()) {
    const std::string text = FormatDefault(fallback);
    Note(key, KeyType::kNumber, n, &range, &text);
  }
  if (!n) return fallback;
  return CheckNumber(Where(file_, n) + ": " + what_ + " '" + key + "'",
                     AsDouble(n, file_, what_ + " '" + key + "'"), range);
}
int MapReader::GetInt(const std::string& key, int fallback, long long lo, long long hi) {
  const YAML::Node n = OptionalNode(key);
  if (KeyReadLogActive()) {
    const std::string text = std::to_string(fallback), range = FormatIntegerRange(lo, hi);
    Note(key, KeyType::kInteger, n, nullptr, &text, &range);
  }
  if (!n) return fallback;
  const double v = AsDouble(n, file_, what_ + " '" + key + "'");
  EMB_THROW_IF(v != std::floor(v) || v < static_cast<double>(lo) || v > static_cast<double>(hi),
               Where(file_, n) << ": " << what_ << " '" << key << "': expected an integer in ["
                               << lo << ", " << hi << "], got " << n.Scalar());
  return static_cast<int>(v);
}

void CheckUniqueKeys(const YAML::Node& root, const std::string& file) {
  // Iterative (a deep document must not exhaust the stack).
  std::vector<YAML::Node> pending{root};
  while (!pending.empty()) {
    const YAML::Node node = pending.back();
    pending.pop_back();
    if (node.IsMap()) {
      std::map<std::string, int> first_line;
      for (const auto& kv : node) {
        const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : std::string();
        const int line = kv.first.Mark().line + 1;
        const auto [it, inserted] = first_line.emplace(key, line);
        EMB_THROW_IF(!inserted && kv.first.IsScalar(),
                     Where(file, kv.first) << ": key '" << key << "' given twice (first at line "
                                           << it->second << "); expected each key once");
        pending.push_back(kv.second);
      }
    } else if (node.IsSequence()) {
      for (const auto& item : node) pending.push_back(item);
    }
  }
}
bool MapReader::GetBool(const std::string& key, bool fallback) {
  const YAML::Node n = OptionalNode(key);
  if (KeyReadLogActive()) {
    const std::string text = FormatDefault(fallback);
    Note(key, KeyType::kBool, n, nullptr, &text);
  }
  if (!n) return fallback;
  try {
    return n.as<bool>();
  } catch (const YAML::Exception&) {
    EMB_THROW(InputError, Where(file_, n)
                              << ": " << what_ << " '" << key << "': expected true or false");
  }
}
std::string MapReader::GetString(const std::string& key) {
  const YAML::Node n = RequireNode(key);
  const std::string word = n.IsScalar() ? n.Scalar() : std::string();
  Note(key, KeyType::kString, n, nullptr, nullptr, nullptr, &word);
  EMB_THROW_IF(!n.IsScalar(), Where(file_, n)
                                  << ": " << what_ << " '" << key << "': expected a name or word");
  return n.Scalar();
}
std::string MapReader::GetString(const std::string& key, const std::string& fallback) {
  if (Has(key)) return GetString(key);
  known_.insert(key);
  Note(key, KeyType::kString, Lookup(key), nullptr, &fallback);
  return fallback;
}
Eigen::Vector3d MapReader::GetVector3(const std::string& key) {
  const YAML::Node n = RequireNode(key);
  Note(key, KeyType::kVector3, n);
  const std::vector<double> v = AsDoubles(n, file_, what_ + " '" + key + "'");
  EMB_THROW_IF(v.size() != 3, Where(file_, n)
                                  << ": " << what_ << " '" << key
                                  << "': expected 3 numbers [x, y, z], got " << v.size());
  return {v[0], v[1], v[2]};
}
Eigen::Vector3d MapReader::GetVector3(const std::string& key, const Eigen::Vector3d& fallback) {
  if (Has(key)) return GetVector3(key);
  known_.insert(key);
  if (KeyReadLogActive()) {
    const double v[3] = {fallback.x(), fallback.y(), fallback.z()};
    const std::string text = FormatDefault(v);
    Note(key, KeyType::kVector3, Lookup(key), nullptr, &text);
  }
  return fallback;
}
std::vector<double> MapReader::GetDoubles(const std::string& key) {
  const YAML::Node n = RequireNode(key);
  Note(key, KeyType::kNumbers, n);
  return AsDoubles(n, file_, what_ + " '" + key + "'");
}

void MapReader::Finish() const {
  for (const auto& kv : node_) {
    const std::string key = kv.first.Scalar();
    if (!known_.count(key)) {
      const std::vector<std::string> cands(known_.begin(), known_.end());
      EMB_THROW(InputError, Where(file_, kv.first) << ": " << what_ << ": unknown key '" << key
                                                   << "'" << DidYouMean(key, cands));
    }
  }
}

}  // namespace emb::scene
