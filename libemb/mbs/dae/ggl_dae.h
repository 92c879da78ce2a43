#pragma once
/// @file
/// The constrained equations of motion (seed eq. 1.24) in the stabilised index-2 form of
/// Gear, Gupta and Leimkuhler (GGL), as in SUNDIALS' idaSlCrank_dns example, for
/// quaternion coordinates. Unknowns y = [q (nq), v (nv), lambda (m), mu (m + nb), z (nz)]
/// (z: the force elements' continuous states, ForceElement::num_continuous_states, with
/// their own rows R(t, z, z', q, v) = 0 and their forces f(q, v, z) in the dynamic rows):
///
///   q'  - H(q) v + B(q)^T mu       = 0   (nq)  kinematics, stabilised
///   M v' - f(q, v, t) + C(q)^T lambda = 0 (nv)  Newton-Euler with reactions
///   C(q) v + Phi_t(t)              = 0   (m)   velocity constraints
///   [Phi(q, t); (|e_b|^2 - 1)/2]   = 0   (m + nb) position and unit-quaternion constraints
///
/// with H v = [v_WB; 1/2 Q(e) omega_B] per body, C the velocity Jacobian (constraint_eval.h)
/// and B = d[Phi; (|e|^2-1)/2]/dq, whose quaternion block is C_pi (2/|e|) Q(e/|e|)^T
/// (the rotation is evaluated from the normalised quaternion) and e^T for the norm row.
/// At a solution mu = 0; the mu terms only pull q back onto the constraint manifold.
/// lambda and mu are algebraic and excluded from IDA's error test.
///
/// The iteration matrix dF/dy + cj dF/dy' is analytic: besides cj I, cj M, H, C, B and the
/// gyroscopic term it has the second-derivative terms sum_k lambda_k K_k, sum_k mu_k K_k
/// and v^T K_k of the constraint kernels (EvalKernelHessian), mapped from [delta p, delta pi]
/// to q by X_b = [I 0; 0 (2/|e|^2) Q(e)^T] (delta pi = (2/|e|^2) Q(e)^T delta e), the
/// derivative of that map in B^T mu, and the force elements' stiffness -K_ab X_b and
/// damping -D_ab (force_jacobian.h). It is assembled block by block (per body, per kernel
/// term, per force element) through a MatrixAssembler, into a dense matrix for the dense
/// solver or into a compressed-column matrix whose structure is fixed at the first call
/// (KLU): O(number of blocks) per evaluation, no n x n work on the sparse path. Flexible
/// bodies are exact too: their inertia's dependence on eta and R (d(M(eta) v')/dx), the
/// frame acceleration in the translational geometric stiffness, and the curvature of the
/// marker maps of their markers (kinematics.h, CalcMarkerCurvature) in the constraint and
/// force terms.

#include <Eigen/Dense>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "libemb/integrators/dae_problem.h"
#include "libemb/mbs/dae/ggl_workspace.h"
#include "libemb/mbs/constraints/constraint_eval.h"

namespace emb::mbs {

class System;

/// Offsets of the blocks of the GGL unknown vector.
class GglLayout {
 public:
  GglLayout() = default;
  GglLayout(int nq, int nv, int m, int num_moving, int nz = 0)
      : nq_(nq), nv_(nv), m_(m), nb_(num_moving), nz_(nz) {}
  int q() const { return 0; }
  int v() const { return nq_; }
  int lambda() const { return nq_ + nv_; }
  int mu() const { return nq_ + nv_ + m_; }
  int z() const { return nq_ + nv_ + 2 * m_ + nb_; }
  int size() const { return nq_ + nv_ + 2 * m_ + nb_ + nz_; }
  int nq() const { return nq_; }
  int nv() const { return nv_; }
  int m() const { return m_; }
  int num_mu() const { return m_ + nb_; }
  int nz() const { return nz_; }

