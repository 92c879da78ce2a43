#pragma once
/// @file
/// The multibody model: bodies, markers, constraint elements (joints, primitives, motions,
/// couplers), force elements and gravity. Built with Add* calls, then Finalize(); after
/// that it is immutable and only read by the analyses (Drake MultibodyPlant pattern).
/// Mutable per-run data (continuous joint angles) lives in ConstraintWorkspace.

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "libemb/mbs/core/body.h"
#include "libemb/mbs/core/force_element.h"
#include "libemb/mbs/core/joint.h"
#include "libemb/mbs/core/probe.h"
#include "libemb/mbs/core/state_layout.h"
#include "libemb/mbs/core/time_function.h"

namespace emb::mbs {

/// A frame fixed on a body. On a flexible body it moves with the deformation: its origin by
/// shape_t eta and its axes by the rotation Exp(shape_r eta) (in B), e.g. the reference
/// node of an interface with the rows of the body file's interface shapes.
struct Marker {
  std::string name;
  int body{0};                                        ///< 0 = ground
  Eigen::Vector3d p_BM{Eigen::Vector3d::Zero()};      ///< in B, from the CM [m] (undeformed)
  Eigen::Matrix3d R_BM{Eigen::Matrix3d::Identity()};  ///< marker axes in B (undeformed)
  Eigen::MatrixXd shape_t, shape_r;                   ///< 3 x ne, empty on rigid bodies
};

/// An output-only measurement: the pose of marker I relative to marker J, reported as
/// [R_JW (p_I - p_J); rotation vector of R_J^T R_I] (e.g. the torsion of a crank nose
/// against the flywheel, or a journal's eccentricity in its bearing).
struct Sensor {
  std::string name;
  int marker_i{-1}, marker_j{-1};
};

/// A change of the elastic coordinates of flexible body `body`: eta = T xi (ne x n'), with the
/// new coordinates flagged in `quasi_static` (empty: all dynamic) made quasi-static
/// (ElasticModel::MakeQuasiStatic). System::WithElasticBases applies it.
struct ElasticBasisChange {
  int body{-1};
  Eigen::MatrixXd T;
  std::vector<bool> quasi_static;
  /// > 0: the quasi-static coordinates get the extra damping relaxation_time x K_ss [s]
  /// (ElasticModel::AddRelaxationDamping).
  double relaxation_time{0.0};
};

/// What kind of constraint element produced an equation.
enum class ElementKind { kJoint, kMotion, kCoupler };

/// A constraint element: a joint/primitive between markers I and J, a motion on a joint
/// coordinate, or a coupler relating two joint coordinates.
struct ConstraintElement {
  std::string name;
  ElementKind kind{ElementKind::kJoint};
  JointType type{JointType::kRevolute};  ///< for joints; for motions the joint's type
  /// Joints and motions: the joint's markers. Couplers: the markers of the first joint.
  int marker_i{-1}, marker_j{-1};
  int marker_i2{-1}, marker_j2{-1};  ///< couplers: the markers of the second joint
  std::string second_joint;          ///< couplers: the second joint's name
  int first_equation{0};             ///< set by Finalize
  int num_equations{0};
};

/// Where a constraint element's reaction is reported: the load the element puts on the
/// body of marker I through the markers (I, J) of one kernel term (reactions.h). Every
/// element has one port (term 0, its own or its first joint's markers); a coupler has a
/// second port on the second joint (term 1), because its multiplier loads both joints.
struct ReactionPort {
  std::string name;  ///< the element's name; "<coupler>:<joint2>" for a coupler's second port
  int element{0};
  int term{0};
  int marker_i{-1}, marker_j{-1};
};

class System {
 public:
  System();

  /// Names of bodies, elements, force elements and sensors are non-empty, without spaces,
  /// control characters or '.' (channels are "<name>.<quantity>"); marker names may hold '.'.
  /// Adds a rigid body; returns its index (>= 1). The ground is index 0, named "ground".
  /// @throws InputError for a duplicate or malformed name or invalid data
  /// (RigidBody::Validate).
  int AddBody(const RigidBody& body);
  /// Adds a marker on `body_name` at p_BM with axes R_BM (columns, in B); returns its index.
  /// @throws InputError for an unknown body, a duplicate name or non-orthonormal axes.
  int AddMarker(const std::string& name, const std::string& body_name, const Eigen::Vector3d& p_BM,
                const Eigen::Matrix3d& R_BM);
  /// A marker on a flexible body that follows the deformation with the translation and
  /// rotation shapes (3 x ne each, in B, per unit modal coordinate).
  /// @throws InputError if the body is not flexible or the shapes do not have its ne columns.
  int AddFlexibleMarker(const std::string& name, const std::string& body_name,
                        const Eigen::Vector3d& p_BM, const Eigen::Matrix3d& R_BM,
                        const Eigen::MatrixXd& shape_t, const Eigen::MatrixXd& shape_r);
  /// Adds a joint or primitive constraint between markers I (first body) and J.
  int AddJoint(const std::string& name, JointType type, const std::string& marker_i,
               const std::string& marker_j);
  /// Prescribes coordinate c of joint `joint` as f(t) (1 equation).
  int AddMotion(const std::string& name, const std::string& joint, JointCoordinate c,
                const TimeFunction& f);
  /// Couples two joint coordinates: g1 - ratio * g2 - offset = 0 (1 equation), e.g. a gear
  /// pair with ratio -z2/z1 on the two revolute angles.
  int AddCoupler(const std::string& name, const std::string& joint1, JointCoordinate c1,
                 const std::string& joint2, JointCoordinate c2, double ratio, double offset);
  void AddForceElement(std::shared_ptr<const ForceElement> element);
  /// Adds a sensor of marker I relative to marker J (output only).
  void AddSensor(const std::string& name, const std::string& marker_i,
                 const std::string& marker_j);
  /// Adds a probe (output only, probe.h). @throws InputError for a duplicate name or a body
  /// index it reads that does not exist.
  void AddProbe(std::shared_ptr<const Probe> probe);
  /// Gravity acceleration in W [m/s^2].
  void SetGravity(const Eigen::Vector3d& g_W) { gravity_W_ = g_W; }

