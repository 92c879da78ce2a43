#include "libemb/compare/station_sampling.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "libemb/common/error.h"
#include "libemb/common/skew.h"

namespace emb {
namespace {

// Nodes of `mesh` within the segment's prism around x (see the header).
std::vector<int> NodesNear(const Mesh& mesh, const GeometryPart& seg, double x, double w) {
  const double r_max = 0.5 * seg.section.outer_diameter * (1.0 + 1e-3);
  std::vector<int> out;
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const Eigen::Vector3d p = mesh.nodes.col(n);
    if (std::abs(p.x() - x) > w) continue;
    if ((p.tail<2>() - seg.axis_point_W.tail<2>()).norm() > r_max) continue;
    out.push_back(n);
  }
  return out;
}

Station MakeStation(const Mesh& mesh, const GeneratedBeamModel& beam, const GeometryPart& seg,
                    int node, double w0) {
  Station s;
  s.beam_node = node;
  s.name = beam.model.nodes()[node].name;
  s.p_W = beam.model.nodes()[node].p_W;
  s.radius = 0.5 * seg.section.outer_diameter;
  const double w_max = 0.5 * seg.length;
  double w = std::min(w0, w_max);
  for (;;) {
    s.mesh_nodes = NodesNear(mesh, seg, s.p_W.x(), w);
    if (static_cast<int>(s.mesh_nodes.size()) >= kMinStationNodes || w >= w_max) break;
    w = std::min(1.5 * w, w_max);
  }
  s.half_width = w;
  EMB_THROW_IF(static_cast<int>(s.mesh_nodes.size()) < kMinStationNodes,
               "station '" << s.name << "' at x = " << s.p_W.x() << " m: expected at least "
                           << kMinStationNodes << " mesh nodes of '" << mesh.source
                           << "' within the segment '" << seg.name << "' (radius " << s.radius
                           << " m, |dx| <= " << w << " m), got " << s.mesh_nodes.size()
                           << ": are the beam and 3-D models of the same part?");
  return s;
}

}  // namespace

std::vector<Station> MakeStations(const GeneratedBeamModel& beam, const Mesh& mesh,
                                  int axis_stations) {
  std::vector<const GeometryPart*> segments;
  for (const GeometryPart& p : beam.parts)
    if (p.kind == GeometryPart::Kind::kSegment && p.name.rfind("neck", 0) != 0)
      segments.push_back(&p);
  EMB_THROW_IF(segments.empty(), "beam model of '" << beam.source << "' has no beam segment");
  std::vector<Station> out;
  if (segments.size() == 1 && beam.parts.size() == 1) {
    EMB_THROW_IF(axis_stations < 2, "axis stations: expected at least 2, got " << axis_stations);
    const GeometryPart& seg = *segments[0];
    // The segment's nodes in order along x: element ends.
    std::vector<int> nodes;
    for (int e : seg.elements) {
      const BeamElement& el = beam.model.elements()[e];
      if (nodes.empty()) nodes.push_back(el.node_a);
      nodes.push_back(el.node_b);
    }
    const int n = static_cast<int>(nodes.size());
    const double element = seg.length / std::max(1, n - 1);
    const int count = std::min(axis_stations, n);
    for (int k = 0; k < count; ++k) {
      const int i = static_cast<int>(std::lround(static_cast<double>(k) * (n - 1) / (count - 1)));
      out.push_back(MakeStation(mesh, beam, seg, nodes[i], 0.5 * element));
    }
    return out;
  }
  for (const GeometryPart* seg : segments)
    out.push_back(MakeStation(mesh, beam, *seg, beam.model.FindNode(seg->name), 0.5 * seg->length));
  return out;
}

SampledShapes SampleMeshShapes(const Mesh& mesh, const std::vector<Station>& stations,
                               const Eigen::MatrixXd& shapes) {
  EMB_THROW_IF(shapes.rows() != 3 * mesh.num_nodes(),
               "sampling 3-D shapes: expected " << 3 * mesh.num_nodes() << " rows, got "
                                                << shapes.rows());
  const int m = static_cast<int>(shapes.cols());
  SampledShapes out;
  out.values.resize(6 * static_cast<int>(stations.size()), m);
  Eigen::VectorXd residual2 = Eigen::VectorXd::Zero(m), total2 = Eigen::VectorXd::Zero(m);
  for (size_t s = 0; s < stations.size(); ++s) {
    const Station& st = stations[s];
    const int ns = static_cast<int>(st.mesh_nodes.size());
    // Rotations scaled by R_s: the fit's unknowns are (t, θ·R_s), well scaled.
    Eigen::MatrixXd B(3 * ns, 6), U(3 * ns, m);
    for (int k = 0; k < ns; ++k) {
      const int n = st.mesh_nodes[k];
      B.block<3, 3>(3 * k, 0).setIdentity();
      B.block<3, 3>(3 * k, 3) = -Skew(mesh.nodes.col(n) - st.p_W) / st.radius;
      U.middleRows(3 * k, 3) = shapes.middleRows(3 * n, 3);
    }
    const Eigen::MatrixXd q = (B.transpose() * B).ldlt().solve(B.transpose() * U);
    out.values.middleRows(6 * static_cast<int>(s), 6) = q;
    residual2 += (U - B * q).colwise().squaredNorm().transpose();
    total2 += U.colwise().squaredNorm().transpose();
  }
  out.section_deformation.resize(m);
  for (int j = 0; j < m; ++j)
    out.section_deformation[j] = total2[j] > 0.0 ? std::sqrt(residual2[j] / total2[j]) : 0.0;
  return out;
}

SampledShapes SampleBeamShapes(const BeamModel& model, const std::vector<Station>& stations,
                               const Eigen::MatrixXd& shapes) {
  const int m = static_cast<int>(shapes.cols());
  SampledShapes out;
  out.values.resize(6 * static_cast<int>(stations.size()), m);
  for (size_t s = 0; s < stations.size(); ++s) {
    const int row = 6 * model.FindNode(stations[s].name);
    EMB_THROW_IF(row + 6 > shapes.rows(), "sampling beam shapes: station '"
                                              << stations[s].name << "' beyond the "
                                              << shapes.rows() << " rows given");
    out.values.middleRows(6 * static_cast<int>(s), 3) = shapes.middleRows(row, 3);
    out.values.middleRows(6 * static_cast<int>(s) + 3, 3) =
        stations[s].radius * shapes.middleRows(row + 3, 3);
  }
  return out;
}

}  // namespace emb
