#pragma once
/// @file
/// Static exactness check of a Craig–Bampton body (certificate item 5).
///
/// Interface 0 is held (its six reference coordinates zero); unit forces and moments act, one
/// at a time, on the six reference coordinates of every other interface. The interface
/// displacements are solved twice:
///  - reduced: K̂_ff x = e on the reduced coordinates without the held ones;
///  - full FE model with the same couplings: unknowns y = (interior u, RBE2 reference
///    coordinates), K_y = Pᵀ K P (P slaves the RBE2 surfaces); RBE3 loads spread as W_jᵀ F and
///    RBE3 displacements read as W_j u. Independent of the reduction's shifted factorisation,
///    the free body is pinned by six statically determinate unknowns (3-2-1 on three far
///    apart nodes): with R_y the exact rigid motions, G the support rows and K_p the pinned
///    stiffness (positive definite),
///        μ = (G R_y)⁻ᵀ R_yᵀ f,   u_p = K_p⁻¹ (f − Gᵀ μ),   y = u_p − R_y (G R_y)⁻¹ G u_p.
/// The error of a load case is ‖d_red − d_full‖ / ‖d_full‖ with rotations scaled by the part's
/// size L (so metres and radians weigh alike).

#include <string>

#include <Eigen/Core>

#include "libemb/cms/coupled_model.h"
#include "libemb/cms/craig_bampton.h"

namespace emb {

struct StaticExactness {
  bool run{false};
  std::string note;   ///< support and loads, or why it was not run
  int num_loads{0};
  double max_error{0.0};
  double seconds{0.0};
  /// With a stress operator S (6 m × 3n) given: S u_full of every load case (6 m × loads)
  /// and the reduced solutions z (nr × loads, the held coordinates zero), for
  /// CheckModalStresses (modal_stress.h).
  Eigen::MatrixXd full_stresses, reduced_z;
};

/// @param model  BuildCoupledModel(mesh, sys, basis.interfaces)
/// @param stress  optional stress operator (empty: none), see StaticExactness
StaticExactness CheckStaticExactness(const Mesh& mesh, const CoupledModel& model,
                                     const ReductionBasis& basis, const Eigen::MatrixXd& Khat,
                                     const SparseMatrix& stress = SparseMatrix());

}  // namespace emb
