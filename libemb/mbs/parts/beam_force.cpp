#include "libemb/mbs/parts/beam_force.h"

#include <cmath>

#include "libemb/common/error.h"

namespace emb::mbs {
namespace {

// K_bb of eq. 1.26 after checking the beam's data, named after the element.
Bushing::Matrix6d ValidatedEndStiffness(const std::string& name,
                                        const BeamElementProperties& beam,
                                        double stiffness_damping) {
  const std::string what = "beam force '" + name + "'";
  EMB_THROW_IF(!(std::isfinite(beam.length) && beam.length > 0.0),
               what << ": length: expected > 0 m, got " << beam.length);
  EMB_THROW_IF(!(beam.youngs_modulus > 0.0 && beam.shear_modulus > 0.0),
               what << ": moduli: expected E > 0 and G > 0 Pa, got E = " << beam.youngs_modulus
                    << ", G = " << beam.shear_modulus);
  ValidateSection(beam.section, what);
  EMB_THROW_IF(!(std::isfinite(stiffness_damping) && stiffness_damping >= 0.0),
               what << ": stiffness damping beta: expected >= 0 s, got " << stiffness_damping);
  return CalcBeamEndStiffness(beam);
}

}  // namespace

BeamForce::BeamForce(std::string name, int marker_i, int marker_j,
                     const BeamElementProperties& beam, double stiffness_damping)
    : BeamForce(name, marker_i, marker_j, beam.length,
                ValidatedEndStiffness(name, beam, stiffness_damping), stiffness_damping) {}

// The bushing of J (end b) relative to I (end a): the beam frame is I's.
BeamForce::BeamForce(std::string name, int marker_i, int marker_j, double length,
                     const Matrix6d& stiffness, double stiffness_damping)
    : Bushing(std::move(name), marker_j, marker_i, stiffness, stiffness_damping * stiffness,
              length * Eigen::Vector3d::UnitX()),
      length_(length) {}

namespace {

// K = C⁻¹ after checking the link's compliance and β, named after the link.
Bushing::Matrix6d LinkStiffness(const std::string& name, const Bushing::Matrix6d& compliance,
                                double stiffness_damping) {
  const std::string what = "beam link '" + name + "'";
  EMB_THROW_IF(!(std::isfinite(stiffness_damping) && stiffness_damping >= 0.0),
               what << ": stiffness damping beta: expected >= 0 s, got " << stiffness_damping);
  const double asym = (compliance - compliance.transpose()).cwiseAbs().maxCoeff();
  const Eigen::LLT<Bushing::Matrix6d> llt(0.5 * (compliance + compliance.transpose()));
  EMB_THROW_IF(!compliance.allFinite() || asym > 1e-12 * compliance.cwiseAbs().maxCoeff() ||
                   llt.info() != Eigen::Success,
               what << ": compliance: expected a symmetric positive definite 6x6 matrix");
  const Bushing::Matrix6d K = llt.solve(Bushing::Matrix6d::Identity());
  return 0.5 * (K + K.transpose());
}

}  // namespace

// The bushing of J (node b) relative to I (node a), in I's axes.
BeamLinkForce::BeamLinkForce(std::string name, int marker_i, int marker_j,
                             const Matrix6d& compliance, const Eigen::Vector3d& free_offset,
                             double stiffness_damping)
    : Bushing(name, marker_j, marker_i, LinkStiffness(name, compliance, stiffness_damping),
              stiffness_damping * LinkStiffness(name, compliance, stiffness_damping),
              free_offset) {}

}  // namespace emb::mbs
