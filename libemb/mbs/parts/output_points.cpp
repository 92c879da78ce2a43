#include "libemb/mbs/parts/output_points.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "libemb/common/error.h"

namespace emb::mbs {
namespace {

using Eigen::Vector3d;

std::string Who(const OutputPointSpec& spec) { return "output point '" + spec.name + "'"; }

// The direction of the "n" component at mesh point x (mesh = part axes), unit or zero.
Vector3d DirectionAt(const OutputPointSpec& spec, const Vector3d& x, const Vector3d& normal) {
  switch (spec.direction) {
    case OutputPointSpec::Direction::kNone:
      return Vector3d::Zero();
    case OutputPointSpec::Direction::kFixed:
      return spec.vector;
    case OutputPointSpec::Direction::kNormal:
      return normal;
    case OutputPointSpec::Direction::kRadial: {
      const Vector3d d = x - spec.axis_point;
      const Vector3d radial = d - spec.axis.dot(d) * spec.axis;
      EMB_THROW_IF(radial.norm() <= 1e-12 * std::max(1.0, d.norm()),
                   Who(spec) << ": the point " << x.transpose()
                             << " lies on the radial direction's axis; expected a point off it");
      return radial.normalized();
    }
  }
  return Vector3d::Zero();
}

}  // namespace

OutputPointProbe::OutputPointProbe(std::string name, std::vector<MaterialPoint> points,
                                   OutputPointSpec::Quantity quantity, bool with_direction)
    : Probe(std::move(name)),
      points_(std::move(points)),
      quantity_(quantity),
      with_direction_(with_direction) {
  EMB_THROW_IF(points_.empty(), "output point '" << this->name() << "': no mesh node selected");
  for (const MaterialPoint& p : points_) total_weight_ += p.weight;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const MaterialPoint& p = points_[i];
    auto g = std::find_if(groups_.begin(), groups_.end(),
                          [&](const BodyGroup& b) { return b.body == p.body; });
    if (g == groups_.end()) g = groups_.insert(groups_.end(), BodyGroup{p.body, {}, {}});
    g->points.push_back(static_cast<int>(i));
  }
  for (BodyGroup& g : groups_) {
    const MaterialPoint& first = points_[static_cast<std::size_t>(g.points.front())];
    if (first.phi.size() == 0) continue;
    g.phi.resize(3 * static_cast<Eigen::Index>(g.points.size()), first.phi.cols());
    for (std::size_t k = 0; k < g.points.size(); ++k) {
      const MaterialPoint& p = points_[static_cast<std::size_t>(g.points[k])];
      EMB_CHECK(p.phi.rows() == 3 && p.phi.cols() == first.phi.cols());
      g.phi.middleRows<3>(3 * static_cast<Eigen::Index>(k)) = p.phi;
    }
  }
  EMB_THROW_IF(!(total_weight_ > 0.0), "output point '" << this->name()
                                                        << "': expected a positive total "
                                                           "weight (area), got "
                                                        << total_weight_);
  if (quantity_ == OutputPointSpec::Quantity::kRadiatedPower) {
    channels_ = {"power"};
    return;
  }
  for (const char* q : {"u", "v", "a"}) {
    for (const char* c : {"x", "y", "z"}) channels_.push_back(std::string(q) + "." + c);
    if (with_direction_) channels_.push_back(std::string(q) + ".n");
  }
}

std::shared_ptr<const Probe> OutputPointProbe::WithElasticBasis(int body,
                                                                const Eigen::MatrixXd& T) const {
  std::vector<MaterialPoint> points = points_;
  bool changed = false;
  for (MaterialPoint& p : points)
    if (p.body == body && p.phi.size()) {
      EMB_CHECK(p.phi.cols() == T.rows());
      p.phi = p.phi * T;
      changed = true;
    }
  if (!changed) return nullptr;
  return std::make_shared<OutputPointProbe>(name(), std::move(points), quantity_, with_direction_);
}

std::vector<int> OutputPointProbe::bodies() const {
  std::vector<int> b;
  for (const MaterialPoint& p : points_) b.push_back(p.body);
  return b;
}

