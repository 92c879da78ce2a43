#pragma once
/// @file
/// The scratch of the GGL DAE (ggl_dae.h): everything one residual or iteration-matrix
/// evaluation computes, sized for one System and reused by every evaluation (issue 15 item
/// 3; Pinocchio's Model/Data split): the System stays immutable, an evaluation allocates
/// nothing once the workspace has been through one residual and one matrix.
///
/// Per evaluation, every body's and every marker's kinematics are computed once
/// (CalcAllMarkerKinematics) and read by the constraint kernels, the force elements and the
/// flexible-body terms; a flexible body's inertia and force terms once (CalcFlexibleTerms).

#include <Eigen/Dense>
#include <vector>

#include "libemb/common/scratch_matrices.h"
#include "libemb/integrators/matrix_assembler.h"
#include "libemb/mbs/constraints/constraint_eval.h"
#include "libemb/mbs/core/elastic_model.h"
#include "libemb/mbs/core/force_element.h"
#include "libemb/mbs/core/kinematics.h"

namespace emb::mbs {

class System;

struct GglWorkspace {
  explicit GglWorkspace(const System& system);

  ConstraintWorkspace constraint;        ///< continuous joint angles: the run's state
  std::vector<BodyKinematics> bodies;    ///< at the evaluated (q, v)
  std::vector<MarkerKinematics> markers;  ///< every marker at that state
  ConstraintEval constraints;            ///< Phi, C, ... at that state
  std::vector<FlexibleTerms> flexible;   ///< per body (used for flexible bodies only)
  Eigen::VectorXd f;                     ///< generalised forces (nv)
  /// max |f| of the last residual evaluation (GglDae::DoFollowedScale) [N, N m]
  double force_scale{0.0};
  Eigen::VectorXd w;                     ///< C^T mu (nv)
  Eigen::VectorXd reaction;              ///< C^T lambda (nv)
  Eigen::VectorXd accel;                 ///< one body's [v'_WB, omega'_B, eta''] (head 6 + ne)
  Eigen::VectorXd Ma;                    ///< one body's M(eta) accel (head 6 + ne)
  MatrixAssembler assembler;             ///< keeps the sparse structure between matrices
  /// Per body, the map from q-space to [delta p, delta pi]: X_b = d x / d q (7 -> 6).
  std::vector<Eigen::Matrix<double, 6, 7>> body_maps;
  /// Temporaries of the iteration matrix of dynamic size (flexible bodies' blocks).
  ScratchMatrices scratch;
  /// The force elements' failure channel of the current evaluation (ForceContext::Fail).
  DomainFailure failure;
};

}  // namespace emb::mbs
