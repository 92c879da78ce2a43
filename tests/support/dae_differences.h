#pragma once
// Central differences of a DAE residual: the reference for analytic iteration matrices
// dF/dy + cj dF/dy' (test support).

#include <Eigen/Dense>

#include "libemb/integrators/dae_problem.h"

namespace emb::testing {

/// d/d(eps) of F(t, y + eps e_j, y' + cj eps e_j) for every j, with step h.
inline Eigen::MatrixXd DifferenceIterationMatrix(const DaeProblem& dae, double t, double cj,
                                                 const Eigen::VectorXd& y,
                                                 const Eigen::VectorXd& yp, double h) {
  const int n = dae.size();
  Eigen::MatrixXd J(n, n);
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd yp1 = y, ym1 = y, ypp1 = yp, ypm1 = yp;
    yp1[j] += h;
    ym1[j] -= h;
    ypp1[j] += cj * h;
    ypm1[j] -= cj * h;
    Eigen::VectorXd rp(n), rm(n);
    dae.CalcResidual(t, yp1, ypp1, rp);
    dae.CalcResidual(t, ym1, ypm1, rm);
    J.col(j) = (rp - rm) / (2 * h);
  }
  return J;
}

}  // namespace emb::testing