 private:
  int nq_{0}, nv_{0}, m_{0}, nb_{0}, nz_{0};
};

/// The GGL DAE of a finalized System (the model, immutable) evaluated into a GglWorkspace (the
/// data: every evaluation's scratch and the continuous joint angles; Pinocchio's
/// Model/Data). The workspace is the caller's or the DAE's own; one workspace serves one
/// integration at a time.
class GglDae final : public DaeProblem {
 public:
  /// With a workspace of its own.
  explicit GglDae(const System& system);
  /// With the caller's workspace, built from the same System (not owned; must outlive the
  /// DAE).
  GglDae(const System& system, GglWorkspace* workspace);
  ~GglDae() override;

  /// The workspace the evaluations fill (the caller's or the DAE's own).
  GglWorkspace& data() const { return *ws_; }

  const GglLayout& ggl_layout() const { return layout_; }

  /// Consistent (y, y') from an assembled q, projected v and the acceleration solution; the
  /// force elements' states z and rates z' given (a restart keeps them), or, if null, their
  /// steady states at (q, v) (ForceElement::CalcSteadyStates).
  void MakeInitialValues(const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                         const Eigen::VectorXd& vdot, const Eigen::VectorXd& lambda,
                         Eigen::VectorXd* y, Eigen::VectorXd* yp,
                         const Eigen::VectorXd* z = nullptr,
                         const Eigen::VectorXd* z_dot = nullptr) const;

  ConstraintWorkspace& workspace() const { return ws_->constraint; }

  /// The event functions of the force elements (ForceElement::CalcEventFunctions), element
  /// after element: force element k owns roots [root_offset(k), root_offset(k) + its
  /// num_event_functions()). -1 if it has none.
  int root_offset(int k) const { return root_offset_.at(k); }

 protected:
  int DoSize() const override { return layout_.size(); }
  bool DoCalcResidual(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                      const Eigen::Ref<const Eigen::VectorXd>& yp,
                      Eigen::Ref<Eigen::VectorXd> r) const override;
  bool DoHasJacobian() const override { return true; }
  /// The multipliers' tolerance follows the loads they balance: the largest generalised
  /// force (applied, gravity, gyroscopic, elastic) of the last residual evaluation
  /// [N, N m], made of error-tested positions and velocities (DaeProblem::FollowedScale).
  double DoFollowedScale() const override { return ws_->force_scale; }
  bool DoCalcJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                      const Eigen::Ref<const Eigen::VectorXd>& yp,
                      Eigen::Ref<Eigen::MatrixXd> jacobian) const override;
  Eigen::VectorXd DoDifferentialMask() const override;
  /// One block per flexible body: its modal coordinates and rates (dense among themselves
  /// through the mass, stiffness and geometric-stiffness terms and the marker maps).
  std::vector<std::vector<int>> DoDenseBlocks() const override;
  std::string DoComponentName(int i) const override;
  int DoNumRoots() const override { return num_roots_; }
  bool DoCalcRoots(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                   const Eigen::Ref<const Eigen::VectorXd>& yp,
                   Eigen::Ref<Eigen::VectorXd> g) const override;
  bool DoHasSparseJacobian() const override { return true; }
  bool DoCalcSparseJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                            const Eigen::Ref<const Eigen::VectorXd>& yp,
                            SparseMatrixd* jacobian) const override;

 private:
  // The iteration matrix through `assembler` (begun by the caller; finished here, or
  // abandoned and false on a failure reported by a force element).
  bool AssembleJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                        const Eigen::Ref<const Eigen::VectorXd>& yp,
                        MatrixAssembler* assembler) const;
  // Body and marker kinematics at y into the workspace; false for a state the residual
  // cannot be evaluated at (a vanishing quaternion, a non-finite value).
  bool UpdateKinematics(const Eigen::Ref<const Eigen::VectorXd>& y) const;
  // visit(index in z, element, its state j) for every force element's state.
  void ForEachForceState(const std::function<void(int, const ForceElement&, int)>& visit) const;

  const System& system_;
  GglLayout layout_;
  // The evaluation scratch (the System stays immutable; const evaluations fill it): the
  // caller's, or own_.
  std::unique_ptr<GglWorkspace> own_;
  GglWorkspace* ws_;
  std::vector<int> root_offset_;  // per force element (ggl_dae_events.cpp)
  int num_roots_{0};
  void InitRoots();
};

}  // namespace emb::mbs
