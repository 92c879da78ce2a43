#include "libemb/mbs/flexible/static_compliance.h"

#include <algorithm>

#include "libemb/common/error.h"

namespace emb::mbs {

std::vector<unsigned> MarkerLoadsOf(const System& sys) {
  std::vector<unsigned> loads(sys.markers().size(), 0u);
  for (const ScalarEquation& eq : sys.equations())
    for (int n = 0; n < eq.num_terms; ++n) {
      unsigned i = 0, j = 0;
      switch (eq.kernel[n].kind) {
        case KernelKind::kPointComponent:  // e_k . (p_I - p_J)
          i = j = kMarkerForce;
          break;
        case KernelKind::kPointOnAxis:  // (p_I - p_J) . a_J: J's axis turns
          i = kMarkerForce;
          j = kMarkerForceAndMoment;
          break;
        case KernelKind::kAxisDot:  // a_I . b_J
        case KernelKind::kAngle:
          i = j = kMarkerMoment;
          break;
      }
      loads[eq.marker_i[n]] |= i;
      loads[eq.marker_j[n]] |= j;
    }
  for (const auto& f : sys.force_elements())
    for (int m : f->markers())
      if (m >= 0) loads[m] |= f->MarkerLoads(m);
  return loads;
}

double StaticComplianceError(const Eigen::MatrixXd& K, const Eigen::MatrixXd& F,
                             const Eigen::MatrixXd& T) {
  EMB_CHECK(K.rows() == K.cols() && F.rows() == K.rows() && T.rows() == K.rows());
  if (F.cols() == 0) return 0.0;
  const Eigen::LDLT<Eigen::MatrixXd> Kldlt(K);
  if (Kldlt.info() != Eigen::Success || !(Kldlt.vectorD().minCoeff() > 0.0))
    EMB_THROW(NumericalError, "static compliance: the stiffness is not positive definite");
  const Eigen::MatrixXd C_full = F.transpose() * Kldlt.solve(F);
  const Eigen::MatrixXd KT = T.transpose() * K * T;
  const Eigen::LDLT<Eigen::MatrixXd> KTldlt(KT);
  if (T.cols() > 0 && (KTldlt.info() != Eigen::Success || !(KTldlt.vectorD().minCoeff() > 0.0)))
    EMB_THROW(NumericalError, "static compliance: the stiffness of the basis is not positive "
                              "definite");
  const Eigen::MatrixXd TF = T.transpose() * F;
  const Eigen::MatrixXd C_new =
      T.cols() > 0 ? Eigen::MatrixXd(TF.transpose() * KTldlt.solve(TF))
                   : Eigen::MatrixXd::Zero(F.cols(), F.cols()).eval();
  const double scale = C_full.cwiseAbs().maxCoeff();
  if (!(scale > 0.0)) return 0.0;
  return (C_new - C_full).cwiseAbs().maxCoeff() / scale;
}

}  // namespace emb::mbs
