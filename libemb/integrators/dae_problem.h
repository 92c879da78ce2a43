#pragma once
/// @file
/// An implicit differential-algebraic problem F(t, y, y') = 0 as the time integrators see it.
/// The integrators know nothing of what y means (MFEM `linalg/ode.hpp` style): a multibody
/// system, a beam model or a test problem implement this interface.

#include <Eigen/Dense>
#include <string>
#include <utility>
#include <vector>

namespace emb {

/// Residual form F(t, y, y') = 0 of size n, with the iteration matrix
///   J = dF/dy + c_j dF/dy'   (n x n, dense),
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

  /// r = F(t, y, y'). Sizes n. Implementations may throw (the integrator re-throws) or
  /// return false to flag a recoverable failure (e.g. a non-finite value), after which the
  /// integrator retries with a smaller step.
  bool CalcResidual(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                    const Eigen::Ref<const Eigen::VectorXd>& yp,
                    Eigen::Ref<Eigen::VectorXd> r) const;

  /// True if CalcJacobian() is implemented; otherwise the integrator uses difference
  /// quotients.
  bool has_jacobian() const { return DoHasJacobian(); }

  /// J = dF/dy + cj dF/dy' at (t, y, y'), n x n, overwritten.
  /// @pre has_jacobian().
  void CalcJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                    const Eigen::Ref<const Eigen::VectorXd>& yp,
                    Eigen::Ref<Eigen::MatrixXd> jacobian) const;

  /// Structurally non-zero entries (row, column) of the iteration matrix, for sparse
  /// linear solvers; empty means "treat as dense". Entries outside the pattern must be zero
  /// in every CalcJacobian result.
  std::vector<std::pair<int, int>> JacobianPattern() const { return DoJacobianPattern(); }

  /// 1 for a differential component, 0 for an algebraic one (size n).
  Eigen::VectorXd DifferentialMask() const;

  /// A human-readable name of component i ("body crank: q_w", "joint pin: lambda[2]"),
  /// used in failure reports. Default "y[i]".
  std::string ComponentName(int i) const { return DoComponentName(i); }

 protected:
  virtual int DoSize() const = 0;
  virtual bool DoCalcResidual(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                              const Eigen::Ref<const Eigen::VectorXd>& yp,
                              Eigen::Ref<Eigen::VectorXd> r) const = 0;
  virtual bool DoHasJacobian() const { return false; }
  virtual void DoCalcJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                              const Eigen::Ref<const Eigen::VectorXd>& yp,
                              Eigen::Ref<Eigen::MatrixXd> jacobian) const;
  virtual std::vector<std::pair<int, int>> DoJacobianPattern() const { return {}; }
  virtual Eigen::VectorXd DoDifferentialMask() const = 0;
  virtual std::string DoComponentName(int i) const;
};

}  // namespace emb
