#include "libemb/cms/interface_partition.h"

#include <Eigen/Geometry>
#include <algorithm>

#include "libemb/common/error.h"
#include "libemb/fe/assembly.h"
#include "libemb/common/skew.h"
#include "libemb/linalg/submatrix.h"

namespace emb {

Eigen::Matrix<double, 6, 6> ReferenceRigidMotions(const Eigen::Vector3d& p) {
  Eigen::Matrix<double, 6, 6> R = Eigen::Matrix<double, 6, 6>::Identity();
  R.block<3, 3>(0, 3) = -Skew(p);  // t = t0 + θ0 × p = t0 − [p]× θ0
  return R;
}

InterfacePartition PartitionByInterfaces(const Mesh& mesh, const std::vector<Interface>& interfaces) {
  InterfacePartition part;
  const int N = 3 * mesh.num_nodes();
  const int nb = static_cast<int>(interfaces.size());
  int num_rbe3 = 0;
  for (const auto& itf : interfaces) {
    part.rbe3_row.push_back(itf.coupling == Coupling::kRbe3 ? 6 * num_rbe3++ : -1);
    if (itf.coupling == Coupling::kRbe3) continue;
    for (int s : itf.nodes)
      for (int c = 0; c < 3; ++c) part.slaved.push_back(Dof(s, c));
  }
  std::sort(part.slaved.begin(), part.slaved.end());
  part.interior = Complement(part.slaved, N);
  part.interior_position.assign(N, -1);
  for (size_t k = 0; k < part.interior.size(); ++k) part.interior_position[part.interior[k]] = k;
  std::vector<int> slave_position(N, -1);
  for (size_t k = 0; k < part.slaved.size(); ++k) slave_position[part.slaved[k]] = k;

  part.TS = Eigen::MatrixXd::Zero(part.slaved.size(), 6 * nb);
  part.Q = Eigen::MatrixXd::Zero(6 * num_rbe3, 6 * nb);
  std::vector<Eigen::Triplet<double>> ct;
  for (int j = 0; j < nb; ++j) {
    const Interface& itf = interfaces[j];
    if (itf.coupling == Coupling::kRbe2) {
      for (int s : itf.nodes) {
        const auto B = itf.RigidMap(mesh.nodes.col(s));
        for (int c = 0; c < 3; ++c) part.TS.block(slave_position[Dof(s, c)], 6 * j, 1, 6) = B.row(c);
      }
      continue;
    }
    const Eigen::MatrixXd W = itf.AveragingOperator(mesh);
    const int row = part.rbe3_row[j];
    for (size_t s = 0; s < itf.nodes.size(); ++s)
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 6; ++r)
          if (W(r, 3 * s + c) != 0.0)
            ct.emplace_back(row + r, part.interior_position[Dof(itf.nodes[s], c)], W(r, 3 * s + c));
    part.Q.block(row, 6 * j, 6, 6).setIdentity();
  }
  part.C.resize(6 * num_rbe3, part.interior.size());
  part.C.setFromTriplets(ct.begin(), ct.end());
  part.C.makeCompressed();
  return part;
}

// Six interior unknowns that hold the rigid motions statically determinately:
// node A (x, y, z), node B (the two directions least aligned with AB), node C (the direction
// most aligned with the normal of ABC); A, B, C far apart among the interior nodes.
std::vector<int> PinUnknowns(const Mesh& mesh, const InterfacePartition& part) {
  std::vector<int> nodes;  // nodes whose three unknowns are all interior
  for (int i = 0; i < mesh.num_nodes(); ++i)
    if (part.interior_position[Dof(i, 0)] >= 0) nodes.push_back(i);
  EMB_CHECK(nodes.size() >= 3);
  auto x = [&](int i) { return Eigen::Vector3d(mesh.nodes.col(i)); };
  const Eigen::Vector3d centre = mesh.nodes.rowwise().mean();
  auto farthest = [&](auto distance) {
    return *std::max_element(nodes.begin(), nodes.end(),
                             [&](int a, int b) { return distance(a) < distance(b); });
  };
  const int A = farthest([&](int i) { return (x(i) - centre).squaredNorm(); });
  const int B = farthest([&](int i) { return (x(i) - x(A)).squaredNorm(); });
  const Eigen::Vector3d ab = (x(B) - x(A)).normalized();
  const int C = farthest([&](int i) { return (x(i) - x(A)).cross(ab).squaredNorm(); });
  const Eigen::Vector3d normal = ab.cross(x(C) - x(A)).normalized();
  int along;
  ab.cwiseAbs().maxCoeff(&along);
  int across;
  normal.cwiseAbs().maxCoeff(&across);
  std::vector<int> pins;
  for (int c = 0; c < 3; ++c) pins.push_back(part.interior_position[Dof(A, c)]);
  for (int c = 0; c < 3; ++c)
    if (c != along) pins.push_back(part.interior_position[Dof(B, c)]);
  pins.push_back(part.interior_position[Dof(C, across)]);
  std::sort(pins.begin(), pins.end());
  return pins;
}

}  // namespace emb
