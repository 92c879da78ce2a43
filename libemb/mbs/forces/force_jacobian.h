#pragma once
/// @file
/// Analytic derivatives of force elements' generalised forces (force_element.h), for the
/// iteration matrix of the GGL DAE and the stiffness of static equilibrium.
///
/// With f_a the generalised force on body a (force in W, moment about the CM in B; 6) and
/// the perturbations of notation.h, x_b = [delta p_WB, delta pi_B] (delta R = R [delta pi x])
/// and v_b = [v_WB, omega_B], an element adds the 6x6 blocks
///   stiffness K_ab = d f_a / d x_b,    damping D_ab = d f_a / d v_b.
///
/// Elements work in local slots: X = [x_s0, x_s1, ...], V = [v_s0, ...] (6 per slot, one
/// slot per marker's body; two slots may hold the same body and their partials add when
/// scattered). World-frame kinematic derivatives of a marker M on the body of slot s
/// (phi = the body's virtual rotation in W, delta phi = R_WB delta pi):
///   d p_WM  = [I, -[s_W x] R_WB]                      (columns of slot s, s_W = R_WB s_B)
///   d v_WM  = [0, -[(omega_W x s_W) x] R_WB] dX + [I, -[s_W x] R_WB] dV
///   d omega_W = -[omega_W x] R_WB d pi + R_WB d omega_B
/// and a wrench (F at a point with arm r from the CM of body a, couple T) gives
///   f_a = [F; R_a^T (T + r x F)],
///   d f_a = [dF; R_a^T (dT + [r x] dF - [F x] dr)] + [0; [n_a x] d pi_a],  n_a = R_a^T (T + r x F).

#include <Eigen/Dense>
#include <array>
#include <initializer_list>
#include <vector>

#include "libemb/mbs/core/kinematics.h"
#include "libemb/mbs/core/state_layout.h"

#include "libemb/common/scratch_matrices.h"

namespace emb::mbs {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// At most kMaxForceSlots local slots per element (two markers per joint coordinate of a
/// driveline coordinate of two joints; an applied load with a reaction and an argument joint).
/// Derivatives in the slots are fixed-capacity matrices: they live on the stack, so an
/// iteration matrix allocates nothing (ggl_workspace.h).
inline constexpr int kMaxForceSlots = 4;
inline constexpr int kMaxSlotColumns = 6 * kMaxForceSlots;
/// Rows x (6 x slots) derivatives, fixed capacity.
template <int Rows>
using SlotRows = Eigen::Matrix<double, Rows, Eigen::Dynamic,
                               Rows == 1 ? Eigen::RowMajor : Eigen::ColMajor, Rows, kMaxSlotColumns>;
/// (6 x slots) x (6 x slots), fixed capacity.
using SlotMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxSlotColumns, kMaxSlotColumns>;

/// Receives the blocks of the force elements' derivatives; never called for the ground.
/// A block of bodies (a, b) is body_nv(a) x body_nv(b) (state_layout.h): rows and columns
/// [delta p, delta pi] (or [v_WB, omega_B]) and then, on a flexible body, its modal
/// coordinates (or rates).
class ForceJacobianSink {
 public:
  virtual ~ForceJacobianSink() = default;
  /// K_ab = d f_a / d x_b.
  virtual void AddStiffness(int body_a, int body_b, const Eigen::Ref<const Eigen::MatrixXd>& K) = 0;
  /// D_ab = d f_a / d v_b.
  virtual void AddDamping(int body_a, int body_b, const Eigen::Ref<const Eigen::MatrixXd>& D) = 0;

  /// The blocks of a force on the virtual body of marker Ma by the motion of the virtual body
  /// of Mb (6 x 6 each: K_ab = d f_a/d x_b, D_ab = d f_a/d v_b), taken to the bodies'
  /// coordinates by the chain rule through the marker maps (LocalForceJacobian::ScatterTo);
  /// `curvature_force` (a == b on a flexible marker) is the generalised force f_a whose
  /// curvature term map's second derivative adds. Temporaries in the sink's own scratch:
  /// nothing is allocated once their sizes have been seen.
  void AddMarkerBlocks(const MarkerKinematics& Ma, const MarkerKinematics& Mb,
                       const Eigen::Ref<const Matrix6d>& K, const Eigen::Ref<const Matrix6d>& D,
                       const Eigen::Matrix<double, 6, 1>* curvature_force);

