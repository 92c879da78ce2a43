#pragma once
/// @file
/// What a flexible body's elastic basis must keep of its static flexibility where it is
/// loaded: which markers can carry loads, and how far a basis's static compliance there is
/// from the full one's (the installed basis reports it, installed_basis.h; so does the error
/// indicator of a truncated free-free basis, basis_truncation.h).

#include <Eigen/Dense>
#include <vector>

#include "libemb/mbs/core/system.h"

namespace emb::mbs {

/// What can load each marker of `system` (MarkerLoad flags, force_element.h, one entry per
/// marker): the constraint kernels through their structure (a flexible marker is its own
/// virtual body, so a kernel that reads only its origin puts no moment on it: a point
/// component loads both markers with a force, a point on J's axis I with a force and J with
/// a force and a moment, an axis or angle kernel both with a moment) and the force elements'
/// ForceElement::MarkerLoads.
std::vector<unsigned> MarkerLoadsOf(const System& system);

/// The relative error of the static compliance of the coordinates xi, eta = T xi
/// (T: ne x n', full column rank), against that of eta, for the generalised load directions
/// F (ne x nf, one column per unit load: a marker's shape_t^T for its forces, shape_r^T for
/// its moments) and the stiffness K (ne x ne, symmetric positive definite):
///   C_full = F^T K^-1 F,   C_T = (T^T F)^T (T^T K T)^-1 (T^T F),
///   error  = max_ij |C_T - C_full|_ij / max_ij |C_full|_ij
/// (0 if F is empty or C_full is zero; round-off if the static responses K^-1 F are in the
/// span of T). C_T <= C_full (a basis can only stiffen). @throws NumericalError if K or
/// T^T K T is not positive definite. Cost O(ne^3 + ne^2 (n' + nf)).
double StaticComplianceError(const Eigen::MatrixXd& K, const Eigen::MatrixXd& F,
                             const Eigen::MatrixXd& T);

}  // namespace emb::mbs
