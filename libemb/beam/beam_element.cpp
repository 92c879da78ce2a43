#include "libemb/beam/beam_element.h"

#include <Eigen/Geometry>
#include <cmath>

#include "libemb/common/error.h"
#include "libemb/common/skew.h"

namespace emb {
namespace {

using Matrix4d = Eigen::Matrix4d;

// Consistent mass of one bending plane for (v₁, θ₁, v₂, θ₂) with θ = +dv/dx: translational
// inertia ρA and rotary inertia ρI, Timoshenko shape functions with shear parameter Φ
// (Przemieniecki 1968, §11.6; Φ = 0 gives ρAL/420·[156 22L 54 −13L; …] + ρI/(30L)·[36 3L …]).
Matrix4d PlaneConsistentMass(double rhoA, double rhoI, double L, double phi) {
  const double f = phi, f2 = phi * phi, b2 = (1.0 + phi) * (1.0 + phi);
  const double L2 = L * L;
  const double t11 = 13.0 / 35 + 7.0 / 10 * f + f2 / 3;
  const double t12 = (11.0 / 210 + 11.0 / 120 * f + f2 / 24) * L;
  const double t13 = 9.0 / 70 + 3.0 / 10 * f + f2 / 6;
  const double t14 = -(13.0 / 420 + 3.0 / 40 * f + f2 / 24) * L;
  const double t22 = (1.0 / 105 + f / 60 + f2 / 120) * L2;
  const double t24 = -(1.0 / 140 + f / 60 + f2 / 120) * L2;
  Matrix4d T;
  T << t11, t12, t13, t14,  //
      t12, t22, -t14, t24,  //
      t13, -t14, t11, -t12, //
      t14, t24, -t12, t22;
  const double r12 = (1.0 / 10 - f / 2) * L;
  const double r22 = (2.0 / 15 + f / 6 + f2 / 3) * L2;
  const double r24 = (-1.0 / 30 - f / 6 + f2 / 6) * L2;
  Matrix4d R;
  R << 6.0 / 5, r12, -6.0 / 5, r12,  //
      r12, r22, -r12, r24,           //
      -6.0 / 5, -r12, 6.0 / 5, -r12, //
      r12, r24, -r12, r22;
  return rhoA * L / b2 * T + rhoI / (b2 * L) * R;
}

// Scatters a 4×4 plane matrix onto the 12 unknowns at indices idx.
void Scatter(const Matrix4d& A, const int (&idx)[4], Matrix12d& out) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) out(idx[i], idx[j]) += A(i, j);
}

}  // namespace

double BeamElementProperties::shear_parameter_y() const {
  if (!shear_deformable) return 0.0;
  const auto& s = section;
  return 12.0 * youngs_modulus * s.second_moment_y /
         (s.shear_coefficient * shear_modulus * s.area * length * length);
}

double BeamElementProperties::shear_parameter_z() const {
  if (!shear_deformable) return 0.0;
  const auto& s = section;
  return 12.0 * youngs_modulus * s.second_moment_z /
         (s.shear_coefficient * shear_modulus * s.area * length * length);
}

BeamElementProperties MakeBeamElementProperties(double length, const BeamSection& section,
                                                const IsotropicMaterial& material,
                                                bool shear_deformable, const std::string& what) {
  EMB_THROW_IF(!(std::isfinite(length) && length > 0.0),
               what << ": length: expected > 0 m, got " << length);
  ValidateSection(section, what);
  material.Validate();
  BeamElementProperties p;
  p.length = length;
  p.section = section;
  p.youngs_modulus = material.youngs_modulus;
  p.shear_modulus = material.mu();
  p.density = material.density;
  p.shear_deformable = shear_deformable;
  return p;
}

Matrix6d CalcBeamEndStiffness(const BeamElementProperties& p) {
  const double L = p.length, E = p.youngs_modulus, G = p.shear_modulus;
  const auto& s = p.section;
  const double EIy = E * s.second_moment_y, EIz = E * s.second_moment_z;
  const double phi_y = p.shear_parameter_y(), phi_z = p.shear_parameter_z();
  const double by = 1.0 + phi_y, bz = 1.0 + phi_z;
  Matrix6d K = Matrix6d::Zero();
  K(kUx, kUx) = E * s.area / L;
  K(kUy, kUy) = 12.0 * EIz / (L * L * L * bz);
  K(kUy, kThetaZ) = K(kThetaZ, kUy) = -6.0 * EIz / (L * L * bz);
  K(kThetaZ, kThetaZ) = (4.0 + phi_z) * EIz / (L * bz);
  K(kUz, kUz) = 12.0 * EIy / (L * L * L * by);
  K(kUz, kThetaY) = K(kThetaY, kUz) = 6.0 * EIy / (L * L * by);
  K(kThetaY, kThetaY) = (4.0 + phi_y) * EIy / (L * by);
  K(kThetaX, kThetaX) = G * s.torsion_constant / L;
  return K;
}

