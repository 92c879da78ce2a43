// Body file: HDF5 round trip bit for bit, a tampered file refused, a stale basis refused.

#include "libemb/cms/body_file.h"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <tuple>

#include "libemb/common/error.h"
#include "libemb/fe/assembly.h"
#include "libemb/mesh/box_mesh.h"
#include "tests/support/h5_edit.h"
#include "tests/support/temp_dir.h"

namespace emb {
namespace {

struct Fixture {
  Mesh mesh = MakeBoxMesh({0.6, 0.06, 0.04}, {6, 1, 1}, CellType::kHex20);
  SystemMatrices sys = AssembleSystem(mesh, IsotropicMaterial{});
  ReducedBody body;
  BodyFileInfo info;
  Fixture() {
    ReductionJob job;
    job.interfaces = {InterfaceSpec::Parse("x0:rbe2"), InterfaceSpec::Parse("x1:rbe3")};
    job.reduction.selection.count = 4;
    job.certificate.reference = false;
    body = ReduceBody(mesh, sys, IsotropicMaterial{}, job);
    info.provenance = {"test", "box", sys.mesh_hash, "order=2"};
    info.interfaces = "x0:rbe2; x1:rbe3";
    info.selection = job.reduction.selection.Describe();
  }
};

std::string TempPath(const std::string& name) {
  return testing::ProcessTempDir().File("body_" + name);
}

template <typename A, typename B>
bool Identical(const A& a, const B& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

TEST(BodyFile, RoundTripsBitForBit) {
  const Fixture f;
  const std::string path = TempPath("roundtrip.h5");
  WriteBodyFile(path, "", f.body, f.info, &f.mesh);
  BodyFileInfo info;
  const ReducedBody b = ReadBodyFile(path, &info);
  EXPECT_TRUE(Identical(b.K, f.body.K));
  EXPECT_TRUE(Identical(b.M, f.body.M));
  EXPECT_TRUE(Identical(b.D, f.body.D));
  EXPECT_TRUE(Identical(b.modes.elastic, f.body.modes.elastic));
  EXPECT_TRUE(Identical(b.modes.frequencies_hz, f.body.modes.frequencies_hz));
  EXPECT_TRUE(Identical(b.interface_shapes, f.body.interface_shapes));
  EXPECT_TRUE(Identical(b.invariants.Ibar, f.body.invariants.Ibar));
  for (int k = 0; k < 9; ++k) EXPECT_TRUE(Identical(b.invariants.Sbar[k], f.body.invariants.Sbar[k]));
  EXPECT_EQ(b.invariants.mass, f.body.invariants.mass);
  ASSERT_EQ(b.interfaces.size(), 2u);
  EXPECT_EQ(b.interfaces[1].name, "x1");
  EXPECT_EQ(b.interfaces[1].coupling, Coupling::kRbe3);
  EXPECT_EQ(b.interfaces[1].point, f.body.interfaces[1].point);
  EXPECT_EQ(b.interfaces[1].nodes, f.body.interfaces[1].nodes);
  EXPECT_EQ(info.provenance.mesh_hash, f.sys.mesh_hash);
  EXPECT_EQ(info.material.youngs_modulus, IsotropicMaterial{}.youngs_modulus);
  EXPECT_EQ(b.damping.kind, DampingModel::Kind::kModal);
  std::filesystem::remove(path);
}

void ExpectDigestRefusal(const std::string& path) {
  try {
    ReadBodyFile(path);
    FAIL() << "a tampered file was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("content digest"), std::string::npos) << e.what();
  }
}

TEST(BodyFile, RefusesATamperedFile) {
  const Fixture f;
  const std::string path = TempPath("tampered.h5");
  for (const char* dataset : {"/reduced/K", "/geometric_stiffness/centrifugal"}) {
    SCOPED_TRACE(dataset);
    WriteBodyFile(path, "", f.body, f.info, nullptr);
    ChangeOneEntry(path, dataset, static_cast<std::size_t>(f.body.K.rows()) + 1);
    ExpectDigestRefusal(path);
  }
  std::filesystem::remove(path);
}

// Replaces the double attribute `object@name` (as an editor would: delete, create).
void ChangeAttribute(const std::string& path, const char* object, const char* name, double value) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  ASSERT_GE(H5Adelete_by_name(file, object, name, H5P_DEFAULT), 0);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr =
      H5Acreate_by_name(file, object, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT,
                        H5P_DEFAULT);
  ASSERT_GE(attr, 0);
  ASSERT_GE(H5Awrite(attr, H5T_NATIVE_DOUBLE, &value), 0);
  H5Aclose(attr);
  H5Sclose(space);
  H5Fclose(file);
}

// Issue 14: the attributes the reader uses (damping, material, counts) are covered by the
// digest too (version 2), so changing them is refused like changing a matrix entry.
TEST(BodyFile, RefusesTamperedAttributes) {
  const Fixture f;
  const std::string path = TempPath("attributes.h5");
  for (auto [object, name, value] : {std::tuple{"/damping", "ratio", 0.5},
                                     std::tuple{"/material", "density", 7851.0},
                                     std::tuple{"/provenance", "shift_hz", 1.0}}) {
    SCOPED_TRACE(std::string(object) + "@" + name);
    WriteBodyFile(path, "", f.body, f.info, nullptr);
    EXPECT_NO_THROW(ReadBodyFile(path));
    ChangeAttribute(path, object, name, value);
    ExpectDigestRefusal(path);
  }
  std::filesystem::remove(path);
}

// The stress-stiffening group round-trips bit for bit; a body without it (reduced with
// geometric_stiffness off, or a file written before the group existed: the same bytes) reads
// with present = false.
TEST(BodyFile, GeometricStiffnessRoundTripsAndIsOptional) {
  const Fixture f;
  const GeometricStiffness& g = f.body.geometric_stiffness;
  ASSERT_TRUE(g.present);
  const std::string path = TempPath("geometric.h5");
  WriteBodyFile(path, "", f.body, f.info, nullptr);
  const GeometricStiffness r = ReadBodyFile(path).geometric_stiffness;
  ASSERT_TRUE(r.present);
  for (int p = 0; p < 6; ++p) EXPECT_TRUE(Identical(r.centrifugal[p], g.centrifugal[p]));
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(Identical(r.translational[k], g.translational[k]));
  EXPECT_TRUE(Identical(r.reference_point, g.reference_point));
  EXPECT_EQ(r.support, g.support);

  ReducedBody without = f.body;
  without.geometric_stiffness = GeometricStiffness{};
  WriteBodyFile(path, "", without, f.info, nullptr);
  BodyFileInfo info;
  const ReducedBody b = ReadBodyFile(path, &info);
  EXPECT_FALSE(b.geometric_stiffness.present);
  EXPECT_TRUE(Identical(b.K, f.body.K));
  EXPECT_EQ(b.geometric_stiffness.Describe(), "none");
  std::filesystem::remove(path);
}

TEST(BodyFile, RefusesAStaleBasisAndOtherFiles) {
  const Fixture f;
  const std::string path = TempPath("stale.h5");
  WriteBodyFile(path, "", f.body, f.info, nullptr);
  BodyFileInfo info;
  ReadBodyFile(path, &info);
  EXPECT_NO_THROW(CheckBodyProvenance(path, info, f.sys.mesh_hash));
  const Mesh other = MakeBoxMesh({0.6, 0.06, 0.05}, {6, 1, 1}, CellType::kHex20);
  try {
    CheckBodyProvenance(path, info, MeshHash(other));
    FAIL() << "a stale basis was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("stale basis"), std::string::npos);
  }
  IsotropicMaterial aluminium{70e9, 0.33, 2700.0, "aluminium"};
  EXPECT_THROW(CheckBodyProvenance(path, info, f.sys.mesh_hash, &aluminium), InputError);
  EXPECT_THROW(ReadBodyFile(TempPath("missing.h5")), InputError);
  std::filesystem::remove(path);
}

// Issue 18: a body file from someone else must not make emb read other files. Each crafted
// object is added to a valid body file; the reader refuses it and names it.
class ForeignStorage : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = TempPath("foreign.h5");
    other_ = TempPath("other.h5");
    WriteBodyFile(path_, "", f_.body, f_.info, nullptr);
    // A file the crafted links point into.
    const hid_t o = H5Fcreate(other_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    const hsize_t n = 4;
    const hid_t space = H5Screate_simple(1, &n, nullptr);
    const hid_t ds = H5Dcreate2(o, "x", H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dclose(ds);
    H5Sclose(space);
    H5Fclose(o);
  }
  void TearDown() override {
    std::filesystem::remove(path_);
    std::filesystem::remove(other_);
  }
  // Expects ReadBodyFile to refuse the file with every word in the message.
  void ExpectRefusal(std::initializer_list<std::string> words) {
    try {
      ReadBodyFile(path_);
      FAIL() << "the crafted file was read";
    } catch (const InputError& e) {
      for (const auto& w : words) EXPECT_NE(std::string(e.what()).find(w), std::string::npos) << e.what();
    }
  }
  hid_t Open() { return H5Fopen(path_.c_str(), H5F_ACC_RDWR, H5P_DEFAULT); }
  Fixture f_;
  std::string path_, other_;
};

TEST_F(ForeignStorage, ExternalLinkIsRefusedByName) {
  const hid_t file = Open();
  ASSERT_GE(H5Lcreate_external(other_.c_str(), "/x", file, "/reduced/borrowed", H5P_DEFAULT,
                               H5P_DEFAULT),
            0);
  H5Fclose(file);
  ExpectRefusal({"/reduced/borrowed", "external link"});
}

TEST_F(ForeignStorage, ExternalDatasetIsRefused) {
  const hid_t file = Open();
  const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  ASSERT_GE(H5Pset_external(dcpl, "/etc/hostname", 0, 32), 0);
  const hsize_t n = 4;
  const hid_t space = H5Screate_simple(1, &n, nullptr);
  const hid_t ds = H5Dcreate2(file, "/modes/outside", H5T_IEEE_F64LE, space, H5P_DEFAULT, dcpl,
                              H5P_DEFAULT);
  ASSERT_GE(ds, 0);
  H5Dclose(ds);
  H5Sclose(space);
  H5Pclose(dcpl);
  H5Fclose(file);
  ExpectRefusal({"/modes/outside", "external files"});
}

TEST_F(ForeignStorage, VirtualDatasetIsRefused) {
  const hid_t file = Open();
  const hsize_t n = 4;
  const hid_t space = H5Screate_simple(1, &n, nullptr);
  const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  ASSERT_GE(H5Pset_virtual(dcpl, space, other_.c_str(), "/x", space), 0);
  const hid_t ds = H5Dcreate2(file, "/invariants/mapped", H5T_IEEE_F64LE, space, H5P_DEFAULT, dcpl,
                              H5P_DEFAULT);
  ASSERT_GE(ds, 0);
  H5Dclose(ds);
  H5Pclose(dcpl);
  H5Sclose(space);
  H5Fclose(file);
  ExpectRefusal({"/invariants/mapped", "virtual dataset"});
}

TEST_F(ForeignStorage, ArrayWhereOneValueBelongsIsRefusedNotOverrun) {
  // An attribute read into one double: a 1000-element array there must not be written over
  // the reader's stack.
  const hid_t file = Open();
  const hid_t obj = H5Oopen(file, "/material", H5P_DEFAULT);
  H5Adelete(obj, "density");
  const hsize_t n = 1000;
  const hid_t space = H5Screate_simple(1, &n, nullptr);
  const hid_t attr = H5Acreate2(obj, "density", H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT);
  const std::vector<double> v(n, 7850.0);
  ASSERT_GE(H5Awrite(attr, H5T_NATIVE_DOUBLE, v.data()), 0);
  H5Aclose(attr);
  H5Sclose(space);
  H5Oclose(obj);
  H5Fclose(file);
  ExpectRefusal({"/material@density", "expected a single value", "1000"});
}

TEST_F(ForeignStorage, DatasetClaimingMoreThanTheFileHoldsIsRefused) {
  // A chunked, compressed dataset of 2^40 values whose chunks were never written takes a few
  // bytes in the file; reading it would allocate 8 TB.
  const hid_t file = Open();
  H5Ldelete(file, "/reduced/K", H5P_DEFAULT);
  const hsize_t dims[2] = {hsize_t{1} << 20, hsize_t{1} << 20}, chunk[2] = {64, 64};
  const hid_t space = H5Screate_simple(2, dims, nullptr);
  const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(dcpl, 2, chunk);
  H5Pset_deflate(dcpl, 4);
  const hid_t ds =
      H5Dcreate2(file, "/reduced/K", H5T_IEEE_F64LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
  ASSERT_GE(ds, 0);
  H5Dclose(ds);
  H5Pclose(dcpl);
  H5Sclose(space);
  H5Fclose(file);
  try {
    ReadBodyFile(path_);
    FAIL() << "the crafted file was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/reduced/K"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace emb
