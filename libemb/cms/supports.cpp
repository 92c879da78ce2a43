#include "libemb/cms/supports.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "libemb/common/error.h"
#include "libemb/common/skew.h"
#include "libemb/fe/assembly.h"

namespace emb {
namespace {

// The group `name` of a support given as `option` (for the message).
const PhysicalGroup& FindGroup(const Mesh& mesh, const std::string& name, const std::string& option) {
  for (const auto& g : mesh.groups)
    if (g.name == name) return g;
  EMB_THROW(InputError, option << ": mesh '" << mesh.source << "' has no physical group '" << name
                               << "'; expected one of: " << mesh.GroupNames());
}

// The nodes of `groups` (all of them: the intersection of several).
std::vector<int> CommonNodes(const Mesh& mesh, const ComponentSupport& s) {
  std::vector<int> nodes;
  for (size_t k = 0; k < s.groups.size(); ++k) {
    const PhysicalGroup& g = FindGroup(mesh, s.groups[k], "--fixed " + s.text);
    EMB_THROW_IF(g.nodes.empty(), "--fixed '" << s.text << "': physical group '" << g.name
                                              << "' has no mesh nodes");
    if (k == 0) {
      nodes = g.nodes;
    } else {
      std::vector<int> both;
      std::set_intersection(nodes.begin(), nodes.end(), g.nodes.begin(), g.nodes.end(),
                            std::back_inserter(both));
      nodes = std::move(both);
    }
  }
  EMB_THROW_IF(nodes.empty(), "--fixed '" << s.text << "': the groups have no node in common");
  return nodes;
}

// Adds to the Gram matrix of the rigid motions the row's direction a = c·R (unit weight).
void AddRigidRow(const Mesh& mesh, const Supports& s, const LinearConstraint& row,
                 const Eigen::Vector3d& center, double L, Eigen::Matrix<double, 6, 6>* gram) {
  Eigen::Matrix<double, 1, 6> a = Eigen::Matrix<double, 1, 6>::Zero();
  double size = 0.0;
  for (const auto& [j, c] : row.terms) {
    Eigen::Matrix<double, 3, 6> R;  // rigid motions of the point that unknown j moves with
    int comp = 0;
    if (j < s.num_dofs) {
      comp = j % 3;
      R << Eigen::Matrix3d::Identity(), -Skew((mesh.nodes.col(j / 3) - center) / L);
    } else {
      int r = 0;
      while (s.reference_column[r] < 0 || j >= s.reference_column[r] + 6) ++r;
      const int k = j - s.reference_column[r];
      if (k < 3) {
        comp = k;
        R << Eigen::Matrix3d::Identity(), -Skew((s.references[r].point - center) / L);
      } else {
        comp = k - 3;
        R << Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Identity() / L;
      }
    }
    a += c * R.row(comp);
    size += std::abs(c) * R.row(comp).norm();
  }
  // A row that no rigid motion moves (its terms cancel) holds none.
  if (a.norm() > 1e-12 * size) *gram += a.transpose() * a / a.squaredNorm();
}

}  // namespace

bool Supports::IsSelection() const {
  for (const auto& r : rows)
    if (r.terms.size() != 1 || r.terms[0].first >= num_dofs) return false;
  return true;
}

std::vector<int> Supports::HeldDofs() const {
  EMB_CHECK(IsSelection());
  std::vector<int> held;
  for (const auto& r : rows) held.push_back(r.terms[0].first);
  std::sort(held.begin(), held.end());
  return held;
}

SparseMatrix Supports::DofBasis() const { return elimination.T.topRows(num_dofs); }

ModalOptions Supports::Apply(ModalOptions options) const {
  if (IsSelection()) {
    options.fixed_dofs = HeldDofs();
  } else {
    options.basis = DofBasis();
  }
  options.expected_rigid_modes = expected_rigid_modes;
  return options;
}

Supports BuildSupports(const Mesh& mesh, const SupportSpecs& specs) {
  Supports s;
  s.num_dofs = 3 * mesh.num_nodes();
  const int n = s.num_dofs;
  std::vector<std::string> parts;
  enum Kind { kHold, kLink, kReferenceHold, kRbe3, kSymmetry, kEquation };
  std::vector<Kind> kind;
  auto add_row = [&](LinearConstraint row, Kind k, std::string source) {
    s.rows.push_back(std::move(row));
    kind.push_back(k);
    s.row_source.push_back(std::move(source));
  };
  // 1. Held components, each unknown once (groups sharing an edge hold it twice).
  std::vector<int> held_by(n, -1);  // index into the source texts
  std::vector<std::string> hold_text;
  auto hold = [&](int dof, const std::string& text) {
    if (held_by[dof] >= 0) return;
    held_by[dof] = static_cast<int>(hold_text.size()) - 1;
    add_row({{{dof, 1.0}}, dof}, kHold, text);
  };
  for (const auto& f : specs.fixed) {
    hold_text.push_back("--fixed " + f.text);
    parts.push_back(hold_text.back());
    for (int a : CommonNodes(mesh, f))
      for (int i = 0; i < 3; ++i)
        if (f.held[i]) hold(Dof(a, i), hold_text.back());
  }
  std::vector<std::pair<const SymmetrySupport*, Eigen::Vector3d>> oblique;
  for (const auto& sym : specs.symmetry) {
    const PhysicalGroup& g = FindGroup(mesh, sym.group, "--symmetry " + sym.text);
    EMB_THROW_IF(g.nodes.empty(), "--symmetry '" << sym.text << "': physical group '" << g.name
                                                 << "' has no mesh nodes");
    const std::optional<Eigen::Vector3d> normal = PlaneNormal(mesh, g);
    EMB_THROW_IF(!normal && (sym.axis < 0 || !g.faces.empty()),
                 "--symmetry '" << sym.text << "': expected a planar surface group, got "
                                << (g.faces.empty() ? "a group without faces (give the axis)"
                                                    : "a curved surface"));
    hold_text.push_back("--symmetry " + sym.text);
    parts.push_back(hold_text.back());
    int axis = sym.axis;
    if (normal) {
      int closest = 0;
      normal->cwiseAbs().maxCoeff(&closest);
      // Axis-aligned to 1e-8: the plane's own normal is that axis.
      const bool aligned = std::abs((*normal)[closest]) > 1.0 - 1e-8;
      EMB_THROW_IF(sym.axis >= 0 && (!aligned || closest != sym.axis),
                   "--symmetry '" << sym.text << "': the plane's normal is ("
                                  << normal->transpose() << "), not the " << "xyz"[sym.axis]
                                  << " axis");
      if (aligned) axis = closest;
      else oblique.emplace_back(&sym, *normal);
    }
    if (axis >= 0)
      for (int a : g.nodes) hold(Dof(a, axis), hold_text.back());
  }
  s.num_held_components = static_cast<int>(s.rows.size());
  // Reference supports, resolved together (overlaps and repeats are refused there).
  std::vector<InterfaceSpec> itf_specs;
  for (const auto& r : specs.reference) itf_specs.push_back(r.interface);
  s.references = ResolveInterfaces(mesh, itf_specs);
  int columns = n;
  for (size_t r = 0; r < specs.reference.size(); ++r) {
    s.reference_held.push_back(specs.reference[r].held);
    const bool rbe2 = s.references[r].coupling == Coupling::kRbe2;
    s.reference_column.push_back(rbe2 ? columns : -1);
    if (rbe2) columns += 6;
    parts.push_back(std::string("--") + Name(s.references[r].coupling) + " " +
                    specs.reference[r].text);
  }
  // 2. RBE2 links, 3. held RBE2 components.
  for (size_t r = 0; r < s.references.size(); ++r) {
    const Interface& itf = s.references[r];
    if (itf.coupling != Coupling::kRbe2) continue;
    const std::string src = "--rbe2 " + specs.reference[r].text;
    const int q0 = s.reference_column[r];
    for (int a : itf.nodes) {
      const Eigen::Matrix<double, 3, 6> B = itf.RigidMap(mesh.nodes.col(a));
      for (int i = 0; i < 3; ++i) {
        EMB_THROW_IF(held_by[Dof(a, i)] >= 0,
                     src << ": node " << mesh.node_tags[a] << " is slaved to the reference node "
                         << "and its " << "xyz"[i] << " component is also held by "
                         << hold_text[held_by[Dof(a, i)]]
                         << "; hold the reference node's components instead");
        LinearConstraint row{{{Dof(a, i), 1.0}}, Dof(a, i)};
        for (int c = 0; c < 6; ++c)
          if (B(i, c) != 0.0) row.terms.emplace_back(q0 + c, -B(i, c));
        add_row(std::move(row), kLink, src);
      }
    }
    for (int c = 0; c < 6; ++c)
      if (s.reference_held[r][c])
        add_row({{{q0 + c, 1.0}}, q0 + c}, kReferenceHold, src + " (" + ComponentName(c) + ")");
  }
  // 4. Held RBE3 components.
  for (size_t r = 0; r < s.references.size(); ++r) {
    const Interface& itf = s.references[r];
    if (itf.coupling != Coupling::kRbe3) continue;
    const Eigen::MatrixXd W = itf.AveragingOperator(mesh);
    for (int c = 0; c < 6; ++c) {
      if (!s.reference_held[r][c]) continue;
      LinearConstraint row;
      for (size_t k = 0; k < itf.nodes.size(); ++k)
        for (int i = 0; i < 3; ++i)
          if (W(c, 3 * k + i) != 0.0) row.terms.emplace_back(Dof(itf.nodes[k], i), W(c, 3 * k + i));
      add_row(std::move(row), kRbe3,
              "--rbe3 " + specs.reference[r].text + " (component " + ComponentName(c) + ")");
    }
  }
  // 5. Oblique symmetry planes.
  for (const auto& [sym, nrm] : oblique)
    for (int a : mesh.group(sym->group).nodes) {
      LinearConstraint row;
      for (int i = 0; i < 3; ++i)
        if (nrm[i] != 0.0) row.terms.emplace_back(Dof(a, i), nrm[i]);
      add_row(std::move(row), kSymmetry,
              "--symmetry " + sym->text + " (node " + std::to_string(mesh.node_tags[a]) + ")");
    }
  // 6. Equations between nodes.
  std::unordered_map<std::size_t, int> node_of_tag;
  if (!specs.equations.empty())
    for (int a = 0; a < mesh.num_nodes(); ++a) node_of_tag[mesh.node_tags[a]] = a;
  for (const auto& e : specs.equations) {
    LinearConstraint row;
    for (const auto& t : e.terms) {
      const auto it = node_of_tag.find(t.node_tag);
      EMB_THROW_IF(it == node_of_tag.end(), e.source << ": mesh '" << mesh.source
                                                     << "' has no node with tag " << t.node_tag);
      row.terms.emplace_back(Dof(it->second, t.component), t.coefficient);
    }
    add_row(std::move(row), kEquation, e.source);
  }
  if (!specs.equations.empty()) parts.push_back(std::to_string(specs.equations.size()) + " equations");

  s.elimination = EliminateConstraints(columns, s.rows);
  for (int r : s.elimination.dependent_rows) {
    EMB_THROW_IF(kind[r] != kSymmetry,
                 s.row_source[r] << ": this constraint is implied by (or conflicts with) the "
                                    "supports before it: remove it");
    ++s.num_redundant_rows;
  }
  s.description.clear();
  for (size_t k = 0; k < parts.size(); ++k) s.description += (k ? "; " : "") + parts[k];
  bool any_u = false;
  for (int j : s.elimination.masters) any_u = any_u || j < n;
  EMB_THROW_IF(!any_u, "the supports (" << s.description << ") hold all " << n
                                        << " unknowns of the part: nothing is left to vibrate");

  // Rigid motions left: 6 − rank(C R), rotations scaled by the part's size.
  const Eigen::Vector3d lo = mesh.nodes.rowwise().minCoeff(), hi = mesh.nodes.rowwise().maxCoeff();
  const Eigen::Vector3d center = 0.5 * (lo + hi);
  const double L = std::max((hi - lo).norm(), 1e-300);
  Eigen::Matrix<double, 6, 6> gram = Eigen::Matrix<double, 6, 6>::Zero();
  for (const auto& row : s.rows) AddRigidRow(mesh, s, row, center, L, &gram);
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>>(gram)
                                 .eigenvalues();
  int rank = 0;
  // Each row adds a unit of trace; a new direction adds at least ~1 (a row's own component
  // across the others), round-off ~1e-16 per row.
  for (int k = 0; k < 6; ++k) rank += ev[k] > 1e-9 * std::max(1.0, gram.trace());
  s.expected_rigid_modes = 6 - rank;
  return s;
}

double ConstraintResidual(const Supports& supports, const ModalResult& modes) {
  const Eigen::MatrixXd x = modes.basis_coordinates.cols() > 0
                                ? Eigen::MatrixXd(supports.elimination.T * modes.basis_coordinates)
                                : modes.eig.vectors;
  double worst = 0.0;
  for (int k = 0; k < x.cols(); ++k) {
    const double xmax = x.col(k).cwiseAbs().maxCoeff();
    if (!(xmax > 0)) continue;
    for (const auto& row : supports.rows) {
      double v = 0.0, scale = 0.0;
      for (const auto& [j, a] : row.terms) {
        v += a * x(j, k);
        scale += std::abs(a);
      }
      worst = std::max(worst, std::abs(v) / (scale * xmax));
    }
  }
  return worst;
}

}  // namespace emb
