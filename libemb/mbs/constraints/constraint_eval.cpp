#include "libemb/mbs/constraints/constraint_eval.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "libemb/common/error.h"
#include "libemb/mbs/constraints/primitive.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {

ConstraintWorkspace::ConstraintWorkspace(const System& system)
    : angle_(system.num_angle_slots(), std::numeric_limits<double>::quiet_NaN()) {
  for (const auto& e : system.force_elements())
    if (std::unique_ptr<ForceElementData> d = e->MakeData())
      element_data_.emplace_back(e.get(), std::move(d));
}

ForceElementData* ConstraintWorkspace::element_data(const ForceElement* e) const {
  for (const auto& [element, data] : element_data_)
    if (element == e) return data.get();
  return nullptr;
}

double ConstraintWorkspace::Unwrap(int slot, double raw, double hint) {
  EMB_CHECK(slot >= 0 && slot < static_cast<int>(angle_.size()));
  double& a = angle_[slot];
  const double reference = std::isnan(a) ? hint : a;
  a = reference + WrapAngle(raw - reference);
  return a;
}

double ConstraintWorkspace::state(int slot) const {
  EMB_CHECK(slot >= 0 && slot < static_cast<int>(angle_.size()));
  return angle_[slot];
}

void ConstraintWorkspace::set_state(int slot, double value) {
  EMB_CHECK(slot >= 0 && slot < static_cast<int>(angle_.size()));
  angle_[slot] = value;
}

void ConstraintWorkspace::Reset() {
  for (double& a : angle_) a = std::numeric_limits<double>::quiet_NaN();
}

ConstraintEval CalcConstraints(const System& system, const std::vector<BodyKinematics>& bodies,
                               double t, ConstraintWorkspace* workspace) {
  std::vector<MarkerKinematics> markers;
  CalcAllMarkerKinematics(system, bodies, &markers);
  ConstraintEval c;
  CalcConstraints(system, markers, t, workspace, &c);
  return c;
}

void CalcConstraints(const System& system, const std::vector<MarkerKinematics>& markers,
                     double t, ConstraintWorkspace* workspace, ConstraintEval* out) {
  const StateLayout& L = system.layout();
  const int m = system.num_equations();
  ConstraintEval& c = *out;
  c.phi.setZero(m);
  c.quadratic.setZero(m);
  c.phi_t.setZero(m);
  c.phi_tt.setZero(m);
  std::vector<Eigen::Triplet<double, int>>& entries = c.entries;
  entries.clear();
  auto add_row = [&](int k, const MarkerKinematics& M, double a,
                     const Eigen::Matrix<double, 1, 6>& d) {
    if (L.is_ground(M.body)) return;
    if (!M.flexible()) {
      for (int i = 0; i < 6; ++i) entries.emplace_back(k, L.velocity(M.body) + i, a * d[i]);
      return;
    }
    c.row_scratch.noalias() = d * M.map;  // through the marker map (kinematics.h)
    const Eigen::RowVectorXd& dm = c.row_scratch;
    for (int i = 0; i < 6; ++i) entries.emplace_back(k, L.velocity(M.body) + i, a * dm[i]);
    for (int i = 6; i < dm.size(); ++i)
      entries.emplace_back(k, L.elastic_v(M.body) + i - 6, a * dm[i]);
  };
  for (int k = 0; k < m; ++k) {
    const ScalarEquation& eq = system.equations()[k];
    FunctionValue f;
    if (eq.has_function)
      f = eq.function.EvalAtTime(t, 2, "motion", system.elements()[eq.element].name);
    for (int term = 0; term < eq.num_terms; ++term) {
      const MarkerKinematics& I = markers[eq.marker_i[term]];
      const MarkerKinematics& J = markers[eq.marker_j[term]];
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
      add_row(k, I, a, g.d_i);
      add_row(k, J, a, g.d_j);
      c.quadratic[k] += a * (g.quadratic + g.d_i.dot(I.extra) + g.d_j.dot(J.extra));
    }
    if (eq.has_function) {
      c.phi[k] -= f.f;
      c.phi_t[k] = -f.df;
      c.phi_tt[k] = -f.d2f;
    }
  }
  // The entries come in the same order at every state: sum them into the structure found
  // the first time (setFromTriplets sums shared bodies; so does the slot map).
  if (c.entry_slot.size() == entries.size() && c.jacobian.rows() == m &&
      c.jacobian.cols() == L.nv()) {
    double* values = c.jacobian.valuePtr();
    std::fill(values, values + c.jacobian.nonZeros(), 0.0);
    for (std::size_t e = 0; e < entries.size(); ++e) values[c.entry_slot[e]] += entries[e].value();
    return;
  }
  c.jacobian.resize(m, L.nv());
  c.jacobian.setFromTriplets(entries.begin(), entries.end());
  c.jacobian.makeCompressed();
  c.entry_slot.resize(entries.size());
  const int* outer = c.jacobian.outerIndexPtr();
  const int* inner = c.jacobian.innerIndexPtr();
  for (std::size_t e = 0; e < entries.size(); ++e) {
    const int row = entries[e].row(), col = entries[e].col();
    const int* begin = inner + outer[row];
    const int* end = inner + outer[row + 1];
    const int* at = std::lower_bound(begin, end, col);
    EMB_CHECK(at != end && *at == col);
    c.entry_slot[e] = static_cast<int>(at - inner);
  }
}

void VisitKernelTerms(const System& system, const std::vector<BodyKinematics>& bodies,
                      const std::function<void(const KernelTerm&)>& visit) {
  std::vector<MarkerKinematics> markers;
  CalcAllMarkerKinematics(system, bodies, &markers);
  VisitKernelTerms(system, markers, visit);
}

void VisitKernelTerms(const System& system, const std::vector<MarkerKinematics>& markers,
                      const std::function<void(const KernelTerm&)>& visit) {
  KernelTerm term;
  for (int k = 0; k < system.num_equations(); ++k) {
    const ScalarEquation& eq = system.equations()[k];
    for (int n = 0; n < eq.num_terms; ++n) {
      const MarkerKinematics& I = markers[eq.marker_i[n]];
      const MarkerKinematics& J = markers[eq.marker_j[n]];
      const KernelEval g = EvalKernel(eq.kernel[n], I, J);
      const double a = eq.coeff[n];
      term.equation = k;
      term.body_i = I.body;
      term.body_j = J.body;
      term.gradient << a * g.d_i, a * g.d_j;
      term.hessian = a * EvalKernelHessian(eq.kernel[n], I, J);
      term.marker[0] = I.flexible() ? &I : nullptr;
      term.marker[1] = J.flexible() ? &J : nullptr;
      visit(term);
    }
  }
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
