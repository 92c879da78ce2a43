#pragma once
/// @file
/// Modal stresses on the whole boundary surface of a part (issue 17): the field an engineer
/// opens in ParaView to find the hot spots before choosing stress groups (modal_stress.h).
///
/// The surface is mesh/boundary_surface.h's (faces of one cell; quadratic faces kept), its
/// modal stresses Σ_s = S_s Φ with S_s the nodal-averaged stress operator at its nodes
/// (fe/nodal_stress.h) — the same rows a stress group holding the same node gets, so a
/// group's stresses are a subset of the surface's.
///
/// Body file (optional, inside /stress; present → @content_digest_version 4):
///   /stress/surface        @units "Pa per unit elastic coordinate"
///     face_types           (t strings) e.g. "Tri6"; the face blocks below, in this order
///     nodes                (s) 0-based mesh nodes, ascending
///     coordinates          (s, 3) their positions [m, mesh axes]
///     faces/<Type>         (f, k) 0-based indices into `nodes`, gmsh face order (= XDMF's)
///     modal                (6 s, ne) Σ_s, row 6 i + c = component c (xx yy zz xy yz zx)
///                          at nodes[i] per unit elastic coordinate [Pa]; stored as float32
///                          (@precision): half the size of doubles for a relative rounding
///                          of 2⁻²⁴ per entry, far below the nodal recovery's mesh error
///                          (benchmarks/stress_surface.sh measures it on the crank's fields)

#include <vector>

#include <Eigen/Core>

#include "libemb/fe/material.h"
#include "libemb/mesh/mesh.h"

namespace emb {

namespace body_codec {
class Codec;
}

/// The modal stresses on the boundary surface of a part (file comment).
struct ModalStressSurface {
  std::vector<int> nodes;         ///< mesh nodes, ascending (s)
  Eigen::MatrixXd coordinates;    ///< s × 3 [m]
  std::vector<CellBlock> faces;   ///< connectivity into `nodes`; tags = face numbers
  Eigen::MatrixXd stresses;       ///< 6 s × ne [Pa per unit ξ]; from a file: float32 values
  bool empty() const { return nodes.empty(); }
  int num_nodes() const { return static_cast<int>(nodes.size()); }
  int num_faces() const;
};

/// The boundary surface of `mesh` and Σ_s = S_s Φ (Φ: 3n × ne mode shapes at all nodes).
/// Cost: the face sort of ExtractBoundarySurface plus O(nnz(S_s) · ne).
/// @throws InputError for a non-manifold mesh or a Φ of the wrong size.
ModalStressSurface CalcSurfaceModalStresses(const Mesh& mesh, const IsotropicMaterial& material,
                                            const Eigen::MatrixXd& Phi);

/// Writes or reads /stress/surface through `codec` (internal to the body file, called by
/// TransferModalStresses); reading, absent → `surface` empty.
/// @throws InputError naming the file and dataset for a wrong shape, an unknown face type or
///   a face index out of range.
void TransferSurfaceStresses(body_codec::Codec& codec, ModalStressSurface& surface,
                             Eigen::Index ne);

}  // namespace emb
