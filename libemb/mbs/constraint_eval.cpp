#include "libemb/mbs/constraint_eval.h"

#include <cmath>
#include <limits>

#include "libemb/common/error.h"
#include "libemb/mbs/primitive.h"
#include "libemb/mbs/rotation.h"
#include "libemb/mbs/system.h"

namespace emb::mbs {

ConstraintWorkspace::ConstraintWorkspace(const System& system)
    : angle_(system.num_angle_slots(), std::numeric_limits<double>::quiet_NaN()) {}

double ConstraintWorkspace::Unwrap(int slot, double raw, double hint) {
  EMB_CHECK(slot >= 0 && slot < static_cast<int>(angle_.size()));
  double& a = angle_[slot];
  const double reference = std::isnan(a) ? hint : a;
  a = reference + WrapAngle(raw - reference);
  return a;
}

void ConstraintWorkspace::Reset() {
  for (double& a : angle_) a = std::numeric_limits<double>::quiet_NaN();
}

ConstraintEval CalcConstraints(const System& system, const std::vector<BodyKinematics>& bodies,
                               double t, ConstraintWorkspace* workspace) {
  const StateLayout& L = system.layout();
  const int m = system.num_equations();
  ConstraintEval c;
  c.phi.setZero(m);
  c.jacobian.setZero(m, L.nv());
  c.quadratic.setZero(m);
  c.phi_t.setZero(m);
  c.phi_tt.setZero(m);
  for (int k = 0; k < m; ++k) {
    const ScalarEquation& eq = system.equations()[k];
    FunctionValue f;
    if (eq.has_function) f = eq.function.Eval(t);
    for (int term = 0; term < eq.num_terms; ++term) {
      const MarkerKinematics I = CalcMarkerKinematics(system, bodies, eq.marker_i[term]);
      const MarkerKinematics J = CalcMarkerKinematics(system, bodies, eq.marker_j[term]);
      const KernelEval g = EvalKernel(eq.kernel[term], I, J);
      double value = g.value;
      if (eq.angle_slot[term] >= 0) {
        EMB_CHECK(workspace != nullptr);
        // For a single-term motion the target branch is f(t); otherwise the raw branch.
        const double hint = eq.num_terms == 1 && eq.has_function ? f.f : g.value;
        value = workspace->Unwrap(eq.angle_slot[term], g.value, hint);
      }
      const double a = eq.coeff[term];
      c.phi[k] += a * value;
      if (!L.is_ground(I.body)) c.jacobian.block<1, 6>(k, L.velocity(I.body)) += a * g.d_i;
      if (!L.is_ground(J.body)) c.jacobian.block<1, 6>(k, L.velocity(J.body)) += a * g.d_j;
      c.quadratic[k] += a * g.quadratic;
    }
    if (eq.has_function) {
      c.phi[k] -= f.f;
      c.phi_t[k] = -f.df;
      c.phi_tt[k] = -f.d2f;
    }
  }
  return c;
}

WorstEquation FindWorstEquation(const Eigen::VectorXd& phi) {
  WorstEquation w;
  if (phi.size() == 0) return w;
  Eigen::Index i = 0;
  w.residual = phi.cwiseAbs().maxCoeff(&i);
  w.equation = static_cast<int>(i);
  return w;
}

}  // namespace emb::mbs
