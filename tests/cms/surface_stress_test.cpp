// Modal stresses on the whole boundary surface (cms/surface_stress.h): the surface of a Hex20
// bar against the closed form (faces, nodes on the box boundary), its modal stresses at the
// nodes of named groups against those groups' own modal stresses, the body file round trip
// with its digest (modal stresses as float32; version 4; a changed entry or a removed surface refused; a file without
// the surface keeps its older version).

#include "libemb/cms/surface_stress.h"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "libemb/cms/body_file.h"
#include "libemb/cms/reduction.h"
#include "libemb/common/error.h"
#include "libemb/fe/assembly.h"
#include "libemb/io/hdf5_file.h"
#include "libemb/mesh/box_mesh.h"
#include "tests/support/h5_edit.h"
#include "tests/support/temp_dir.h"

namespace emb {
namespace {

// The group and the surface rows of one node come from the same nodal average over the same
// cells, summed in the same order: equal up to the round-off of the sparse-dense product.
constexpr double kRoundOff = 1e-12;  // relative to the largest modal stress

// float32 rounds each entry to 2^-24 of itself (round to nearest: half an ulp).
constexpr double kFloat32 = 6.0e-8;

const Eigen::Vector3d kSize{0.6, 0.06, 0.04};  // [m]
const Eigen::Vector3i kCells{6, 2, 1};

struct Bar {
  Mesh mesh;
  ReducedBody body;
  explicit Bar(bool surface)
      : mesh(MakeBoxMesh(kSize, kCells, CellType::kHex20)) {
    const SystemMatrices sys = AssembleSystem(mesh, IsotropicMaterial{});
    ReductionJob job;
    job.interfaces = {InterfaceSpec::Parse("x0:rbe2"), InterfaceSpec::Parse("x1:rbe2")};
    job.reduction.selection.count = 4;
    job.certificate.reference = false;
    job.geometric_stiffness = false;
    job.keep_mesh_shapes = false;
    job.stress_groups = {"z1", "y0"};
    job.stress_surface = surface;
    body = ReduceBody(mesh, sys, IsotropicMaterial{}, job);
  }
};

const Bar& SurfaceBar() {
  static const Bar bar(true);
  return bar;
}

TEST(SurfaceStress, SurfaceOfTheBarIsItsBoundary) {
  const Bar& bar = SurfaceBar();
  const ModalStressSurface& s = bar.body.stress_surface;
  ASSERT_FALSE(s.empty());
  // Hex20: one Quad8 per boundary square, 2 (6·2 + 2·1 + 1·6) = 40.
  ASSERT_EQ(s.faces.size(), 1u);
  EXPECT_EQ(s.faces[0].type, CellType::kQuad8);
  EXPECT_EQ(s.num_faces(), 2 * (kCells.x() * kCells.y() + kCells.y() * kCells.z() +
                                kCells.z() * kCells.x()));
  const int ne = static_cast<int>(bar.body.modes.frequencies_hz.size());
  EXPECT_EQ(s.stresses.rows(), 6 * s.num_nodes());
  EXPECT_EQ(s.stresses.cols(), ne);
  for (int i = 0; i < s.num_nodes(); ++i) {
    const Eigen::Vector3d p = s.coordinates.row(i).transpose();
    EXPECT_EQ((p - bar.mesh.nodes.col(s.nodes[static_cast<std::size_t>(i)])).norm(), 0.0);
    const bool on_boundary = ((p.array().abs() < 1e-12) || ((p - kSize).array().abs() < 1e-12)).any();
    EXPECT_TRUE(on_boundary) << "surface node " << i << " at " << p.transpose();
  }
}

TEST(SurfaceStress, EqualsTheGroupsModalStressesAtTheirNodes) {
  const Bar& bar = SurfaceBar();
  const ModalStressSurface& s = bar.body.stress_surface;
  const double scale = s.stresses.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0.0);
  for (const ModalStressGroup& g : bar.body.stress_groups) {
    for (int i = 0; i < g.num_nodes(); ++i) {
      const auto it = std::lower_bound(s.nodes.begin(), s.nodes.end(), g.nodes[static_cast<std::size_t>(i)]);
      ASSERT_TRUE(it != s.nodes.end() && *it == g.nodes[static_cast<std::size_t>(i)])
          << "group " << g.name << " node " << g.nodes[static_cast<std::size_t>(i)] << " not on the surface";
      const Eigen::Index k = it - s.nodes.begin();
      const double diff = (s.stresses.middleRows(6 * k, 6) - g.stresses.middleRows(6 * i, 6))
                              .cwiseAbs()
                              .maxCoeff();
      EXPECT_LE(diff, kRoundOff * scale) << g.name << " node " << i;
    }
  }
}

TEST(SurfaceStress, BodyFileRoundTripAndDigest) {
  const Bar& bar = SurfaceBar();
  BodyFileInfo info;
  info.provenance = {"test", "box", MeshHash(bar.mesh), "order=2"};
  info.interfaces = "x0:rbe2; x1:rbe2";
  const std::string path = testing::ProcessTempDir().File("surface_body.h5");
  WriteBodyFile(path, "", bar.body, info, nullptr);
  {
    const H5File f(path, H5File::Mode::kRead);
    EXPECT_EQ(f.ReadIntAttribute("/", "content_digest_version"), 4);
    EXPECT_EQ(f.ReadStrings("/stress/surface/face_types"), std::vector<std::string>{"Quad8"});
    EXPECT_EQ(f.Shape("/stress/surface/faces/Quad8"),
              (std::vector<std::uint64_t>{static_cast<std::uint64_t>(bar.body.stress_surface.num_faces()), 8}));
  }
  const ReducedBody back = ReadBodyFile(path);
  const ModalStressSurface& a = bar.body.stress_surface;
  const ModalStressSurface& b = back.stress_surface;
  EXPECT_EQ(b.nodes, a.nodes);
  EXPECT_EQ((b.coordinates - a.coordinates).norm(), 0.0);
  // Stored as float32: read back exactly the rounded values.
  EXPECT_EQ((b.stresses - a.stresses.cast<float>().cast<double>()).norm(), 0.0);
  EXPECT_LE((b.stresses - a.stresses).cwiseAbs().maxCoeff(),
            kFloat32 * a.stresses.cwiseAbs().maxCoeff());
  ASSERT_EQ(b.faces.size(), a.faces.size());
  EXPECT_EQ(b.faces[0].connectivity, a.faces[0].connectivity);
  EXPECT_EQ(back.stress_groups.size(), 2u);
  // A changed modal stress or node position (a non-zero entry: the edit scales it), and the
  // surface removed, are refused.
  std::size_t nonzero = 0;
  while (a.coordinates(static_cast<Eigen::Index>(nonzero / 3), static_cast<Eigen::Index>(nonzero % 3)) == 0.0) ++nonzero;
  for (const auto& [dataset, entry] : {std::pair{"/stress/surface/modal", std::size_t{7}},
                                       std::pair{"/stress/surface/coordinates", nonzero}}) {
    const std::string changed = testing::ProcessTempDir().File("surface_changed.h5");
    std::filesystem::copy_file(path, changed, std::filesystem::copy_options::overwrite_existing);
    ChangeOneEntry(changed, dataset, entry, 1.0 + 1e-6);  // above float32's rounding
    EXPECT_THROW(ReadBodyFile(changed), InputError) << dataset;
  }
  const std::string removed = testing::ProcessTempDir().File("surface_removed.h5");
  std::filesystem::copy_file(path, removed, std::filesystem::copy_options::overwrite_existing);
  {
    const hid_t file = H5Fopen(removed.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    ASSERT_GE(H5Ldelete(file, "/stress/surface", H5P_DEFAULT), 0);
    H5Fclose(file);
  }
  try {
    ReadBodyFile(removed);
    FAIL() << "a body file stripped of its surface stresses was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/stress/surface"), std::string::npos) << e.what();
  }
}

// Without --stress-surface the file is what it was before (digest version 3 with groups).
TEST(SurfaceStress, FileWithoutSurfaceKeepsItsVersion) {
  const Bar bar(false);
  EXPECT_TRUE(bar.body.stress_surface.empty());
  BodyFileInfo info;
  info.provenance = {"test", "box", MeshHash(bar.mesh), "order=2"};
  const std::string path = testing::ProcessTempDir().File("groups_body.h5");
  WriteBodyFile(path, "", bar.body, info, nullptr);
  const H5File f(path, H5File::Mode::kRead);
  EXPECT_EQ(f.ReadIntAttribute("/", "content_digest_version"), 3);
  EXPECT_FALSE(f.Exists("/stress/surface"));
  EXPECT_TRUE(ReadBodyFile(path).stress_surface.empty());
}

}  // namespace
}  // namespace emb