Matrix6d CalcBeamEndCompliance(const BeamElementProperties& p) {
  const double L = p.length, E = p.youngs_modulus, G = p.shear_modulus;
  const auto& s = p.section;
  const double EIy = E * s.second_moment_y, EIz = E * s.second_moment_z;
  const double shear = p.shear_deformable ? L / (s.shear_coefficient * G * s.area) : 0.0;
  Matrix6d C = Matrix6d::Zero();
  C(kUx, kUx) = L / (E * s.area);
  C(kUy, kUy) = L * L * L / (3.0 * EIz) + shear;
  C(kUy, kThetaZ) = C(kThetaZ, kUy) = L * L / (2.0 * EIz);
  C(kThetaZ, kThetaZ) = L / EIz;
  C(kUz, kUz) = L * L * L / (3.0 * EIy) + shear;
  C(kUz, kThetaY) = C(kThetaY, kUz) = -L * L / (2.0 * EIy);
  C(kThetaY, kThetaY) = L / EIy;
  C(kThetaX, kThetaX) = L / (G * s.torsion_constant);
  return C;
}

Matrix12d CalcBeamStiffness(const BeamElementProperties& p) {
  Eigen::Matrix<double, 6, 12> B;
  B << -CalcRigidTransfer(Eigen::Vector3d(p.length, 0.0, 0.0)), Matrix6d::Identity();
  const Matrix12d K = B.transpose() * CalcBeamEndStiffness(p) * B;
  return 0.5 * (K + K.transpose());
}

Matrix12d CalcBeamConsistentMass(const BeamElementProperties& p) {
  const double L = p.length, rho = p.density;
  const auto& s = p.section;
  Matrix12d M = Matrix12d::Zero();
  const double ma = rho * s.area * L / 6.0, mt = rho * s.polar_moment() * L / 6.0;
  const int ax[2] = {kUx, kBeamNodeDofs + kUx}, tx[2] = {kThetaX, kBeamNodeDofs + kThetaX};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      M(ax[i], ax[j]) = ma * (i == j ? 2.0 : 1.0);
      M(tx[i], tx[j]) = mt * (i == j ? 2.0 : 1.0);
    }
  // x–y plane: (v, θz) with θz = +dv/dx.
  const int xy[4] = {kUy, kThetaZ, kBeamNodeDofs + kUy, kBeamNodeDofs + kThetaZ};
  Scatter(PlaneConsistentMass(rho * s.area, rho * s.second_moment_z, L, p.shear_parameter_z()),
          xy, M);
  // x–z plane: (w, θy) with θy = −dw/dx: the same matrix with the rotations' signs flipped.
  const Eigen::Vector4d flip(1.0, -1.0, 1.0, -1.0);
  const Matrix4d Mxz =
      flip.asDiagonal() *
      PlaneConsistentMass(rho * s.area, rho * s.second_moment_y, L, p.shear_parameter_y()) *
      flip.asDiagonal();
  const int xz[4] = {kUz, kThetaY, kBeamNodeDofs + kUz, kBeamNodeDofs + kThetaY};
  Scatter(Mxz, xz, M);
  return M;
}

Vector12d CalcBeamLumpedMass(const BeamElementProperties& p) {
  const double half = 0.5 * p.density * p.length;
  const auto& s = p.section;
  Vector6d end;
  end << half * s.area, half * s.area, half * s.area, half * s.polar_moment(),
      half * s.second_moment_y, half * s.second_moment_z;
  Vector12d m;
  m << end, end;
  return m;
}

Matrix6d CalcRigidTransfer(const Eigen::Vector3d& r) {
  Matrix6d G = Matrix6d::Identity();
  G.topRightCorner<3, 3>() = -Skew(r);
  return G;
}

Eigen::Matrix3d CalcBeamFrame(const Eigen::Vector3d& p_Wa, const Eigen::Vector3d& p_Wb,
                              const Eigen::Vector3d& reference_W, const std::string& what) {
  const Eigen::Vector3d d = p_Wb - p_Wa;
  const double L = d.norm();
  EMB_THROW_IF(!(L > 0.0), what << ": length: expected > 0 m, got " << L
                                << " (both ends at the same point)");
  const Eigen::Vector3d x = d / L;
  Eigen::Vector3d ref = reference_W;
  if (ref.norm() == 0.0) {
    // cos 25° ≈ 0.906: far enough from the axis for a well-conditioned projection.
    ref = std::abs(x.y()) < 0.9 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
  }
  Eigen::Vector3d y = ref - ref.dot(x) * x;
  // A reference within ~0.06° of the axis leaves too little to normalise reliably.
  EMB_THROW_IF(!(y.norm() > 1e-3 * ref.norm()),
               what << ": reference vector (" << reference_W.transpose()
                    << "): expected a direction not parallel to the beam axis ("
                    << x.transpose() << ")");
  y.normalize();
  Eigen::Matrix3d R;
  R.col(0) = x;
  R.col(1) = y;
  R.col(2) = x.cross(y);
  return R;
}

Eigen::MatrixXd RotateBlocks(const Eigen::MatrixXd& A_B, const Eigen::Matrix3d& R_WB) {
  const int n = static_cast<int>(A_B.rows());
  EMB_CHECK(n % 3 == 0 && A_B.cols() == n);
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(n, n);
  for (int k = 0; k < n; k += 3) T.block<3, 3>(k, k) = R_WB;
  return T * A_B * T.transpose();
}

}  // namespace emb
