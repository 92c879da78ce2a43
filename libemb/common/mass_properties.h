#pragma once
/// @file
/// Rigid-body mass properties and the parallel-axis theorem: the one place where emb moves
/// an inertia tensor between points or adds bodies together.
///
/// For a body of mass m with centre of mass C and inertia I_C about C, and a point O with
/// d = p_C − p_O (same axes),
///   I_O = I_C + m (|d|² 1 − d dᵀ)                                   (parallel axes)
/// and the inertia tensor follows from the second moment J = ∫ρ r rᵀ about the same point as
///   I = tr(J) 1 − J.
/// Units: kg, m, kg·m² (any consistent set).

#include <Eigen/Core>
#include <vector>

namespace emb {

struct MassProperties {
  double volume{0.0};                                          ///< [m³]; 0 if not known
  double mass{0.0};                                            ///< [kg]
  Eigen::Vector3d center_of_mass{Eigen::Vector3d::Zero()};     ///< [m]
  Eigen::Matrix3d inertia_about_com{Eigen::Matrix3d::Zero()};  ///< [kg·m²]

  /// Inertia about point p_O (same axes): I_C + ParallelAxisTerm(m, c − p_O).
  Eigen::Matrix3d InertiaAbout(const Eigen::Vector3d& p_O) const;
};

/// m (|d|² 1 − d dᵀ): the parallel-axis term that takes an inertia about the centre of mass
/// to a point at −d from it (d = p_C − p_O).
Eigen::Matrix3d ParallelAxisTerm(double mass, const Eigen::Vector3d& d);

/// tr(J) 1 − J: the inertia tensor of a second moment J = ∫ρ r rᵀ (about the same point).
Eigen::Matrix3d InertiaFromSecondMoment(const Eigen::Matrix3d& J);

/// Several bodies as one: Add each (mass, centre of mass, inertia about it), then Result()
/// gives the total mass, the common centre of mass c = Σ m_i c_i / m and
/// I_c = Σ (I_i + ParallelAxisTerm(m_i, c_i − c)), summed about c itself (no cancellation
/// of large terms about a distant origin). Cost O(bodies).
class MassPropertiesSum {
 public:
  void Add(double mass, const Eigen::Vector3d& center_of_mass,
           const Eigen::Matrix3d& inertia_about_com, double volume = 0.0);
  void Add(const MassProperties& p) {
    Add(p.mass, p.center_of_mass, p.inertia_about_com, p.volume);
  }
  double mass() const { return mass_; }
  /// The sum; with zero total mass the centre and inertia are zero.
  MassProperties Result() const;

 private:
  std::vector<MassProperties> parts_;
  double mass_{0.0};
};

/// Mass properties from a 6 × 6 rigid-body mass matrix about the origin O,
///   M_rr = [ m 1      −m [c×]
///            m [c×]    I_O    ],
/// whose columns are the translations x, y, z and the rotations about x, y, z through O
/// (e.g. R̃ᵀ M R̃ of a finite-element or beam model). m is the mean of the translational
/// diagonal, c is read from the skew blocks (averaged) and I_c = I_O − ParallelAxisTerm(m, c).
/// A non-positive m gives zero centre and inertia. No volume.
MassProperties MassPropertiesFromRigidMass(const Eigen::Matrix<double, 6, 6>& M_rr);

}  // namespace emb
