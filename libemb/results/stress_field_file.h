#pragma once
/// @file
/// Stress fields at chosen times on sets of mesh nodes (stress groups, or the whole surface of
/// a part), as HDF5 with an XDMF file beside it for ParaView (issue 17; written by `emb run`
/// for a scene's stress_outputs, stress_recorder.h).
///
/// HDF5 ("emb.stress_fields"), per field F (e.g. "/fillets/journal_fillet_2",
/// "/fillets/surface") with m nodes and k times:
///   F/nodes (m) 0-based mesh nodes, F/coordinates (m, 3) [m, mesh axes], F/times (k) [s],
///   F/stress (k, m, 6) [Pa, Voigt xx yy zz xy yz zx, mesh axes],
///   F/von_mises, F/max_principal (σ1), F/signed_von_mises (k, m) [Pa] (fe/stress_measures.h),
///   F/faces/<Type> (f, n) 0-based indices into F/nodes, gmsh face order (= XDMF's), for
///   Type in Tri3, Tri6, Quad4, Quad8 — absent for a field without faces.
/// XDMF: per field a temporal collection; per time a uniform grid per face type (a spatial
/// collection of them when there are several) with topology Triangle, Tri_6, Quadrilateral or
/// Quad_8 — ParaView shows a coloured surface — or, without faces, a Polyvertex grid (shown
/// by the "Point Gaussian" representation); node attributes von_mises, max_principal,
/// signed_von_mises (Scalar) and stress (Tensor6).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "libemb/mesh/mesh.h"

namespace emb::results {

/// One field: where its nodes are and the stress at each of its times.
struct NodalStressField {
  std::string path;                     ///< HDF5 group, e.g. "/fillets/surface"
  std::string title;                    ///< XDMF grid name, e.g. "fillets.surface"
  std::vector<int> nodes;               ///< m mesh nodes
  Eigen::MatrixXd coordinates;          ///< m × 3 [m]
  std::vector<CellBlock> faces;         ///< surface faces, indices into `nodes` (may be empty)
  std::vector<double> times;            ///< k times [s]
  std::vector<Eigen::MatrixXd> stress;  ///< k matrices 6 × m [Pa]
};

/// Writes `fields` (those with at least one time) to `h5_path` and the XDMF to `xdmf_path`,
/// both atomically (temp + rename; both complete before either takes its name).
/// @throws InputError naming the file if it cannot be written; a face index or a stress
///   matrix that does not fit the field's nodes is a precondition violation (EMB_CHECK).
void WriteStressFields(const std::string& h5_path, const std::string& xdmf_path,
                       const std::vector<NodalStressField>& fields);

}  // namespace emb::results
