#pragma once
/// @file
/// Force elements (Drake `force_element.h` pattern): a non-virtual public method that
/// checks and a protected Do* that works. Generalised forces live in v-space (notation.h):
/// for body b, f[velocity(b)..+2] is the force in W [N] and f[angular_velocity(b)..+2] the
/// moment about the CM in B [N m].

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "libemb/mbs/core/kinematics.h"
#include "libemb/mbs/core/state_layout.h"

namespace emb::mbs {

class ConstraintWorkspace;
class ForceJacobianSink;  // forces/force_jacobian.h

/// What a force element may read: all body kinematics at (q, v), the time, and (for
/// elements that follow a joint angle across turns) the run's workspace with the first of
/// its angle slots.
struct ForceContext {
  const System* system{nullptr};
  const std::vector<BodyKinematics>* bodies{nullptr};
  double t{0.0};
  ConstraintWorkspace* workspace{nullptr};  ///< may be null: angles are then wrapped
  int angle_slot{-1};                       ///< this element's first slot (System::Finalize)
  /// Every marker's kinematics at the same state (CalcAllMarkerKinematics), computed once
  /// for all elements; null: Marker() evaluates a marker on demand.
  const std::vector<MarkerKinematics>* markers{nullptr};

  /// Marker m at this state: the shared one, or evaluated into `scratch` (and returned).
  const MarkerKinematics& Marker(int m, MarkerKinematics* scratch) const;
};

class ForceElement {
 public:
  explicit ForceElement(std::string name) : name_(std::move(name)) {}
  virtual ~ForceElement() = default;
  const std::string& name() const { return name_; }

  /// Adds this element's generalised forces to f (size nv).
  void AddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const;
  /// Adds the analytic derivatives of those forces, K_ab = d f_a/d x_b and D_ab = d f_a/d v_b
  /// (force_jacobian.h), to `sink`. The same (a, b) blocks at every state, so that a sparse
  /// iteration matrix keeps its structure.
  void AddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const;
  /// Stored (potential) energy [J]; 0 for non-conservative elements.
  double CalcPotentialEnergy(const ForceContext& ctx) const { return DoCalcPotentialEnergy(ctx); }
  /// Power dissipated by the element [W], >= 0 for a passive damper.
  double CalcDissipatedPower(const ForceContext& ctx) const { return DoCalcDissipatedPower(ctx); }
  /// Markers this element reads (to validate marker indices at Finalize).
  std::vector<int> markers() const { return DoMarkers(); }
  /// Continuous-angle slots it needs in the ConstraintWorkspace (e.g. a crank angle over a
  /// 720 degree cycle).
  int num_angle_slots() const { return DoNumAngleSlots(); }
  /// For output: the force [N] and moment [N m] the element applies to the body of its first
  /// marker, in its second marker's axes (bearing and mount loads); false if the element
  /// does not report one (e.g. applied loads, which are inputs).
  bool CalcLoad(const ForceContext& ctx, Eigen::Matrix<double, 6, 1>* load) const {
    return DoCalcLoad(ctx, load);
  }
  /// True if CalcLoad() reports a load (then the results have F/T channels for it).
  bool reports_load() const { return DoReportsLoad(); }

 protected:
  virtual void DoAddForces(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> f) const = 0;
  virtual void DoAddForceJacobian(const ForceContext& ctx, ForceJacobianSink* sink) const = 0;
  virtual double DoCalcPotentialEnergy(const ForceContext&) const { return 0.0; }
  virtual double DoCalcDissipatedPower(const ForceContext&) const { return 0.0; }
  virtual std::vector<int> DoMarkers() const = 0;
  virtual int DoNumAngleSlots() const { return 0; }
  virtual bool DoCalcLoad(const ForceContext&, Eigen::Matrix<double, 6, 1>*) const {
    return false;
  }
  virtual bool DoReportsLoad() const { return false; }

 private:
  std::string name_;
};

/// Adds a generalised force f6 = [force in W; moment about the origin in B] acting on the
/// virtual rigid body of marker M (kinematics.h) to f: f6 on M's body or, on a flexible
/// body, map^T f6 on its rigid and modal rows. Nothing for the ground.
void AddMarkerForce(const StateLayout& layout, const MarkerKinematics& M,
                    const Eigen::Matrix<double, 6, 1>& f6, Eigen::Ref<Eigen::VectorXd> f);

/// Adds a force F_W [N] acting at world point p_WQ and a couple T_W [N m], transmitted
/// through marker M, to M's body (nothing for the ground): with f6 = [F_W; R_BW (T_W +
/// (p_WQ - p_WB) x F_W)] on M's virtual body (AddMarkerForce; on a flexible body the point
/// moves with the marker frame, kinematics.h).
void AddWrench(const StateLayout& layout, const MarkerKinematics& M, const Eigen::Vector3d& p_WQ,
               const Eigen::Vector3d& F_W, const Eigen::Vector3d& T_W,
               Eigen::Ref<Eigen::VectorXd> f);

}  // namespace emb::mbs
