#include "libemb/cms/support_spec.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "libemb/common/error.h"

namespace emb {
namespace {

std::vector<std::string> Split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(s);
  while (std::getline(in, item, sep)) out.push_back(item);
  if (!s.empty() && s.back() == sep) out.push_back("");
  return out;
}

// "x,z" → flags over the first `count` names of {x, y, z, rx, ry, rz}.
template <size_t N>
std::array<bool, N> ParseComponents(const std::string& list, const std::string& text,
                                    const std::string& option, const char* expected) {
  std::array<bool, N> held{};
  EMB_THROW_IF(list.empty(), option << " '" << text << "': expected components after ':' ("
                                    << expected << "), got none");
  for (const std::string& c : Split(list, ',')) {
    int k = -1;
    for (size_t i = 0; i < N; ++i)
      if (c == ComponentName(static_cast<int>(i))) k = static_cast<int>(i);
    EMB_THROW_IF(k < 0, option << " '" << text << "': expected components from " << expected
                               << " separated by commas, got '" << c << "'");
    EMB_THROW_IF(held[k], option << " '" << text << "': component '" << c << "' is given twice");
    held[k] = true;
  }
  return held;
}

// Splits "HEAD:TAIL" at the last ':' (TAIL empty and has_tail false when there is none).
void SplitTail(const std::string& text, std::string* head, std::string* tail, bool* has_tail) {
  const auto colon = text.rfind(':');
  *has_tail = colon != std::string::npos;
  *head = *has_tail ? text.substr(0, colon) : text;
  *tail = *has_tail ? text.substr(colon + 1) : "";
}

void CheckGroupName(const std::string& name, const std::string& text, const std::string& option) {
  EMB_THROW_IF(name.empty() || name.find_first_of(" \t@:&") != std::string::npos,
               option << " '" << text << "': expected a physical group name, got '" << name
                      << "'");
}

}  // namespace

const char* ComponentName(int c) {
  static const char* const kNames[] = {"x", "y", "z", "rx", "ry", "rz"};
  return c >= 0 && c < 6 ? kNames[c] : "?";
}

ComponentSupport ComponentSupport::Parse(const std::string& text) {
  ComponentSupport s;
  s.text = text;
  std::string head, tail;
  bool has_tail = false;
  SplitTail(text, &head, &tail, &has_tail);
  s.groups = Split(head, '&');
  EMB_THROW_IF(s.groups.empty(), "--fixed '" << text << "': expected GROUP[:x,y,z]");
  for (const auto& g : s.groups) CheckGroupName(g, text, "--fixed");
  s.held = has_tail ? ParseComponents<3>(tail, text, "--fixed", "x, y, z")
                    : std::array<bool, 3>{true, true, true};
  return s;
}

SymmetrySupport SymmetrySupport::Parse(const std::string& text) {
  SymmetrySupport s;
  s.text = text;
  std::string tail;
  bool has_tail = false;
  SplitTail(text, &s.group, &tail, &has_tail);
  CheckGroupName(s.group, text, "--symmetry");
  if (has_tail) {
    EMB_THROW_IF(tail != "x" && tail != "y" && tail != "z",
                 "--symmetry '" << text << "': expected the plane's normal axis x, y or z, got '"
                                << tail << "'");
    s.axis = tail[0] - 'x';
  }
  return s;
}

ReferenceSupport ReferenceSupport::Parse(const std::string& text, Coupling coupling) {
  const std::string option = std::string("--") + Name(coupling);
  std::string head, tail;
  bool has_tail = false;
  SplitTail(text, &head, &tail, &has_tail);
  EMB_THROW_IF(!has_tail, option << " '" << text
                                 << "': expected GROUP[@x,y,z]:COMPS with the held components "
                                    "of the reference node (x, y, z, rx, ry, rz)");
  ReferenceSupport s;
  s.text = text;
  // The group and point are an interface's (without the coupling, which the option gives).
  EMB_THROW_IF(head.find(':') != std::string::npos,
               option << " '" << text << "': expected GROUP[@x,y,z]:COMPS");
  s.interface = InterfaceSpec::Parse(head);
  s.interface.coupling = coupling;
  s.held = ParseComponents<6>(tail, text, option, "x, y, z, rx, ry, rz");
  return s;
}

NodeEquation NodeEquation::Parse(const std::string& text, const std::string& source) {
  NodeEquation e;
  e.source = source;
  std::istringstream in(text);
  std::vector<std::string> tok;
  for (std::string t; in >> t;) tok.push_back(t);
  EMB_THROW_IF(tok.empty() || tok.size() % 3 != 0,
               source << ": expected terms 'COEFFICIENT NODE_TAG COMPONENT' (e.g. '1 12 x -1 40 "
                         "x' for u_x(12) = u_x(40)), got '"
                      << text << "'");
  for (size_t k = 0; k < tok.size(); k += 3) {
    Term t;
    std::size_t used = 0;
    try {
      t.coefficient = std::stod(tok[k], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    EMB_THROW_IF(used != tok[k].size() || !std::isfinite(t.coefficient) || t.coefficient == 0.0,
                 source << ": expected a non-zero coefficient, got '" << tok[k] << "'");
    try {
      used = 0;
      const long long tag = std::stoll(tok[k + 1], &used);
      EMB_THROW_IF(tag <= 0, "");
      t.node_tag = static_cast<std::size_t>(tag);
    } catch (const std::exception&) {
      used = 0;
    }
    EMB_THROW_IF(used != tok[k + 1].size(),
                 source << ": expected a node tag (a positive integer), got '" << tok[k + 1] << "'");
    const std::string& c = tok[k + 2];
    EMB_THROW_IF(c != "x" && c != "y" && c != "z",
                 source << ": expected component x, y or z, got '" << c << "'");
    t.component = c[0] - 'x';
    for (const Term& o : e.terms)
      EMB_THROW_IF(o.node_tag == t.node_tag && o.component == t.component,
                   source << ": node " << t.node_tag << " component " << c
                          << " appears twice; combine the coefficients");
    e.terms.push_back(t);
  }
  return e;
}

std::vector<NodeEquation> ReadEquationFile(const std::string& path) {
  std::ifstream in(path);
  EMB_THROW_IF(!in, "--equations '" << path << "': cannot open the file");
  std::vector<NodeEquation> out;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    out.push_back(NodeEquation::Parse(line, path + ":" + std::to_string(n)));
  }
  EMB_THROW_IF(out.empty(), "--equations '" << path << "': the file holds no equation");
  return out;
}

}  // namespace emb
