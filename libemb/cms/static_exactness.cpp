#include "libemb/cms/static_exactness.h"

#include <Eigen/Dense>
#include <algorithm>
#include <sstream>

#include "libemb/cms/coupled_model.h"
#include "libemb/common/error.h"
#include "libemb/common/timer.h"
#include "libemb/linalg/pinned_solver.h"

namespace emb {

StaticExactness CheckStaticExactness(const Mesh& mesh, const CoupledModel& model,
                                     const ReductionBasis& basis, const Eigen::MatrixXd& Khat,
                                     const SparseMatrix& stress) {
  StaticExactness out;
  const auto& itfs = basis.interfaces;
  const int nb = static_cast<int>(itfs.size());
  if (basis.free_free || nb < 2) {
    out.note = basis.free_free ? "not run: no interfaces" : "not run: one interface (nothing "
                                                           "to load once it is held)";
    return out;
  }
  Stopwatch sw;
  const InterfacePartition& part = model.partition;
  const std::vector<int>& q_column = model.q_column;
  const SparseMatrix& Ky = model.K;
  const Eigen::MatrixXd& Ry = model.rigid;
  const int ny = model.size();
  const int nq = 6 * nb;
  auto reader = [&](int j) { return model.InterfaceReader(j); };

  // Hold an RBE2 interface if there is one: its six reference unknowns then pin the model
  // directly (K_p is the held stiffness itself); otherwise interface 0 by multipliers.
  int held = 0;
  for (int j = 0; j < nb; ++j)
    if (itfs[j].coupling == Coupling::kRbe2) {
      held = j;
      break;
    }
  std::vector<int> loaded;
  for (int j = 0; j < nb; ++j)
    if (j != held) loaded.push_back(j);
  const Eigen::MatrixXd G = reader(held);
  Eigen::MatrixXd Dout(nq - 6, ny);
  for (size_t k = 0; k < loaded.size(); ++k) Dout.middleRows(6 * k, 6) = reader(loaded[k]);
  const int nl = nq - 6;  // unit loads: the columns of Doutᵀ

  // Pinned factorisation and the support by multipliers (pinned_solver.h).
  std::vector<int> pins;
  if (q_column[held] >= 0)
    for (int r = 0; r < 6; ++r) pins.push_back(q_column[held] + r);
  else
    pins = PinUnknowns(mesh, part);
  const SparseMatrix Gs = G.sparseView();
  const PinnedConstrainedSolver solver(Ky, Ry, pins, Gs);
  ReturnFreedMemory();  // the factorisation's temporaries (K_ff, CHOLMOD's workspace)
  if (!solver.ok()) {
    out.note = "not run: " + solver.message();
    return out;
  }
  // The loads in groups of kLoadsPerSolve: the solves and their refinement hold a few dense
  // blocks of the model's size per group, not per load (at 293k DOF and 60 loads the whole
  // set of them was ~1 GB of the reduction's peak memory).
  constexpr int kLoadsPerSolve = 16;
  Eigen::MatrixXd d_full(nl, nl);
  if (stress.size() > 0) out.full_stresses.resize(stress.rows(), nl);
  for (int first = 0; first < nl; first += kLoadsPerSolve) {
    const int k = std::min(kLoadsPerSolve, nl - first);
    const Eigen::MatrixXd Y =
        solver.Solve(Dout.middleRows(first, k).transpose(), Eigen::MatrixXd::Zero(6, k));
    d_full.middleCols(first, k) = Dout * Y;
    if (stress.size() > 0) out.full_stresses.middleCols(first, k) = stress * (model.P * Y);
  }

  // Reduced: hold the six coordinates of `held`, unit loads on the other interface coordinates.
  const int nr = static_cast<int>(Khat.rows());
  std::vector<int> keep;
  for (int j : loaded)
    for (int r = 0; r < 6; ++r) keep.push_back(6 * j + r);
  for (int k = nq; k < nr; ++k) keep.push_back(k);
  Eigen::MatrixXd Kff(keep.size(), keep.size());
  for (size_t a = 0; a < keep.size(); ++a)
    for (size_t b = 0; b < keep.size(); ++b) Kff(a, b) = Khat(keep[a], keep[b]);
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(keep.size(), nl);
  E.topRows(nl).setIdentity();
  const Eigen::MatrixXd x = Kff.ldlt().solve(E);
  const Eigen::MatrixXd d_red = x.topRows(nl);
  if (stress.size() > 0) {
    out.reduced_z = Eigen::MatrixXd::Zero(nr, nl);
    for (size_t a = 0; a < keep.size(); ++a) out.reduced_z.row(keep[a]) = x.row(a);
  }

  // Rotations weigh by the part's size.
  const double L = (mesh.nodes.rowwise().maxCoeff() - mesh.nodes.rowwise().minCoeff()).norm();
  Eigen::VectorXd w = Eigen::VectorXd::Ones(nl);
  for (int k = 0; k < nl; ++k)
    if (k % 6 >= 3) w[k] = L;
  for (int k = 0; k < nl; ++k) {
    const Eigen::VectorXd a = w.cwiseProduct(d_red.col(k)), b = w.cwiseProduct(d_full.col(k));
    out.max_error = std::max(out.max_error, (a - b).norm() / b.norm());
  }
  out.run = true;
  out.num_loads = nl;
  std::ostringstream note;
  note << "'" << itfs[held].name << "' held; unit forces and moments at the " << nb - 1
       << " other interface(s)";
  out.note = note.str();
  out.seconds = sw.seconds();
  return out;
}

}  // namespace emb