  /// Builds the scalar equation list and the state layout. No Add* afterwards.
  void Finalize();
  bool finalized() const { return finalized_; }

  /// A copy in which each changed body's modal coordinates are eta = T xi: its elastic model
  /// ElasticModel::Transformed(T) (then MakeQuasiStatic), its markers' shapes shape T, its
  /// initial xi the least-squares solution of T xi = eta0 (and the same for the rates).
  /// @throws InputError naming the body if it is not flexible, T has the wrong number of
  /// rows or is rank deficient, or a quasi-static coordinate has no damping.
  System WithElasticBases(const std::vector<ElasticBasisChange>& changes) const;
  /// A copy whose bodies start at state (q, v) (InitialPositions/InitialVelocities layout:
  /// p_WB, unit quaternion, modal coordinates; v_WB, omega_B, modal rates). Markers are
  /// body-fixed, so they move with their bodies. @throws InputError for wrong sizes.
  System WithInitialState(const Eigen::VectorXd& q, const Eigen::VectorXd& v) const;

  /// A copy without the given scalar equations (indices into equations()), e.g. the
  /// redundant ones of a DOF report. The copy records what was removed.
  System WithoutEquations(const std::vector<int>& equations) const;

  // Accessors (all valid after Finalize).
  const StateLayout& layout() const { return layout_; }
  int num_bodies() const { return static_cast<int>(bodies_.size()); }  ///< with ground
  const RigidBody& body(int b) const { return bodies_.at(b); }
  const std::vector<RigidBody>& bodies() const { return bodies_; }
  const std::vector<Marker>& markers() const { return markers_; }
  const Marker& marker(int m) const { return markers_.at(m); }
  const std::vector<ConstraintElement>& elements() const { return elements_; }
  const std::vector<ScalarEquation>& equations() const { return equations_; }
  int num_equations() const { return static_cast<int>(equations_.size()); }
  const std::vector<std::shared_ptr<const ForceElement>>& force_elements() const { return forces_; }
  const std::vector<Sensor>& sensors() const { return sensors_; }
  const std::vector<std::shared_ptr<const Probe>>& probes() const { return probes_; }
  /// Sum of the probes' channel counts.
  int num_probe_channels() const;
  const Eigen::Vector3d& gravity() const { return gravity_W_; }
  int num_angle_slots() const { return num_angle_slots_; }
  /// First workspace slot of force element k (-1 if it needs none): its angle slots, then
  /// its state slots (ForceElement::num_state_slots).
  int force_angle_slot(int k) const { return force_angle_slot_.at(k); }
  /// Continuous states of the force elements (ForceElement::num_continuous_states), element
  /// after element: element k owns [force_state_offset(k), + its count); -1 if it has none.
  int num_force_states() const { return num_force_states_; }
  int force_state_offset(int k) const { return force_state_offset_.at(k); }
  /// Reaction ports (set by Finalize): port e < elements().size() is element e's first port;
  /// the second ports of the couplers follow in element order.
  const std::vector<ReactionPort>& reaction_ports() const { return ports_; }
  /// The second port of coupler element e, or -1.
  int second_reaction_port(int e) const;
  /// "joint 'crank_pin': parallel z_I.x_J" for equation k.
  std::string EquationName(int k) const;
  /// Labels of equations removed by WithoutEquations (empty otherwise).
  const std::vector<std::string>& removed_equations() const { return removed_; }

  int FindBody(const std::string& name) const;     ///< @throws InputError with did-you-mean
  int FindMarker(const std::string& name) const;   ///< @throws InputError with did-you-mean
  int FindElement(const std::string& name) const;  ///< @throws InputError with did-you-mean

  /// The initial q (7 per moving body, then the modal coordinates) and v (6 per moving body,
  /// then the modal rates) from the bodies' data.
  Eigen::VectorXd InitialPositions() const;
  Eigen::VectorXd InitialVelocities() const;

 private:
  void CheckNotFinalized(const char* what) const;
  void CheckNewName(const std::string& name, const char* what) const;
  /// @throws InputError naming both for two channel owners (bodies, joints and couplers,
  /// force elements, sensors, probes, "energy", "residual") with one name.
  void CheckChannelOwnerNames() const;

  std::vector<RigidBody> bodies_;
  std::vector<Marker> markers_;
  std::vector<ConstraintElement> elements_;
  std::vector<ReactionPort> ports_;
  // Motions/couplers: their equations before Finalize numbers them.
  std::vector<ScalarEquation> pending_;
  std::vector<ScalarEquation> equations_;
  std::vector<std::shared_ptr<const ForceElement>> forces_;
  std::vector<Sensor> sensors_;
  std::vector<std::shared_ptr<const Probe>> probes_;
  std::vector<std::string> removed_;
  Eigen::Vector3d gravity_W_{Eigen::Vector3d::Zero()};
  StateLayout layout_;
  int num_angle_slots_{0};
  std::vector<int> force_angle_slot_;
  int num_force_states_{0};
  std::vector<int> force_state_offset_;
  bool finalized_{false};
};

}  // namespace emb::mbs
