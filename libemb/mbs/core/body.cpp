#include "libemb/mbs/core/body.h"

#include <cmath>

#include "libemb/common/error.h"

namespace emb::mbs {

void RigidBody::Validate() const {
  EMB_THROW_IF(!(mass > 0.0) || !std::isfinite(mass),
               "body '" << name << "': expected a positive mass [kg], got " << mass);
  const double scale = inertia_B.cwiseAbs().maxCoeff();
  // Relative asymmetry a user may leave from rounding the off-diagonal terms.
  constexpr double kSymmetryTolerance = 1e-9;
  EMB_THROW_IF(!inertia_B.allFinite() || (inertia_B - inertia_B.transpose()).cwiseAbs().maxCoeff() >
                                             kSymmetryTolerance * scale,
               "body '" << name << "': expected a symmetric inertia tensor [kg m^2]");
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(inertia_B);
  const Eigen::Vector3d I = eig.eigenvalues();
  EMB_THROW_IF(!(I.minCoeff() > 0.0),
               "body '" << name
                        << "': expected a positive definite inertia tensor, got principal "
                           "moments ["
                        << I.transpose() << "] kg m^2");
  // A real mass distribution has I1 <= I2 + I3 (equality for a plane lamina); allow round-off.
  constexpr double kTriangleSlack = 1e-9;
  EMB_THROW_IF(I[2] > (I[0] + I[1]) * (1.0 + kTriangleSlack),
               "body '" << name << "': principal moments [" << I.transpose()
                        << "] kg m^2 violate the triangle inequality I3 <= I1 + I2: no mass "
                           "distribution has this inertia");
  // Tolerance on R^T R = I for a rotation typed with ~12 digits or built from Euler angles.
  constexpr double kRotationTolerance = 1e-9;
  EMB_THROW_IF(
      (R_WB.transpose() * R_WB - Eigen::Matrix3d::Identity()).norm() > kRotationTolerance ||
          R_WB.determinant() < 0.0,
      "body '" << name << "': expected a proper rotation matrix for its orientation");
  if (elastic) {
    elastic->Validate(name);
    const int ne = elastic->num_modes();
    EMB_THROW_IF((eta0.size() != 0 && eta0.size() != ne) ||
                     (eta_dot0.size() != 0 && eta_dot0.size() != ne),
                 "flexible body '" << name << "': expected " << ne
                                   << " initial modal coordinates and rates");
  }
}

}  // namespace emb::mbs