 protected:
  /// Where AddMarkerBlocks keeps its temporaries (a sink that lives for one evaluation passes
  /// longer-lived storage, e.g. the DAE workspace's).
  void UseScratch(ScratchMatrices* scratch) { scratch_ = scratch; }

 private:
  ScratchMatrices own_scratch_;
  ScratchMatrices* scratch_{&own_scratch_};
};

/// Receives the iteration-matrix blocks of an element's continuous states (ForceElement::
/// AddStateJacobian), in the element's own state numbering: R its state residual rows, z its
/// states, f_a the generalised force on body a (force_jacobian.h's blocks, body_nv columns
/// or rows). Never called for the ground.
class StateJacobianSink {
 public:
  virtual ~StateJacobianSink() = default;
  /// dR/dz + cj dR/dz' for the rows from `row` and the columns from `col`.
  virtual void AddStateBlock(int row, int col, const Eigen::Ref<const Eigen::MatrixXd>& block) = 0;
  /// dR/dx_b (rows from `row`, body_nv(b) columns in [delta p, delta pi, eta]).
  virtual void AddStateStiffness(int row, int body,
                                 const Eigen::Ref<const Eigen::MatrixXd>& block) = 0;
  /// dR/dv_b (rows from `row`, body_nv(b) columns).
  virtual void AddStateDamping(int row, int body,
                               const Eigen::Ref<const Eigen::MatrixXd>& block) = 0;
  /// df_a/dz (body_nv(a) rows, the states from `col`).
  virtual void AddForceByState(int body, int col,
                               const Eigen::Ref<const Eigen::MatrixXd>& block) = 0;

  /// dR/dX_M and dR/dV_M of the virtual body of marker M (rows x 6) taken to its body's
  /// coordinates through the marker map (kinematics.h): dR/dx_b = dR/dX map + dR/dV map_rate,
  /// dR/dv_b = dR/dV map (the identity on a rigid body). Nothing for the ground.
  void AddMarkerStateRows(int row, const MarkerKinematics& M,
                          const Eigen::Ref<const Eigen::MatrixXd>& dR_dX,
                          const Eigen::Ref<const Eigen::MatrixXd>& dR_dV);
  /// df6/dz of a generalised force f6 on M's virtual body (6 x cols): map^T df6/dz on its body.
  void AddMarkerForceByState(const MarkerKinematics& M, int col,
                             const Eigen::Ref<const Eigen::MatrixXd>& df6_dz);

 protected:
  void UseScratch(ScratchMatrices* scratch) { scratch_ = scratch; }

 private:
  ScratchMatrices own_scratch_;
  ScratchMatrices* scratch_{&own_scratch_};
};

/// Dense nv x nv stiffness df/dx and damping df/dv (statics, tests). Cost O(nv^2) memory.
class DenseForceJacobian final : public ForceJacobianSink {
 public:
  explicit DenseForceJacobian(const StateLayout& layout);
  void AddStiffness(int body_a, int body_b, const Eigen::Ref<const Eigen::MatrixXd>& K) override;
  void AddDamping(int body_a, int body_b, const Eigen::Ref<const Eigen::MatrixXd>& D) override;
  const Eigen::MatrixXd& stiffness() const { return stiffness_; }
  const Eigen::MatrixXd& damping() const { return damping_; }

