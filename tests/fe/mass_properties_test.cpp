// Mass properties of meshed solids against closed forms.

#include "libemb/fe/mass_properties.h"

#include <gtest/gtest.h>

#include "libemb/common/error.h"
#include "libemb/mesh/box_mesh.h"

namespace emb {
namespace {

// Straight-sided cells and the mass rule: exact up to summation round-off.
constexpr double kRoundOff = 1e-12;

TEST(MassProperties, BoxIsExact) {
  const Eigen::Vector3d size(0.5, 0.2, 0.1);
  const double rho = 7850.0;
  for (CellType t : {CellType::kTet4, CellType::kTet10, CellType::kHex8, CellType::kHex20,
                     CellType::kWedge6, CellType::kWedge15}) {
    const MassProperties p = CalcMassProperties(MakeBoxMesh(size, {3, 2, 2}, t), rho);
    const double m = rho * size.prod();
    EXPECT_NEAR(p.mass, m, kRoundOff * m) << Name(t);
    EXPECT_LE((p.center_of_mass - size / 2).norm(), kRoundOff) << Name(t);
    const Eigen::Vector3d s2 = size.cwiseProduct(size);
    const Eigen::Vector3d I(m * (s2.y() + s2.z()) / 12, m * (s2.x() + s2.z()) / 12,
                            m * (s2.x() + s2.y()) / 12);
    EXPECT_LE((p.inertia_about_com - Eigen::Matrix3d(I.asDiagonal())).cwiseAbs().maxCoeff(),
              kRoundOff * I.maxCoeff())
        << Name(t);
  }
}

TEST(MassProperties, RejectsBadDensity) {
  EXPECT_THROW(CalcMassProperties(MakeBoxMesh({1, 1, 1}, {1, 1, 1}, CellType::kHex8), 0.0),
               InputError);
}

}  // namespace
}  // namespace emb
