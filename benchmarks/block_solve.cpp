// Cost of one sparse factorisation against solves with blocks of right-hand sides, on the
// shifted FE matrix K − σM of a mesh: tells whether a block eigen-solver pays off.
// Usage: build/benchmarks/block_solve MESH [SIGMA] [--json]   (e.g. out/crank8.msh; σ default
// −39.5). Prints: unknowns, nnz(L), analyse/factorise seconds, and seconds per right-hand side
// for block sizes 1, 2, 4, 8, 16, 32; with --json as one JSON document (benchmarks/
// block_solve.sh stores it with the commit and machine in benchmarks/results/).

#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "libemb/common/timer.h"
#include "libemb/fe/assembly.h"
#include "libemb/linalg/sparse_cholesky.h"
#include "libemb/mesh/gmsh_reader.h"

int main(int argc, char** argv) {
  std::vector<std::string> args;
  bool json = false;
  for (int k = 1; k < argc; ++k) {
    if (std::string(argv[k]) == "--json")
      json = true;
    else
      args.push_back(argv[k]);
  }
  if (args.empty()) {
    std::fprintf(stderr, "usage: %s MESH [SIGMA] [--json]\n", argv[0]);
    return 2;
  }
  const double sigma = args.size() > 1 ? std::stod(args[1]) : -39.48;
  const emb::Mesh mesh = emb::ReadMesh(args[0]);
  const emb::SystemMatrices sys = emb::AssembleSystem(mesh, emb::IsotropicMaterial{});
  emb::SparseMatrix A = sys.K - sigma * sys.M;
  A.makeCompressed();
  emb::SparseCholesky chol;
  emb::Stopwatch sw;
  chol.Analyze(A);
  const double t_analyse = sw.seconds();
  sw.Restart();
  const emb::FactorInfo info = chol.Factorize(A);
  const double t_factor = sw.seconds();
  if (!info.ok()) {
    std::fprintf(stderr, "factorisation failed: %s\n", info.message.c_str());
    return 3;
  }
  if (!json)
    std::printf("unknowns %d, nnz(L) %.1fM, flops %.2e, analyse %.2f s, factorise %.2f s\n",
                sys.num_dofs(), info.nnz_factor / 1e6, info.flops, t_analyse, t_factor);
  nlohmann::json blocks = nlohmann::json::array();
  double single = 0.0;
  for (int b : {1, 2, 4, 8, 16, 32}) {
    const Eigen::MatrixXd B = Eigen::MatrixXd::Random(A.rows(), b);
    chol.Solve(B);  // warm-up: workspace allocation
    const int reps = b >= 8 ? 2 : 4;
    sw.Restart();
    for (int r = 0; r < reps; ++r) chol.Solve(B);
    const double per_rhs = sw.seconds() / (reps * b);
    if (b == 1) single = per_rhs;
    blocks.push_back({{"block", b}, {"seconds_per_rhs", per_rhs}, {"repeats", reps}});
    if (!json)
      std::printf("block %2d: %.4f s per right-hand side (%.1f x faster than single)\n", b, per_rhs,
                  single / per_rhs);
  }
  if (json)
    std::cout << nlohmann::json{{"mesh", args[0]},
                                {"sigma", sigma},
                                {"unknowns", sys.num_dofs()},
                                {"nnz_factor", info.nnz_factor},
                                {"flops", info.flops},
                                {"seconds_analyse", t_analyse},
                                {"seconds_factorise", t_factor},
                                {"blocks", blocks}}
                     .dump(1)
              << std::endl;
  return 0;
}