 private:
  StateLayout layout_;
  Eigen::MatrixXd stiffness_, damping_;
};

/// An element's derivatives in its local slots (see the file comment). A slot is the
/// (virtual rigid) body of one marker (kinematics.h): on a flexible body, the marker frame,
/// whose displacement and velocity are map [dx_b] and map V of the body's coordinates.
/// ScatterTo takes a block to the bodies' coordinates by the exact chain rule:
///   K_ab -> map_a^T (K_ab map_b + D_ab map_rate_b) + [a == b] Curvature_a(f_a),
///   D_ab -> map_a^T D_ab map_b,
/// where f_a is the generalised force the element puts on slot a (SetSlotForce; required for
/// every slot on a flexible body) and a rigid slot's map is the identity.
class LocalForceJacobian {
 public:
  /// `slot_markers[s]` is the marker of slot s (its body may be the ground); at most
  /// kMaxForceSlots (an InternalError otherwise).
  LocalForceJacobian(std::initializer_list<const MarkerKinematics*> slot_markers);
  /// The same from the first `count` of an array.
  LocalForceJacobian(const MarkerKinematics* const* slot_markers, int count);
  int num_slots() const { return num_slots_; }
  int num_columns() const { return 6 * num_slots(); }
  /// Rows of f_a (slot a), columns X or V: 6 s x 6 s, zero at construction.
  SlotMatrix stiffness, damping;
  /// The generalised force [F (W); moment about the slot's origin in its axes] the element
  /// applies to slot `slot` (WrenchForce), for the curvature of a flexible slot's map.
  void SetSlotForce(int slot, const Eigen::Matrix<double, 6, 1>& f6);
  /// Adds every (slot a, slot b) block with both bodies off the ground to `sink`: always
  /// the same blocks for the same slots, whatever the values (a fixed sparse structure).
  /// @throws InternalError if a flexible slot has no slot force.
  void ScatterTo(ForceJacobianSink* sink) const;

 private:
  std::array<const MarkerKinematics*, kMaxForceSlots> markers_{};
  int num_slots_{0};
  Eigen::Matrix<double, kMaxSlotColumns, 1> slot_force_{
      Eigen::Matrix<double, kMaxSlotColumns, 1>::Zero()};
  std::array<bool, kMaxForceSlots> slot_force_set_{};
};

/// [F; R_WB^T (T + r x F)]: the generalised force on a (virtual) body of axes R_WB of a force
/// F [N] at arm r [m] from its origin and a couple T [N m] (F, T, r in W).
Eigen::Matrix<double, 6, 1> WrenchForce(const Eigen::Matrix3d& R_WB, const Eigen::Vector3d& F,
                                        const Eigen::Vector3d& T, const Eigen::Vector3d& r);

/// World-frame derivatives of marker M on the body of slot `slot` (3 x 6 num_slots each).
struct MarkerDerivatives {
  SlotRows<3> point_x;     ///< d p_WM / dX
  SlotRows<3> arm_x;       ///< d s_W / dX (s_W = p_WM - p_WB)
  SlotRows<3> rotation_x;  ///< d phi / dX, the body's virtual rotation in W
  SlotRows<3> velocity_x;  ///< d v_WM / dX
  SlotRows<3> velocity_v;  ///< d v_WM / dV
  SlotRows<3> omega_x;     ///< d omega_W / dX
  SlotRows<3> omega_v;     ///< d omega_W / dV
};
MarkerDerivatives DifferentiateMarker(const MarkerKinematics& M, int slot, int num_slots);

/// d f_a / dX for f_a = [F; R_a^T (T + r x F)] on the body of slot `slot_a` (6 x N), given
/// dF, dT and dr (3 x N) with respect to the same X.
SlotRows<6> WrenchStiffness(const Eigen::Matrix3d& R_WB, int slot_a, const Eigen::Vector3d& F,
                            const Eigen::Vector3d& T, const Eigen::Vector3d& r,
                            const SlotRows<3>& dF, const SlotRows<3>& dT, const SlotRows<3>& dr);

/// d f_a / dV for the same wrench (the arm and R_a do not depend on V) (6 x N).
SlotRows<6> WrenchDamping(const Eigen::Matrix3d& R_WB, const Eigen::Vector3d& r,
                          const SlotRows<3>& dF, const SlotRows<3>& dT);

}  // namespace emb::mbs
