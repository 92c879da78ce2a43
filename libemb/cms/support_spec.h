#pragma once
/// @file
/// What a user asks to hold in a modal analysis, as text (the `emb modes` options):
///  - `GROUP[:COMPS]` held components of every node of a group (COMPS ⊆ {x, y, z}, global
///    axes, comma separated; all three if omitted). GROUP may be `A&B`: the nodes in both
///    groups (an edge where two faces meet).
///  - `GROUP[:x|y|z]` a symmetry plane: the displacement normal to the plane is held at every
///    node of the group, u·n = 0. Without an axis, n is the plane's own normal (which may be
///    oblique); with one, the group must lie in a plane normal to that axis.
///  - `GROUP[@x,y,z]:COMPS` a distributing support: the group condensed to one reference node
///    (RBE2 or RBE3, libemb/cms/interface.h) whose components COMPS ⊆ {x, y, z, rx, ry, rz}
///    are held (translations [m] and small rotations [rad] of the reference node, global axes).
///  - an equation `a₁ N₁ c₁ a₂ N₂ c₂ …`: Σ_i a_i u_{N_i, c_i} = 0 between node displacements
///    (N: the mesh file's node tag, c: x, y or z, a: a non-zero number).

#include <array>
#include <string>
#include <vector>

#include "libemb/cms/interface.h"

namespace emb {

/// Held global components of the nodes of a group (or of the common nodes of several).
struct ComponentSupport {
  std::vector<std::string> groups;    ///< one group, or several whose common nodes are held
  std::array<bool, 3> held{};         ///< x, y, z
  std::string text;                   ///< as given, for messages
  /// Parses "GROUP[&GROUP…][:x,y,z]". @throws InputError naming the text and the bad part.
  static ComponentSupport Parse(const std::string& text);
};

/// A symmetry plane: u·n = 0 on the group's nodes.
struct SymmetrySupport {
  std::string group;
  int axis{-1};      ///< 0, 1, 2 for x, y, z; −1: the plane's own normal
  std::string text;
  /// Parses "GROUP[:x|y|z]". @throws InputError.
  static SymmetrySupport Parse(const std::string& text);
};

/// A reference node on a group (RBE2 or RBE3) with some of its six components held.
struct ReferenceSupport {
  InterfaceSpec interface;      ///< group, coupling, optional point
  std::array<bool, 6> held{};   ///< x, y, z, rx, ry, rz
  std::string text;
  /// Parses "GROUP[@x,y,z]:COMPS" for the given coupling. @throws InputError.
  static ReferenceSupport Parse(const std::string& text, Coupling coupling);
};

/// Σ_i a_i u_{N_i, c_i} = 0.
struct NodeEquation {
  struct Term {
    std::size_t node_tag{0};
    int component{0};
    double coefficient{0.0};
  };
  std::vector<Term> terms;
  std::string source;  ///< "--equation 2" or "FILE:LINE", for messages
  /// Parses "a N c a N c …". @throws InputError naming `source` and the bad token.
  static NodeEquation Parse(const std::string& text, const std::string& source);
};

/// Reads equations from a text file, one per line (`#` starts a comment, blank lines are
/// skipped). @throws InputError for an unreadable file or a bad line (FILE:LINE).
std::vector<NodeEquation> ReadEquationFile(const std::string& path);

/// Everything held, in the order the options were given within each kind.
struct SupportSpecs {
  std::vector<ComponentSupport> fixed;
  std::vector<SymmetrySupport> symmetry;
  std::vector<ReferenceSupport> reference;
  std::vector<NodeEquation> equations;
  bool empty() const {
    return fixed.empty() && symmetry.empty() && reference.empty() && equations.empty();
  }
};

/// "x", "y", "z", "rx", "ry", "rz" for 0…5.
const char* ComponentName(int c);

}  // namespace emb