void OutputPointProbe::DoEval(const System& system, const std::vector<BodyKinematics>& bodies,
                              const Eigen::VectorXd& vdot,
                              Eigen::Ref<Eigen::VectorXd> values) const {
  const StateLayout& L = system.layout();
  Vector3d sum[3] = {Vector3d::Zero(), Vector3d::Zero(), Vector3d::Zero()};
  double sum_n[3] = {0.0, 0.0, 0.0};
  double power = 0.0;
  for (const BodyGroup& g : groups_) {
    const bool ground = L.is_ground(g.body);
    const int ne = ground ? 0 : L.num_elastic(g.body);
    Eigen::MatrixXd modal;  // [u, u', u''] of every point, stacked (3 m x 3)
    const BodyKinematics* k = ground ? nullptr : &bodies[static_cast<std::size_t>(g.body)];
    if (g.phi.size() && ne) {
      Eigen::MatrixXd e(ne, 3);
      e << k->eta, k->eta_dot, vdot.segment(L.elastic_v(g.body), ne);
      modal = g.phi * e;
    }
    for (std::size_t m = 0; m < g.points.size(); ++m) {
      const MaterialPoint& p = points_[static_cast<std::size_t>(g.points[m])];
      Vector3d u = Vector3d::Zero(), ud = Vector3d::Zero(), udd = Vector3d::Zero();
      Vector3d vel = Vector3d::Zero(), acc = Vector3d::Zero();
      if (!ground) {
        if (modal.size()) {
          const auto rows = modal.middleRows<3>(3 * static_cast<Eigen::Index>(m));
          u = rows.col(0);
          ud = rows.col(1);
          udd = rows.col(2);
        }
        const Vector3d r = p.r_B + u, w = k->omega_B;
        const Vector3d wd = vdot.segment<3>(L.angular_velocity(p.body));
        vel = k->R_WB.transpose() * k->v_WB + w.cross(r) + ud;
        acc = k->R_WB.transpose() * vdot.segment<3>(L.velocity(p.body)) + wd.cross(r) +
              w.cross(w.cross(r)) + 2.0 * w.cross(ud) + udd;
      }
      const Vector3d q[3] = {p.R_BP.transpose() * u, p.R_BP.transpose() * vel,
                             p.R_BP.transpose() * acc};
      for (int i = 0; i < 3; ++i) {
        sum[i] += p.weight * q[i];
        sum_n[i] += p.weight * p.direction_P.dot(q[i]);
      }
      const double vn = p.direction_P.dot(q[1]);
      power += p.weight * vn * vn;
    }
  }
  if (quantity_ == OutputPointSpec::Quantity::kRadiatedPower) {
    values[0] = power;
    return;
  }
  int c = 0;
  for (int i = 0; i < 3; ++i) {
    values.segment<3>(c) = sum[i] / total_weight_;
    c += 3;
    if (with_direction_) values[c++] = sum_n[i] / total_weight_;
  }
}

