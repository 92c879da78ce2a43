#include "libemb/beam/beam_section.h"

#include <cmath>
#include <numbers>

#include "libemb/common/error.h"

namespace emb {
namespace {

constexpr double kPi = std::numbers::pi;

void CheckPoisson(double nu) {
  EMB_THROW_IF(!(std::isfinite(nu) && nu > -1.0 && nu < 0.5),
               "section shear coefficient: Poisson's ratio expected -1 < nu < 0.5, got " << nu);
}

void CheckPositive(const std::string& what, const char* property, const char* unit, double v) {
  EMB_THROW_IF(!(std::isfinite(v) && v > 0.0),
               what << ": section " << property << ": expected > 0 " << unit << ", got " << v);
}

}  // namespace

BeamSection MakeSolidCircleSection(double diameter, double poisson_ratio) {
  CheckPositive("solid circle section", "diameter", "m", diameter);
  return MakeHollowCircleSection(diameter, 0.0, poisson_ratio);
}

BeamSection MakeHollowCircleSection(double outer_diameter, double inner_diameter,
                                    double poisson_ratio) {
  CheckPositive("hollow circle section", "outer diameter", "m", outer_diameter);
  EMB_THROW_IF(!(std::isfinite(inner_diameter) && inner_diameter >= 0.0 &&
                 inner_diameter < outer_diameter),
               "hollow circle section: inner diameter: expected 0 <= d < D = "
                   << outer_diameter << " m, got " << inner_diameter);
  CheckPoisson(poisson_ratio);
  const double D = outer_diameter, d = inner_diameter, nu = poisson_ratio;
  BeamSection s;
  s.shape = d > 0.0 ? "hollow circle" : "solid circle";
  s.outer_diameter = D;
  s.inner_diameter = d;
  s.area = kPi * (D * D - d * d) / 4.0;
  s.second_moment_y = s.second_moment_z = kPi * (std::pow(D, 4) - std::pow(d, 4)) / 64.0;
  s.torsion_constant = 2.0 * s.second_moment_y;
  const double m = d / D, m2 = m * m, q = (1.0 + m2) * (1.0 + m2);
  s.shear_coefficient = 6.0 * (1.0 + nu) * q / ((7.0 + 6.0 * nu) * q + (20.0 + 12.0 * nu) * m2);
  return s;
}

BeamSection MakeGeneralSection(double area, double second_moment_y, double second_moment_z,
                               double torsion_constant, double shear_coefficient) {
  BeamSection s;
  s.shape = "general";
  s.area = area;
  s.second_moment_y = second_moment_y;
  s.second_moment_z = second_moment_z;
  s.torsion_constant = torsion_constant;
  s.shear_coefficient = shear_coefficient;
  ValidateSection(s, "general section");
  return s;
}

void ValidateSection(const BeamSection& s, const std::string& what) {
  CheckPositive(what, "area A", "m^2", s.area);
  CheckPositive(what, "second moment Iy", "m^4", s.second_moment_y);
  CheckPositive(what, "second moment Iz", "m^4", s.second_moment_z);
  CheckPositive(what, "torsion constant J", "m^4", s.torsion_constant);
  CheckPositive(what, "shear coefficient kappa", "(-)", s.shear_coefficient);
  EMB_THROW_IF(s.shear_coefficient > 1.0, what << ": section shear coefficient kappa: expected "
                                                  "<= 1, got " << s.shear_coefficient);
}

}  // namespace emb
