#include "libemb/cms/interface.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <regex>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/common/skew.h"

namespace emb {
namespace {

// Corners of a face cell (the first 3 or 4 nodes of a gmsh triangle or quadrangle).
int NumCorners(CellType t) {
  switch (t) {
    case CellType::kTri3: case CellType::kTri6: return 3;
    case CellType::kQuad4: case CellType::kQuad8: return 4;
    default: return 0;
  }
}

struct FaceGeometry {
  double area{0.0};
  Eigen::Vector3d normal{Eigen::Vector3d::Zero()};    // unit
  Eigen::Vector3d centroid{Eigen::Vector3d::Zero()};  // of the corner polygon
};

// Area, normal and centroid of the polygon through the corners (a quadrangle as two
// triangles), which is exact for straight-sided planar faces.
FaceGeometry CornerPolygon(const Mesh& mesh, const int* v, int corners) {
  FaceGeometry g;
  Eigen::Vector3d twice_area_vec = Eigen::Vector3d::Zero();
  const Eigen::Vector3d x0 = mesh.nodes.col(v[0]);
  for (int k = 1; k + 1 < corners; ++k) {
    const Eigen::Vector3d a = mesh.nodes.col(v[k]) - x0, b = mesh.nodes.col(v[k + 1]) - x0;
    const Eigen::Vector3d n = a.cross(b);
    twice_area_vec += n;
    g.centroid += 0.5 * n.norm() * (x0 + mesh.nodes.col(v[k]) + mesh.nodes.col(v[k + 1])) / 3.0;
  }
  g.area = 0.5 * twice_area_vec.norm();
  if (g.area > 0) {
    g.normal = twice_area_vec.normalized();
    g.centroid /= g.area;
  }
  return g;
}

int Find(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Number of pieces of the surface: faces are joined when they share a node.
int CountPieces(const PhysicalGroup& g, int num_nodes) {
  std::vector<int> parent(num_nodes);
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& b : g.faces)
    for (int c = 0; c < b.num_cells(); ++c) {
      const int* v = b.cell(c);
      for (int k = 1; k < b.nodes_per_cell(); ++k) parent[Find(parent, v[k])] = Find(parent, v[0]);
    }
  std::vector<int> roots;
  for (const auto& b : g.faces)
    for (int c = 0; c < b.num_cells(); ++c) roots.push_back(Find(parent, b.cell(c)[0]));
  std::sort(roots.begin(), roots.end());
  return static_cast<int>(std::unique(roots.begin(), roots.end()) - roots.begin());
}

struct CylinderFit {
  Eigen::Vector3d axis, center;  // center: a point on the axis
  double radius{0.0};
  double max_deviation{0.0};     // max |distance to axis − radius| [m]
};

// Radial residuals of the nodes for axis a through c with radius R.
Eigen::VectorXd RadialResiduals(const Eigen::Matrix3Xd& x, const Eigen::Vector3d& a,
                                const Eigen::Vector3d& c, double R) {
  Eigen::VectorXd r(x.cols());
  for (int s = 0; s < x.cols(); ++s) {
    const Eigen::Vector3d d = x.col(s) - c;
    r[s] = (d - a.dot(d) * a).norm() - R;
  }
  return r;
}

// Least-squares cylinder through the points x, starting from the axis direction a0:
// Kåsa circle fit in the plane normal to a0, then Gauss–Newton on (axis tilt 2, centre shift 2,
// radius) with finite-difference Jacobians (5 parameters, a few thousand points).
CylinderFit FitCylinder(const Eigen::Matrix3Xd& x, Eigen::Vector3d a) {
  a.normalize();
  // Orthonormal frame (e1, e2) normal to a.
  auto frame = [](const Eigen::Vector3d& axis, Eigen::Vector3d& e1, Eigen::Vector3d& e2) {
    e1 = axis.unitOrthogonal();
    e2 = axis.cross(e1);
  };
  Eigen::Vector3d e1, e2;
  frame(a, e1, e2);
  const Eigen::Vector3d mean = x.rowwise().mean();
  const int n = static_cast<int>(x.cols());
  // Kåsa: u² + v² + D u + E v + F = 0.
  Eigen::MatrixXd A(n, 3);
  Eigen::VectorXd b(n);
  for (int s = 0; s < n; ++s) {
    const Eigen::Vector3d d = x.col(s) - mean;
    const double u = d.dot(e1), v = d.dot(e2);
    A.row(s) << u, v, 1.0;
    b[s] = -(u * u + v * v);
  }
  const Eigen::Vector3d def = A.colPivHouseholderQr().solve(b);
  Eigen::Vector3d c = mean - 0.5 * def[0] * e1 - 0.5 * def[1] * e2;
  double R = std::sqrt(std::max(0.0, 0.25 * (def[0] * def[0] + def[1] * def[1]) - def[2]));
  for (int it = 0; it < 20; ++it) {
    frame(a, e1, e2);
    auto apply = [&](const Eigen::Matrix<double, 5, 1>& p, Eigen::Vector3d& ap, Eigen::Vector3d& cp,
                     double& Rp) {
      ap = (a + p[0] * e1 + p[1] * e2).normalized();
      cp = c + p[2] * e1 + p[3] * e2;
      Rp = R + p[4];
    };
    const Eigen::VectorXd r0 = RadialResiduals(x, a, c, R);
    Eigen::MatrixXd J(n, 5);
    for (int k = 0; k < 5; ++k) {
      Eigen::Matrix<double, 5, 1> p = Eigen::Matrix<double, 5, 1>::Zero();
      const double h = (k < 2 ? 1e-6 : 1e-6 * std::max(R, 1e-3));
      Eigen::Vector3d ap, cp;
      double Rp;
      p[k] = h;
      apply(p, ap, cp, Rp);
      const Eigen::VectorXd rp = RadialResiduals(x, ap, cp, Rp);
      p[k] = -h;
      apply(p, ap, cp, Rp);
      J.col(k) = (rp - RadialResiduals(x, ap, cp, Rp)) / (2 * h);
    }
    const Eigen::Matrix<double, 5, 1> dp = J.colPivHouseholderQr().solve(-r0);
    Eigen::Vector3d an, cn;
    double Rn;
    apply(dp, an, cn, Rn);
    a = an;
    c = cn;
    R = Rn;
    if (dp.norm() < 1e-13 * (1.0 + R)) break;
  }
  CylinderFit f;
  f.axis = a;
  // Mid-width: the middle of the nodes' extent along the axis.
  double tmin = 1e300, tmax = -1e300;
  for (int s = 0; s < n; ++s) {
    const double t = a.dot(x.col(s) - c);
    tmin = std::min(tmin, t);
    tmax = std::max(tmax, t);
  }
  f.center = c + 0.5 * (tmin + tmax) * a;
  f.radius = R;
  f.max_deviation = RadialResiduals(x, a, c, R).cwiseAbs().maxCoeff();
  return f;
}

Interface Resolve(const Mesh& mesh, const InterfaceSpec& spec) {
  EMB_THROW_IF(std::none_of(mesh.groups.begin(), mesh.groups.end(),
                           [&](const PhysicalGroup& g) { return g.name == spec.group; }),
               "interface '" << spec.group << "': mesh '" << mesh.source
                             << "' has no physical group of that name; expected one of: "
                             << mesh.GroupNames());
  const PhysicalGroup& g = mesh.group(spec.group);
  EMB_THROW_IF(g.dim != 2, "interface '" << spec.group << "': expected a surface group, got a "
                                         << g.dim << "-D group");
  EMB_THROW_IF(g.nodes.empty(), "interface '" << spec.group << "': the group has no nodes");
  int num_faces = 0;
  for (const auto& b : g.faces) {
    EMB_THROW_IF(NumCorners(b.type) == 0, "interface '" << spec.group
                                                        << "': expected triangle or quadrangle "
                                                           "faces, got "
                                                        << Name(b.type));
    num_faces += b.num_cells();
  }
  EMB_THROW_IF(num_faces == 0, "interface '" << spec.group
                                             << "': the group has no surface cells (faces are "
                                                "needed for the weights)");
  const int pieces = CountPieces(g, mesh.num_nodes());
  EMB_THROW_IF(pieces != 1, "interface '" << spec.group << "': expected one connected surface, got "
                                          << pieces << " disconnected pieces (split it into "
                                                       "separate groups)");
  Interface itf;
  itf.name = spec.group;
  itf.coupling = spec.coupling;
  itf.nodes = g.nodes;
  itf.weights = Eigen::VectorXd::Zero(g.nodes.size());
  // Face areas shared equally by their nodes; face normals for the shape test.
  Eigen::Matrix3d normal_moment = Eigen::Matrix3d::Zero();
  Eigen::Vector3d area_centroid = Eigen::Vector3d::Zero();
  for (const auto& b : g.faces) {
    const int nc = b.nodes_per_cell();
    for (int c = 0; c < b.num_cells(); ++c) {
      const int* v = b.cell(c);
      const FaceGeometry fg = CornerPolygon(mesh, v, NumCorners(b.type));
      itf.area += fg.area;
      normal_moment += fg.area * fg.normal * fg.normal.transpose();
      area_centroid += fg.area * fg.centroid;
      for (int k = 0; k < nc; ++k) {
        const auto it = std::lower_bound(g.nodes.begin(), g.nodes.end(), v[k]);
        EMB_CHECK(it != g.nodes.end() && *it == v[k]);
        itf.weights[it - g.nodes.begin()] += fg.area / nc;
      }
    }
  }
  EMB_THROW_IF(!(itf.area > 0), "interface '" << spec.group << "': the surface has zero area");
  area_centroid /= itf.area;

  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(normal_moment / itf.area);
  const Eigen::Vector3d lam = es.eigenvalues();  // ascending, sum 1
  // All normals parallel (a plane) up to round-off; a curved surface spreads them.
  const bool planar = lam[1] < 1e-8;
  if (spec.point) {
    itf.point = *spec.point;
    itf.point_source = "given";
  } else if (planar) {
    itf.point = area_centroid;
    itf.point_source = "plane centroid";
  } else {
    Eigen::Matrix3Xd x(3, g.nodes.size());
    for (size_t s = 0; s < g.nodes.size(); ++s) x.col(s) = mesh.nodes.col(g.nodes[s]);
    const CylinderFit fit = FitCylinder(x, es.eigenvectors().col(0));
    // gmsh puts every node on the CAD surface, so a cylinder fits to round-off; 1e-4 of the
    // radius allows for a mesh read back from a file with few digits.
    const double tol = 1e-4 * fit.radius;
    EMB_THROW_IF(!(fit.radius > 0) || !(fit.max_deviation <= tol),
                 "interface '" << spec.group
                               << "': cannot place its reference point: the surface is neither "
                                  "planar nor cylindrical (cylinder fit deviates by "
                               << fit.max_deviation << " m); give it as " << spec.group << ":"
                               << Name(spec.coupling) << "@x,y,z");
    itf.point = fit.center;
    itf.axis = fit.axis;
    itf.radius = fit.radius;
    itf.point_source = "cylinder axis, mid-width";
  }
  return itf;
}

}  // namespace

std::optional<Eigen::Vector3d> PlaneNormal(const Mesh& mesh, const PhysicalGroup& group) {
  Eigen::Matrix3d normal_moment = Eigen::Matrix3d::Zero();
  double area = 0.0;
  for (const auto& b : group.faces) {
    if (NumCorners(b.type) == 0) return std::nullopt;
    for (int c = 0; c < b.num_cells(); ++c) {
      const FaceGeometry fg = CornerPolygon(mesh, b.cell(c), NumCorners(b.type));
      area += fg.area;
      normal_moment += fg.area * fg.normal * fg.normal.transpose();
    }
  }
  if (!(area > 0)) return std::nullopt;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(normal_moment / area);
  // Same planarity test as an interface's (Resolve).
  if (!(es.eigenvalues()[1] < 1e-8)) return std::nullopt;
  return Eigen::Vector3d(es.eigenvectors().col(2));
}

const char* Name(Coupling c) { return c == Coupling::kRbe2 ? "rbe2" : "rbe3"; }

InterfaceSpec InterfaceSpec::Parse(const std::string& text) {
  static const std::regex re(
      R"(^([^:@\s]+)(?::(rbe2|rbe3|RBE2|RBE3))?(?:@([^,]+),([^,]+),([^,]+))?$)");
  std::smatch m;
  EMB_THROW_IF(!std::regex_match(text, m, re),
               "interface '" << text << "': expected NAME[:rbe2|rbe3][@x,y,z]");
  InterfaceSpec s;
  s.group = m[1];
  if (m[2].matched) s.coupling = (m[2] == "rbe2" || m[2] == "RBE2") ? Coupling::kRbe2 : Coupling::kRbe3;
  if (m[3].matched) {
    Eigen::Vector3d p;
    for (int k = 0; k < 3; ++k) {
      const std::string v = m[3 + k];
      std::size_t used = 0;
      try {
        p[k] = std::stod(v, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      EMB_THROW_IF(used != v.size() || !std::isfinite(p[k]),
                   "interface '" << text << "': expected a number for coordinate " << "xyz"[k]
                                 << ", got '" << v << "'");
    }
    s.point = p;
  }
  return s;
}

std::string InterfaceSpec::ToString() const {
  std::ostringstream o;
  o << group << ":" << Name(coupling);
  if (point) o << "@" << point->x() << "," << point->y() << "," << point->z();
  return o.str();
}

Eigen::Matrix<double, 3, 6> Interface::RigidMap(const Eigen::Vector3d& x_s) const {
  Eigen::Matrix<double, 3, 6> B;
  B << Eigen::Matrix3d::Identity(), -Skew(x_s - point);
  return B;
}

Eigen::MatrixXd Interface::AveragingOperator(const Mesh& mesh) const {
  const int ns = static_cast<int>(nodes.size());
  // Rotations scaled by the surface's radius of gyration about p, so G is well scaled.
  double r2 = 0.0;
  for (int s = 0; s < ns; ++s) r2 += weights[s] * (mesh.nodes.col(nodes[s]) - point).squaredNorm();
  const double L = std::sqrt(r2 / area);
  Eigen::Matrix<double, 6, 6> scale = Eigen::Matrix<double, 6, 6>::Identity();
  scale.bottomRightCorner<3, 3>() *= L > 0 ? 1.0 / L : 1.0;
  Eigen::MatrixXd WB(6, 3 * ns);  // columns w_s (B_s S)ᵀ
  Eigen::Matrix<double, 6, 6> G = Eigen::Matrix<double, 6, 6>::Zero();
  for (int s = 0; s < ns; ++s) {
    const Eigen::Matrix<double, 3, 6> B = RigidMap(mesh.nodes.col(nodes[s])) * scale;
    G += weights[s] * B.transpose() * B;
    WB.middleCols(3 * s, 3) = weights[s] * B.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> es(G);
  EMB_THROW_IF(!(es.eigenvalues()[0] > 1e-10 * es.eigenvalues()[5]),
               "interface '" << name
                             << "': an RBE3 average cannot fix a rigid motion of this surface "
                                "(its nodes lie on a line); use rbe2");
  return scale * G.ldlt().solve(WB);
}

std::vector<Interface> ResolveInterfaces(const Mesh& mesh, const std::vector<InterfaceSpec>& specs) {
  std::vector<Interface> out;
  std::vector<int> owner(mesh.num_nodes(), -1);
  for (const auto& spec : specs) {
    for (const auto& o : out)
      EMB_THROW_IF(o.name == spec.group, "interface '" << spec.group << "' is given twice");
    Interface itf = Resolve(mesh, spec);
    for (int s : itf.nodes) {
      EMB_THROW_IF(owner[s] >= 0, "interfaces '" << out[owner[s]].name << "' and '" << itf.name
                                                 << "' overlap (they share node "
                                                 << mesh.node_tags[s] << ")");
      owner[s] = static_cast<int>(out.size());
    }
    out.push_back(std::move(itf));
  }
  return out;
}

std::vector<InterfaceSpec> DefaultInterfaces(const Mesh& mesh) {
  static const std::regex rbe3(R"(^(main_journal_\d+|crankpin_\d+)$)");
  static const std::regex rbe2(R"(^(flange|nose|end_a|end_b)$)");
  std::vector<InterfaceSpec> out;
  for (const auto& g : mesh.groups) {
    if (g.dim != 2) continue;
    InterfaceSpec s;
    s.group = g.name;
    if (std::regex_match(g.name, rbe3)) {
      s.coupling = Coupling::kRbe3;
    } else if (std::regex_match(g.name, rbe2)) {
      s.coupling = Coupling::kRbe2;
    } else {
      continue;
    }
    out.push_back(s);
  }
  return out;
}

}  // namespace emb