std::vector<MaterialPoint> SelectMeshPoints(const Mesh& mesh, const OutputPointSpec& spec) {
  const int given = (spec.node ? 1 : 0) + (spec.position ? 1 : 0) + (spec.group.empty() ? 0 : 1);
  EMB_THROW_IF(given != 1, Who(spec)
                               << ": expected exactly one of node, position, group, got " << given);
  const bool power = spec.quantity == OutputPointSpec::Quantity::kRadiatedPower;
  EMB_THROW_IF(
      (power || spec.direction == OutputPointSpec::Direction::kNormal) && spec.group.empty(),
      Who(spec) << ": a surface normal (and the radiated power) needs a surface group");
  std::vector<MaterialPoint> out;
  if (!spec.group.empty()) {
    SurfacePatch s;
    try {
      s = GroupSurface(mesh, spec.group);
    } catch (const InputError& e) {
      EMB_THROW(InputError, Who(spec) << ": " << e.what());
    }
    for (std::size_t k = 0; k < s.nodes.size(); ++k) {
      MaterialPoint p;
      p.node = s.nodes[k];
      p.r_B = mesh.nodes.col(p.node);
      p.weight = s.weights[static_cast<Eigen::Index>(k)];
      const Vector3d n = s.normals.col(static_cast<Eigen::Index>(k));
      p.direction_P = power ? n : DirectionAt(spec, p.r_B, n);
      out.push_back(p);
    }
    return out;
  }
  MaterialPoint p;
  if (spec.node) {
    EMB_THROW_IF(*spec.node < 0 || *spec.node >= mesh.num_nodes(),
                 Who(spec) << ": expected a node index in [0, " << mesh.num_nodes() - 1
                           << "] of the body's mesh, got " << *spec.node);
    p.node = *spec.node;
  } else {
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < mesh.num_nodes(); ++i) {
      const double d = (mesh.nodes.col(i) - *spec.position).norm();
      if (d < best) best = d, p.node = i;
    }
    EMB_THROW_IF(!(best <= spec.tolerance),
                 Who(spec) << ": the point " << spec.position->transpose()
                           << " is not on the body's mesh: the nearest node (" << p.node << ", at "
                           << mesh.nodes.col(p.node).transpose() << ") is " << best
                           << " m away, expected within the tolerance " << spec.tolerance << " m");
  }
  p.r_B = mesh.nodes.col(p.node);
  p.direction_P = DirectionAt(spec, p.r_B, Vector3d::Zero());
  out.push_back(p);
  return out;
}

std::shared_ptr<Probe> MakeOutputPoint(const System& system, const FlexiblePart& part,
                                       const BodyMeshShapes& mesh, const OutputPointSpec& spec) {
  EMB_THROW_IF(mesh.shapes.cols() != part.num_available_modes ||
                   mesh.shapes.rows() != 3 * mesh.mesh.num_nodes(),
               Who(spec) << ": the mesh shapes of part '" << part.name << "' ("
                         << mesh.shapes.cols() << " modes) do not match its body file ("
                         << part.num_available_modes << " modes)");
  std::vector<MaterialPoint> points = SelectMeshPoints(mesh.mesh, spec);
  for (MaterialPoint& p : points) {
    p.body = part.body;
    p.r_B = part.MeshToBody(p.r_B);
    if (!part.flexible) continue;
    p.phi.resize(3, part.num_modes());
    for (int j = 0; j < part.num_modes(); ++j)
      p.phi.col(j) =
          mesh.shapes.block(3 * p.node, part.kept_modes[static_cast<std::size_t>(j)], 3, 1);
  }
  (void)system;
  return std::make_shared<OutputPointProbe>(spec.name, std::move(points), spec.quantity,
                                            spec.direction != OutputPointSpec::Direction::kNone);
}

std::shared_ptr<Probe> MakeOutputPoint(const System& system, const BeamPart& part,
                                       const BeamPartPlacement& placement, const Mesh& mesh,
                                       const OutputPointSpec& spec) {
  std::vector<int> node_bodies;
  for (const std::string& b : part.bodies) node_bodies.push_back(system.FindBody(b));
  EMB_THROW_IF(node_bodies.empty(), Who(spec) << ": beam part '" << part.name << "' has no nodes");
  std::vector<MaterialPoint> points = SelectMeshPoints(mesh, spec);
  for (MaterialPoint& p : points) {
    const Vector3d p_W = placement.p_WP + placement.R_WP * p.r_B;
    double best = std::numeric_limits<double>::infinity();
    for (int b : node_bodies) {
      const double d = (system.body(b).p_WB - p_W).norm();
      if (d < best) best = d, p.body = b;
    }
    const RigidBody& body = system.body(p.body);
    p.r_B = body.R_WB.transpose() * (p_W - body.p_WB);
    p.R_BP = body.R_WB.transpose() * placement.R_WP;
  }
  return std::make_shared<OutputPointProbe>(spec.name, std::move(points), spec.quantity,
                                            spec.direction != OutputPointSpec::Direction::kNone);
}

}  // namespace emb::mbs
