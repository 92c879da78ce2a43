#pragma once
/// @file
/// Evaluation of all scalar constraint equations of a System (seed eq. 1.24, second part):
/// values Phi(q, t), the Jacobian C = dPhi/d[delta p, delta pi] (m x nv), the velocity
/// term C v, the quadratic term Cdot v and the explicit time derivatives, so that
///   velocity level:      C v + Phi_t = 0,
///   acceleration level:  C vdot = gamma = -(Cdot v) - Phi_tt.
/// C is sparse: an equation touches at most four bodies (two kernel terms of a coupler),
/// so a row has at most 24 non-zeros. Cost O(m).

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "libemb/mbs/core/force_element.h"
#include "libemb/mbs/core/kinematics.h"

namespace emb::mbs {

class System;

/// The mutable part of a run: continuous (unwrapped) values of the angle kernels, one slot
/// each, and the discrete states of force elements (contacts open or closed, ...). An angle
/// slot starts unset; its first value is taken on the branch nearest to the equation's target
/// (f(t) for a motion) and later values within +-pi of the previous one. A state slot starts
/// NaN (the element derives its state from the configuration).
class ConstraintWorkspace {
 public:
  explicit ConstraintWorkspace(const System& system);
  /// The continuous angle for raw atan2 value `raw` [rad].
  double Unwrap(int slot, double raw, double hint);
  /// A force element's state slot (force_element.h), NaN until set.
  double state(int slot) const;
  void set_state(int slot, double value);
  /// True while a dynamic analysis locates events (IDA root finding, event_handling.h):
  /// elements with discrete states then keep them from event to event. False (statics,
  /// linearisation, ...): they take the state their configuration implies at every call.
  bool events_active() const { return events_active_; }
  void set_events_active(bool active) { events_active_ = active; }
  /// Forgets all slots (e.g. before a new assembly); the elements' data is kept (warm
  /// starts only).
  void Reset();
  /// Force element e's data (ForceElement::MakeData), null if it keeps none.
  ForceElementData* element_data(const ForceElement* e) const;

 private:
  std::vector<double> angle_;
  /// One entry per element that keeps data (few: a linear search).
  std::vector<std::pair<const ForceElement*, std::unique_ptr<ForceElementData>>> element_data_;
  bool events_active_{false};
};

/// Element e's data in the context's workspace (ForceElement::MakeData); null without a
/// workspace or for an element that keeps none.
inline ForceElementData* ElementData(const ForceContext& ctx, const ForceElement& e) {
  return ctx.workspace != nullptr ? ctx.workspace->element_data(&e) : nullptr;
}

/// The constraint Jacobian C (m x nv), row-major sparse.
using ConstraintJacobian = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

/// Values of all equations at one configuration.
struct ConstraintEval {
  Eigen::VectorXd phi;          ///< Phi(q, t), m
  ConstraintJacobian jacobian;  ///< C, m x nv (use Eigen::MatrixXd(C) for dense algorithms)
  Eigen::VectorXd quadratic;  ///< Cdot v, m
  Eigen::VectorXd phi_t;      ///< dPhi/dt, m
  Eigen::VectorXd phi_tt;     ///< d2Phi/dt2, m
  /// gamma = -(Cdot v) - Phi_tt (acceleration right-hand side).
  Eigen::VectorXd gamma() const { return -quadratic - phi_tt; }

  /// Scratch of the in-place CalcConstraints: the Jacobian's entries in the order they are
  /// made and where each lands in `jacobian` (the structure is the same at every state, so
  /// after the first evaluation the values are summed in place).
  std::vector<Eigen::Triplet<double, int>> entries;
  std::vector<int> entry_slot;
  Eigen::RowVectorXd row_scratch;
};

/// Evaluates all equations at body kinematics `bodies` and time t.
ConstraintEval CalcConstraints(const System& system, const std::vector<BodyKinematics>& bodies,
                               double t, ConstraintWorkspace* workspace);
/// The same from the markers' kinematics at that state (CalcAllMarkerKinematics) into `out`,
/// reusing its storage: after the first call at a system, no allocation.
void CalcConstraints(const System& system, const std::vector<MarkerKinematics>& markers,
                     double t, ConstraintWorkspace* workspace, ConstraintEval* out);

/// One kernel term (coeff g) of equation `equation` between the bodies of markers I and J,
/// with its Jacobian row and second derivatives in x = [delta p_i, delta pi_i, delta p_j,
/// delta pi_j] (primitive.h), both already multiplied by the coefficient.
struct KernelTerm {
  int equation{0};
  int body_i{0}, body_j{0};                        ///< 0 = ground
  Eigen::Matrix<double, 1, 12> gradient;           ///< coeff [d_i, d_j]
  Eigen::Matrix<double, 12, 12> hessian;           ///< coeff EvalKernelHessian(...)
  /// Markers on flexible bodies (kinematics.h), valid during the visit, null on rigid ones:
  /// the gradient and hessian of such a side are with respect to its marker frame; on the
  /// body's coordinates the gradient is gradient_s map_s and the second derivatives are
  /// map_s^T hessian map_t plus, on the diagonal, CalcMarkerCurvature(marker_s, multiplier x
  /// gradient_s) (the curvature of the marker map).
  const MarkerKinematics* marker[2]{nullptr, nullptr};
};

/// Calls `visit` for every kernel term of every equation, in equation order (the iteration
/// matrices of the GGL DAE and of statics are assembled from these). Cost O(m).
void VisitKernelTerms(const System& system, const std::vector<BodyKinematics>& bodies,
                      const std::function<void(const KernelTerm&)>& visit);
/// The same from the markers' kinematics at that state (CalcAllMarkerKinematics).
void VisitKernelTerms(const System& system, const std::vector<MarkerKinematics>& markers,
                      const std::function<void(const KernelTerm&)>& visit);

/// The equation with the largest |Phi| and its value (for "assembly failed at ..." reports).
struct WorstEquation {
  int equation{-1};
  double residual{0.0};
};
WorstEquation FindWorstEquation(const Eigen::VectorXd& phi);

}  // namespace emb::mbs
