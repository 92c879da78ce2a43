#pragma once
/// @file
/// An implicit differential-algebraic problem F(t, y, y') = 0 as the time integrators see it.
/// The integrators know nothing of what y means (MFEM `linalg/ode.hpp` style): a multibody
/// system, a beam model or a test problem implement this interface.

#include <Eigen/Dense>
#include <limits>
#include <string>
#include <vector>

#include "libemb/integrators/matrix_assembler.h"

namespace emb {

/// Residual form F(t, y, y') = 0 of size n, with the iteration matrix
///   J = dF/dy + c_j dF/dy'   (n x n, dense or compressed-column sparse),
/// and a mask telling which components are differential (appear in y') and which are
/// algebraic (Lagrange multipliers, ...). Algebraic components are the ones an index-2
/// integrator may exclude from its local error test.
///
/// Non-virtual public methods check sizes; the protected Do* methods do the work
/// (Drake `force_element.h` pattern). Implementations must be thread-compatible: the
/// integrator calls them on a const object.
class DaeProblem {
 public:
  virtual ~DaeProblem() = default;

  /// Number of unknowns n.
  int size() const { return DoSize(); }

  /// r = F(t, y, y'). Sizes n. Implementations return false to flag a recoverable failure
  /// (e.g. a non-finite value), after which the integrator retries with a smaller step. A
  /// NumericalError thrown by the implementation (a model leaving its domain at a trial
  /// state, e.g. a journal bearing at eccentricity >= 1) is such a failure too: it is caught
  /// here, kept as last_recoverable_failure() and false is returned. Other exceptions pass
  /// (the integrator re-throws them).
  bool CalcResidual(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                    const Eigen::Ref<const Eigen::VectorXd>& yp,
                    Eigen::Ref<Eigen::VectorXd> r) const;

  /// True if CalcJacobian() is implemented; otherwise the integrator uses difference
  /// quotients.
  bool has_jacobian() const { return DoHasJacobian(); }

  /// J = dF/dy + cj dF/dy' at (t, y, y'), n x n, overwritten. Returns false for a
  /// recoverable failure, as CalcResidual() does: the implementation said so, a NumericalError
  /// (kept as last_recoverable_failure()) or a non-finite entry; J is then unspecified and
  /// the integrators retry with a smaller step. @pre has_jacobian().
  bool CalcJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                    const Eigen::Ref<const Eigen::VectorXd>& yp,
                    Eigen::Ref<Eigen::MatrixXd> jacobian) const;

  /// True if CalcSparseJacobian() assembles a genuinely sparse matrix. Otherwise
  /// CalcSparseJacobian() stores the dense CalcJacobian() result with all n^2 entries.
  bool has_sparse_jacobian() const { return DoHasSparseJacobian(); }
  /// Disjoint groups of unknowns that the iteration matrix couples densely among themselves
  /// but only sparsely with the rest (a flexible body's modal coordinates and rates): a
  /// sparse linear solver may eliminate them as dense blocks (block_elimination_lu.h).
  /// Empty by default.
  std::vector<std::vector<int>> DenseBlocks() const { return DoDenseBlocks(); }

  /// J = dF/dy + cj dF/dy' as a compressed-column matrix. On the first call (J empty,
  /// 0 x 0) the problem builds the structure: every entry that can be non-zero at any
  /// state. Later calls with the same matrix keep that structure and refill only the values
  /// (see MatrixAssembler). Same values and the same failure channel as CalcJacobian() (a
  /// failure in the first call, which builds the structure, throws: there is nothing to
  /// retry with). @pre has_jacobian().
  bool CalcSparseJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                          const Eigen::Ref<const Eigen::VectorXd>& yp, SparseMatrixd* jacobian) const;

  /// 1 for a differential component, 0 for an algebraic one (size n).
  Eigen::VectorXd DifferentialMask() const;

  /// Number of root (event) functions g(t, y, y') whose sign changes the integrator locates
  /// (contact onset and separation of impact elements, ...). Default 0: no events.
  int num_roots() const { return DoNumRoots(); }

  /// g = G(t, y, y') (size num_roots()). Each g_i must be continuous along the solution
  /// between two events; a sign change between two steps is an event, located in time by
  /// the integrator (IdaSolver: IDA's root finding, to ~100 unit round-offs of t). Returns
  /// false for a non-finite value. A NumericalError of the implementation is kept as for
  /// CalcResidual() and false is returned.
  bool CalcRoots(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                 const Eigen::Ref<const Eigen::VectorXd>& yp, Eigen::Ref<Eigen::VectorXd> g) const;

  /// A human-readable name of component i ("body crank: q_w", "joint pin: lambda[2]"),
  /// used in failure reports. Default "y[i]".
  std::string ComponentName(int i) const { return DoComponentName(i); }

  /// The message of the last NumericalError turned into a recoverable failure since
  /// ClearRecoverableFailure() (empty if none): what an integrator that gives up quotes.
  const std::string& last_recoverable_failure() const { return recoverable_failure_; }
  void ClearRecoverableFailure() const { recoverable_failure_.clear(); }

  /// The scale that IdaOptions::follow_relative follows, read after every accepted step:
  /// the problem's own measure of what the followed (algebraic) unknowns balance, from its
  /// last residual evaluation, or NaN (the default): the followed block's largest |y_i|. A
  /// measure made of error-tested unknowns cannot run away; the multipliers' own values
  /// can, because a raised tolerance lets the corrector keep their extrapolated predictor,
  /// whose growth then raises the tolerance again (issue 36: an inline-4 whose beam crank
  /// had no damping, at rtol 1e-8: a dyno bearing's tilt multipliers x2 per step to 1e306).
  double FollowedScale() const { return DoFollowedScale(); }

 protected:
  /// For implementations that learn of a failure without an exception (a force element's
  /// domain failure reported through its context): kept as last_recoverable_failure().
  void ReportRecoverableFailure(const std::string& message) const {
    recoverable_failure_ = message;
  }
  virtual int DoSize() const = 0;
  virtual bool DoCalcResidual(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                              const Eigen::Ref<const Eigen::VectorXd>& yp,
                              Eigen::Ref<Eigen::VectorXd> r) const = 0;
  virtual bool DoHasJacobian() const { return false; }
  virtual double DoFollowedScale() const { return std::numeric_limits<double>::quiet_NaN(); }
  /// False: a recoverable failure (see CalcJacobian()).
  virtual bool DoCalcJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                              const Eigen::Ref<const Eigen::VectorXd>& yp,
                              Eigen::Ref<Eigen::MatrixXd> jacobian) const;
  virtual bool DoHasSparseJacobian() const { return false; }
  /// Default: the dense DoCalcJacobian() stored with a full structure (for small problems).
  virtual bool DoCalcSparseJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                                    const Eigen::Ref<const Eigen::VectorXd>& yp,
                                    SparseMatrixd* jacobian) const;
  virtual Eigen::VectorXd DoDifferentialMask() const = 0;
  virtual int DoNumRoots() const { return 0; }
  virtual bool DoCalcRoots(double, const Eigen::Ref<const Eigen::VectorXd>&,
                           const Eigen::Ref<const Eigen::VectorXd>&,
                           Eigen::Ref<Eigen::VectorXd>) const {
    return true;
  }
  virtual std::vector<std::vector<int>> DoDenseBlocks() const { return {}; }
  virtual std::string DoComponentName(int i) const;

 private:
  mutable std::string recoverable_failure_;
};

}  // namespace emb
