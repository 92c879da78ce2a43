#include "libemb/mbs/core/system.h"

#include <algorithm>
#include <map>
#include <set>

#include "libemb/common/did_you_mean.h"
#include "libemb/common/error.h"
#include "libemb/common/number_check.h"
#include "libemb/mbs/core/rotation.h"

namespace emb::mbs {
namespace {

template <typename T>
std::vector<std::string> Names(const std::vector<T>& v) {
  std::vector<std::string> n;
  for (const auto& x : v) n.push_back(x.name);
  return n;
}

template <typename T>
int FindByName(const std::vector<T>& v, const std::string& name, const char* what) {
  for (std::size_t i = 0; i < v.size(); ++i)
    if (v[i].name == name) return static_cast<int>(i);
  EMB_THROW(InputError, "unknown " << what << " '" << name << "'" << DidYouMean(name, Names(v)));
}

}  // namespace

System::System() {
  RigidBody ground;
  ground.name = "ground";
  ground.mass = 0.0;
  bodies_.push_back(ground);
}

void System::CheckNotFinalized(const char* what) const {
  if (finalized_) EMB_THROW(InternalError, std::string("System::") + what + " after Finalize");
}

void System::CheckNewName(const std::string& name, const char* what) const {
  EMB_THROW_IF(name.empty(), what << ": expected a non-empty name");
  // Names appear in messages, HDF5 name lists and channel names "<name>.<quantity>": no
  // spaces or control characters, and (except markers, which own no channels) no '.'.
  const bool marker = std::string(what) == "marker";
  for (const char c : name)
    EMB_THROW_IF(static_cast<unsigned char>(c) <= ' ' || c == '\x7f' || (c == '.' && !marker),
                 what << " '" << name << "': expected a name without spaces, control characters"
                      << (marker ? "" : " or '.' (channels are <name>.<quantity>)"));
}

void System::CheckChannelOwnerNames() const {
  // Channels are "<owner>.<quantity>": bodies, joints and couplers, force elements, sensors
  // and probes share one namespace with the built-in owners, so that a channel name means one
  // thing (a sensor named like a bushing made "bushing.F.x" resolve to the sensor).
  std::map<std::string, std::string> owner = {{"energy", "the energy channels"},
                                              {"residual", "the residual channels"}};
  auto claim = [&owner](const std::string& name, const std::string& what) {
    const auto [it, added] = owner.emplace(name, what + " '" + name + "'");
    EMB_THROW_IF(!added, what << " '" << name << "': the name is taken by " << it->second
                              << "; channels are <name>.<quantity>, so bodies, joints, force "
                                 "elements, sensors and probes need distinct names");
  };
  for (int b = 1; b < num_bodies(); ++b) claim(bodies_[b].name, "body");
  for (const auto& e : elements_) claim(e.name, "joint or coupler");
  for (const auto& f : forces_) claim(f->name(), "force element");
  for (const auto& s : sensors_) claim(s.name, "sensor");
  for (const auto& pr : probes_) claim(pr->name(), "probe");
}

int System::AddBody(const RigidBody& body) {
  CheckNotFinalized("AddBody");
  CheckNewName(body.name, "body");
  for (const auto& b : bodies_)
    EMB_THROW_IF(b.name == body.name, "body '" << body.name << "' is defined twice");
  body.Validate();
  bodies_.push_back(body);
  return num_bodies() - 1;
}

int System::AddMarker(const std::string& name, const std::string& body_name,
                      const Eigen::Vector3d& p_BM, const Eigen::Matrix3d& R_BM) {
  CheckNotFinalized("AddMarker");
  CheckNewName(name, "marker");
  for (const auto& m : markers_)
    EMB_THROW_IF(m.name == name, "marker '" << name << "' is defined twice");
  // Tolerance on R^T R = I for axes typed with ~12 digits.
  constexpr double kOrthonormalTolerance = 1e-9;
  EMB_THROW_IF(
      !R_BM.allFinite() ||
          (R_BM.transpose() * R_BM - Eigen::Matrix3d::Identity()).norm() > kOrthonormalTolerance ||
          R_BM.determinant() < 0,
      "marker '" << name << "': expected orthonormal right-handed axes");
  Marker m{name, FindBody(body_name), p_BM, R_BM, {}, {}};
  markers_.push_back(m);
  return static_cast<int>(markers_.size()) - 1;
}

int System::AddFlexibleMarker(const std::string& name, const std::string& body_name,
                              const Eigen::Vector3d& p_BM, const Eigen::Matrix3d& R_BM,
                              const Eigen::MatrixXd& shape_t, const Eigen::MatrixXd& shape_r) {
  const int b = FindBody(body_name);
  const int ne = bodies_[b].num_modes();
  EMB_THROW_IF(ne == 0, "marker '" << name << "': body '" << body_name << "' is not flexible");
  EMB_THROW_IF(shape_t.rows() != 3 || shape_r.rows() != 3 || shape_t.cols() != ne ||
                   shape_r.cols() != ne,
               "marker '" << name << "': expected 3 x " << ne << " translation and rotation "
                          << "shapes for the modes of body '" << body_name << "'");
  const int k = AddMarker(name, body_name, p_BM, R_BM);
  markers_[k].shape_t = shape_t;
  markers_[k].shape_r = shape_r;
  return k;
}

int System::AddJoint(const std::string& name, JointType type, const std::string& marker_i,
                     const std::string& marker_j) {
  CheckNotFinalized("AddJoint");
  CheckNewName(name, "joint");
  for (const auto& e : elements_)
    EMB_THROW_IF(e.name == name, "constraint '" << name << "' is defined twice");
  ConstraintElement e;
  e.name = name;
  e.kind = ElementKind::kJoint;
  e.type = type;
  e.marker_i = FindMarker(marker_i);
  e.marker_j = FindMarker(marker_j);
  EMB_THROW_IF(markers_[e.marker_i].body == markers_[e.marker_j].body,
               "joint '" << name << "': markers '" << marker_i << "' and '" << marker_j
                         << "' are on the same body '" << bodies_[markers_[e.marker_i].body].name
                         << "'; expected markers on two different bodies");
  const int index = static_cast<int>(elements_.size());
  for (const auto& [kernel, label] : JointKernels(type)) {
    ScalarEquation q;
    q.element = index;
    q.label = label;
    q.kernel[0] = kernel;
    q.marker_i[0] = e.marker_i;
    q.marker_j[0] = e.marker_j;
    pending_.push_back(q);
  }
  elements_.push_back(e);
  return index;
}

int System::AddMotion(const std::string& name, const std::string& joint, JointCoordinate c,
                      const TimeFunction& f) {
  CheckNotFinalized("AddMotion");
  CheckNewName(name, "motion");
  const int j = FindElement(joint);
  const ConstraintElement& je = elements_[j];
  EMB_THROW_IF(je.kind != ElementKind::kJoint,
               "motion '" << name << "': '" << joint << "' is not a joint");
  ConstraintElement e = je;
  e.name = name;
  e.kind = ElementKind::kMotion;
  ScalarEquation q;
  q.element = static_cast<int>(elements_.size());
  q.label = std::string("motion ") + Name(c) + " of '" + joint + "'";
  q.kernel[0] = CoordinateKernel(je.type, c, joint);
  q.marker_i[0] = je.marker_i;
  q.marker_j[0] = je.marker_j;
  q.has_function = true;
  q.function = f;
  pending_.push_back(q);
  elements_.push_back(e);
  return q.element;
}

int System::AddCoupler(const std::string& name, const std::string& joint1, JointCoordinate c1,
                       const std::string& joint2, JointCoordinate c2, double ratio, double offset) {
  CheckNotFinalized("AddCoupler");
  CheckNewName(name, "coupler");
  const std::string who = "coupler '" + name + "'";
  CheckNumber(who + " ratio", ratio, NumberRange::Finite());
  CheckNumber(who + " offset", offset, NumberRange::Finite());
  EMB_THROW_IF(ratio == 0.0, who << ": expected a non-zero ratio; 0 leaves joint '" << joint2
                                 << "' out and locks joint '" << joint1
                                 << "' at the offset (a motion or a fixed joint does that)");
  EMB_THROW_IF(joint1 == joint2 && c1 == c2,
               who << ": joint1 and joint2 are the same coordinate of joint '" << joint1
                   << "'; expected two different joint coordinates");
  const ConstraintElement& j1 = elements_[FindElement(joint1)];
  const ConstraintElement& j2 = elements_[FindElement(joint2)];
  ConstraintElement e;
  e.name = name;
  e.kind = ElementKind::kCoupler;
  e.type = j1.type;
  e.marker_i = j1.marker_i;
  e.marker_j = j1.marker_j;
  e.marker_i2 = j2.marker_i;
  e.marker_j2 = j2.marker_j;
  e.second_joint = joint2;
  ScalarEquation q;
  q.element = static_cast<int>(elements_.size());
  q.label = "coupler " + joint1 + " - ratio " + joint2;
  q.num_terms = 2;
  q.kernel[0] = CoordinateKernel(j1.type, c1, joint1);
  q.kernel[1] = CoordinateKernel(j2.type, c2, joint2);
  q.marker_i[0] = j1.marker_i;
  q.marker_j[0] = j1.marker_j;
  q.marker_i[1] = j2.marker_i;
  q.marker_j[1] = j2.marker_j;
  q.coeff[0] = 1.0;
  q.coeff[1] = -ratio;
  q.has_function = true;
  q.function = TimeFunction::Constant(offset);
  pending_.push_back(q);
  elements_.push_back(e);
  return q.element;
}

void System::AddForceElement(std::shared_ptr<const ForceElement> element) {
  CheckNotFinalized("AddForceElement");
  EMB_CHECK(element != nullptr);
  CheckNewName(element->name(), "force element");
  for (int m : element->markers()) EMB_CHECK(m >= 0 && m < static_cast<int>(markers_.size()));
  forces_.push_back(std::move(element));
}

void System::AddSensor(const std::string& name, const std::string& marker_i,
                       const std::string& marker_j) {
  CheckNotFinalized("AddSensor");
  CheckNewName(name, "sensor");
  for (const auto& s : sensors_)
    EMB_THROW_IF(s.name == name, "sensor '" << name << "' is defined twice");
  sensors_.push_back({name, FindMarker(marker_i), FindMarker(marker_j)});
}

void System::AddProbe(std::shared_ptr<const Probe> probe) {
  CheckNotFinalized("AddProbe");
  EMB_CHECK(probe != nullptr);
  CheckNewName(probe->name(), "probe");
  for (const auto& p : probes_)
    EMB_THROW_IF(p->name() == probe->name(), "output point '" << probe->name()
                                                              << "' is defined twice");
  for (int b : probe->bodies())
    EMB_THROW_IF(b < 0 || b >= num_bodies(),
                 "output point '" << probe->name() << "': no body with index " << b);
  probes_.push_back(std::move(probe));
}

int System::num_probe_channels() const {
  int n = 0;
  for (const auto& p : probes_) n += p->num_channels();
  return n;
}

void System::Finalize() {
  CheckNotFinalized("Finalize");
  CheckChannelOwnerNames();
  std::vector<int> ne;
  for (const auto& b : bodies_) ne.push_back(b.num_modes());
  layout_ = StateLayout(num_bodies(), ne);
  // A marker added on a flexible body with AddMarker stays at its undeformed place only if
  // the body is rigid: give it zero shapes (it then moves with the reference frame).
  for (auto& m : markers_)
    if (ne[m.body] > 0 && m.shape_t.size() == 0) {
      m.shape_t.setZero(3, ne[m.body]);
      m.shape_r.setZero(3, ne[m.body]);
    }
  equations_.clear();
  // Keep the equations grouped by element in element order.
  for (int e = 0; e < static_cast<int>(elements_.size()); ++e) {
    elements_[e].first_equation = static_cast<int>(equations_.size());
    elements_[e].num_equations = 0;
    for (const auto& q : pending_)
      if (q.element == e) {
        equations_.push_back(q);
        ++elements_[e].num_equations;
      }
  }
  num_angle_slots_ = 0;
  for (auto& q : equations_)
    for (int k = 0; k < q.num_terms; ++k)
      q.angle_slot[k] = q.kernel[k].kind == KernelKind::kAngle ? num_angle_slots_++ : -1;
  ports_.clear();
  for (int e = 0; e < static_cast<int>(elements_.size()); ++e)
    ports_.push_back({elements_[e].name, e, 0, elements_[e].marker_i, elements_[e].marker_j});
  for (int e = 0; e < static_cast<int>(elements_.size()); ++e) {
    const ConstraintElement& c = elements_[e];
    if (c.kind == ElementKind::kCoupler)
      ports_.push_back({c.name + ":" + c.second_joint, e, 1, c.marker_i2, c.marker_j2});
  }
  force_angle_slot_.clear();
  force_state_offset_.clear();
  num_force_states_ = 0;
  for (const auto& fe : forces_) {
    // Angle slots, then state slots (force_element.h).
    const int n = fe->num_angle_slots() + fe->num_state_slots();
    force_angle_slot_.push_back(n > 0 ? num_angle_slots_ : -1);
    num_angle_slots_ += n;
    const int nz = fe->num_continuous_states();
    EMB_THROW_IF(nz < 0, "force element '" << fe->name() << "': expected a number of continuous "
                                            "states >= 0, got " << nz);
    force_state_offset_.push_back(nz > 0 ? num_force_states_ : -1);
    num_force_states_ += nz;
  }
  finalized_ = true;
}

System System::WithoutEquations(const std::vector<int>& equations) const {
  EMB_CHECK(finalized_);
  const std::set<int> drop(equations.begin(), equations.end());
  System s = *this;
  s.finalized_ = false;
  s.pending_.clear();
  for (int k = 0; k < num_equations(); ++k) {
    if (drop.count(k)) {
      s.removed_.push_back(EquationName(k));
    } else {
      s.pending_.push_back(equations_[k]);
    }
  }
  s.Finalize();
  return s;
}

System System::WithElasticBases(const std::vector<ElasticBasisChange>& changes) const {
  EMB_CHECK(finalized_);
  System s = *this;
  s.finalized_ = false;
  s.pending_ = equations_;
  for (const ElasticBasisChange& c : changes) {
    EMB_CHECK(c.body >= 1 && c.body < num_bodies());
    RigidBody& b = s.bodies_[c.body];
    EMB_THROW_IF(!b.elastic, "body '" << b.name << "': a change of elastic basis needs a "
                                          "flexible body");
    const int ne = b.elastic->num_modes();
    EMB_THROW_IF(c.T.rows() != ne || c.T.cols() == 0,
                 "body '" << b.name << "': expected a basis change with " << ne
                          << " rows and at least one column, got " << c.T.rows() << " x "
                          << c.T.cols());
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(c.T);
    EMB_THROW_IF(qr.rank() < c.T.cols(), "body '" << b.name << "': the " << c.T.cols()
                                                   << " new elastic coordinates are dependent (rank "
                                                   << qr.rank() << ")");
    auto model = std::make_shared<ElasticModel>(b.elastic->Transformed(c.T));
    if (c.relaxation_time > 0.0) model->AddRelaxationDamping(c.quasi_static, c.relaxation_time);
    if (!c.quasi_static.empty()) model->MakeQuasiStatic(c.quasi_static, b.name);
    model->Validate(b.name);
    if (b.eta0.size()) b.eta0 = qr.solve(b.eta0);
    if (b.eta_dot0.size()) b.eta_dot0 = qr.solve(b.eta_dot0);
    b.elastic = std::move(model);
    for (Marker& m : s.markers_) {
      if (m.body != c.body || m.shape_t.size() == 0) continue;
      m.shape_t = m.shape_t * c.T;
      m.shape_r = m.shape_r * c.T;
    }
    for (auto& p : s.probes_)
      if (auto q = p->WithElasticBasis(c.body, c.T)) p = std::move(q);
  }
  s.Finalize();
  return s;
}

int System::second_reaction_port(int e) const {
  for (std::size_t p = elements_.size(); p < ports_.size(); ++p)
    if (ports_[p].element == e) return static_cast<int>(p);
  return -1;
}

std::string System::EquationName(int k) const {
  const ScalarEquation& q = equations_.at(k);
  const ConstraintElement& e = elements_.at(q.element);
  const char* kind = e.kind == ElementKind::kJoint    ? Name(e.type)
                     : e.kind == ElementKind::kMotion ? "motion"
                                                      : "coupler";
  return std::string(kind) + " '" + e.name + "': " + q.label;
}

int System::FindBody(const std::string& name) const { return FindByName(bodies_, name, "body"); }
int System::FindMarker(const std::string& name) const {
  return FindByName(markers_, name, "marker");
}
int System::FindElement(const std::string& name) const {
  return FindByName(elements_, name, "joint/constraint");
}

Eigen::VectorXd System::InitialPositions() const {
  Eigen::VectorXd q(layout_.nq());
  for (int b = 1; b < num_bodies(); ++b) {
    q.segment<3>(layout_.position(b)) = bodies_[b].p_WB;
    q.segment<4>(layout_.quaternion(b)) = QuaternionFromRotation(bodies_[b].R_WB);
    const int ne = layout_.num_elastic(b);
    if (ne) {
      q.segment(layout_.elastic_q(b), ne).setZero();
      if (bodies_[b].eta0.size()) q.segment(layout_.elastic_q(b), ne) = bodies_[b].eta0;
    }
  }
  return q;
}

System System::WithInitialState(const Eigen::VectorXd& q, const Eigen::VectorXd& v) const {
  EMB_CHECK(finalized_);
  EMB_THROW_IF(q.size() != layout_.nq() || v.size() != layout_.nv(),
               "initial state: expected " << layout_.nq() << " positions and " << layout_.nv()
                                          << " velocities, got " << q.size() << " and "
                                          << v.size());
  System s = *this;
  for (int b = 1; b < num_bodies(); ++b) {
    RigidBody& body = s.bodies_[b];
    body.p_WB = q.segment<3>(layout_.position(b));
    body.R_WB = RotationFromQuaternion(q.segment<4>(layout_.quaternion(b)).normalized());
    body.v_WB = v.segment<3>(layout_.velocity(b));
    body.omega_W = body.R_WB * v.segment<3>(layout_.angular_velocity(b));
    const int ne = layout_.num_elastic(b);
    if (ne) {
      body.eta0 = q.segment(layout_.elastic_q(b), ne);
      body.eta_dot0 = v.segment(layout_.elastic_v(b), ne);
    }
  }
  return s;
}

Eigen::VectorXd System::InitialVelocities() const {
  Eigen::VectorXd v(layout_.nv());
  for (int b = 1; b < num_bodies(); ++b) {
    v.segment<3>(layout_.velocity(b)) = bodies_[b].v_WB;
    v.segment<3>(layout_.angular_velocity(b)) = bodies_[b].R_WB.transpose() * bodies_[b].omega_W;
    const int ne = layout_.num_elastic(b);
    if (ne) {
      v.segment(layout_.elastic_v(b), ne).setZero();
      if (bodies_[b].eta_dot0.size()) v.segment(layout_.elastic_v(b), ne) = bodies_[b].eta_dot0;
    }
  }
  return v;
}

}  // namespace emb::mbs
