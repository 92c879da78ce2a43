#include "libemb/tribology/film_dae.h"

#include "libemb/common/error.h"

namespace emb::tribology {

FilmDae::FilmDae(const ReynoldsBearing& bearing) : bearing_(&bearing), film_(bearing) {
  EMB_THROW_IF(bearing.parameters().cavitation != CavitationModel::kMassConserving,
               bearing.who() << ": the film as DAE states needs the mass-conserving cavitation "
                                "model");
  x_.Resize(bearing.num_unknowns());
  r_.setZero(bearing.num_unknowns());
  storage_.term = StorageTerm::kDae;
  storage_.inverse_bulk_modulus = 1.0 / bearing.parameters().bulk_modulus;
}

FilmSolveInfo FilmDae::Prepare(const Eigen::VectorXd& u, const Eigen::VectorXd& u_dot,
                               const JournalKinematics& kin) {
  const int n = size();
  EMB_THROW_IF(u.size() != n || u_dot.size() != n,
               bearing_->who() << ": expected film states of size " << n << ", got "
                               << u.size() << " and " << u_dot.size());
  FilmSolveInfo info;
  std::string message;
  if (!film_.Set(kin, &message)) {
    info.status = FilmStatus::kJournalTouchesShell;
    info.message = message;
    return info;
  }
  if (!SetUnknownsFromUniversal(*bearing_, film_, u, &x_)) {
    info.status = FilmStatus::kBeyondViscosityLaw;
    info.message = bearing_->BeyondViscosityLawMessage();
    return info;
  }
  storage_.u_dot = &u_dot;
  return info;
}

FilmSolveInfo FilmDae::CalcResidual(const Eigen::VectorXd& u, const Eigen::VectorXd& u_dot,
                                    const JournalKinematics& kin, Eigen::VectorXd* r,
                                    BearingLoads* loads) {
  FilmSolveInfo info = Prepare(u, u_dot, kin);
  if (!info.ok()) return info;
  r->resize(size());
  CalcFilmResidual(film_, x_, u, storage_, r, &balance_);
  if (loads) CalcBearingLoads(film_, x_, balance_, loads, nullptr);
  return info;
}

FilmSolveInfo FilmDae::CalcJacobian(const Eigen::VectorXd& u, const Eigen::VectorXd& u_dot,
                                    const JournalKinematics& kin, FilmDaeJacobian* J,
                                    BearingLoads* loads) {
  FilmSolveInfo info = Prepare(u, u_dot, kin);
  if (!info.ok()) return info;
  FillFilmJacobian(film_, x_, storage_,
                   ColumnWeights{x_.dpsi_du.data(), x_.dtheta_du.data(), x_.dslack_du.data()},
                   &J->dr_du);
  const BearingGrid& g = bearing_->grid();
  J->dr_du_dot.resize(size());
  for (int k = 0; k < size(); ++k)
    J->dr_du_dot[k] =
        bearing_->is_supply(k) ? 0.0 : g.node_area() * film_.film(k) * DaeStorageSlope(x_, storage_, k);
  CalcFilmKinematicJacobian(film_, x_, storage_, &J->dr_dx, &J->dr_dv);
  CalcFilmResidual(film_, x_, u, storage_, &r_, &balance_);
  CalcBearingLoads(film_, x_, balance_, loads ? loads : &loads_, &J->loads);
  return info;
}

void FilmDae::DifferentialStates(const Eigen::VectorXd& u, Eigen::VectorXd* id) const {
  id->resize(size());
  for (int k = 0; k < size(); ++k) (*id)[k] = !bearing_->is_supply(k) && u[k] < 0.0 ? 1.0 : 0.0;
}

}  // namespace emb::tribology
