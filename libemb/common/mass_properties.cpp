#include "libemb/common/mass_properties.h"

namespace emb {

Eigen::Matrix3d ParallelAxisTerm(double mass, const Eigen::Vector3d& d) {
  return mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
}

Eigen::Matrix3d InertiaFromSecondMoment(const Eigen::Matrix3d& J) {
  return J.trace() * Eigen::Matrix3d::Identity() - J;
}

Eigen::Matrix3d MassProperties::InertiaAbout(const Eigen::Vector3d& p_O) const {
  return inertia_about_com + ParallelAxisTerm(mass, center_of_mass - p_O);
}

void MassPropertiesSum::Add(double mass, const Eigen::Vector3d& center_of_mass,
                            const Eigen::Matrix3d& inertia_about_com, double volume) {
  parts_.push_back({volume, mass, center_of_mass, inertia_about_com});
  mass_ += mass;
}

MassProperties MassPropertiesSum::Result() const {
  MassProperties out;
  out.mass = mass_;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  for (const MassProperties& p : parts_) {
    out.volume += p.volume;
    first += p.mass * p.center_of_mass;
  }
  if (!(mass_ > 0.0)) return out;
  out.center_of_mass = first / mass_;
  for (const MassProperties& p : parts_)
    out.inertia_about_com += p.InertiaAbout(out.center_of_mass);
  return out;
}

MassProperties MassPropertiesFromRigidMass(const Eigen::Matrix<double, 6, 6>& M_rr) {
  MassProperties p;
  p.mass = M_rr.topLeftCorner<3, 3>().trace() / 3.0;
  if (!(p.mass > 0.0)) return p;
  // Lower-left block m [c×], upper-right −m [c×]: c from the averaged off-diagonal entries.
  const Eigen::Matrix3d mS = 0.5 * (M_rr.block<3, 3>(3, 0) - M_rr.block<3, 3>(0, 3));
  p.center_of_mass = Eigen::Vector3d(mS(2, 1), mS(0, 2), mS(1, 0)) / p.mass;
  const Eigen::Matrix3d I_O = 0.5 * (M_rr.block<3, 3>(3, 3) + M_rr.block<3, 3>(3, 3).transpose());
  p.inertia_about_com = I_O - ParallelAxisTerm(p.mass, p.center_of_mass);
  return p;
}

}  // namespace emb
