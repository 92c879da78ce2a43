// The whole-surface stress field as a user meets it (issue 17): `emb reduce --stress-surface`
// stores the surface's modal stresses; `emb run` with `surface_field_times` writes the field on
// the whole surface (faces, von Mises, sigma_1, signed von Mises, components) beside the
// results, whose values at a group's nodes reproduce that group's hot-spot channels; a body
// file without surface stresses is refused naming the file and the option.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "libemb/io/hdf5_file.h"
#include "tests/support/cli_fixture.h"
#include "tests/support/clamped_bar_scene.h"

namespace {

namespace fs = std::filesystem;
using emb::test::CliResult;

// The hot-spot channel and the surface field evaluate the same rows of the modal stresses at
// the same eta, the surface's stored as float32 (2^-24 relative per entry); at the hot spot
// the modes' contributions do not cancel much, so allow 16 times that.
constexpr double kFloat32Rows = 1e-6;  // relative to the channel's value

class EmbStressSurfaceCli : public emb::test::CliTest {
 protected:
  static emb::testing::BarSpec Bar(std::vector<std::string> groups, bool surface) {
    return emb::testing::ClampedBar(std::move(groups), surface);
  }
  void WriteScene(const std::string& name, const emb::testing::BarSpec& bar,
                  const std::string& stress_outputs,
                  const std::string& direction = "[0, 0.6, 0.8]",
                  const std::string& load = "{harmonic: {amplitude: 500, frequency_hz: 200, offset: 500}}",
                  const std::string& analysis = "{type: dynamic, t_end: 0.02, output_step: 2.5e-4}") const {
    std::ofstream(dir_ / name)
        << emb::testing::ClampedBarScene(bar, stress_outputs, direction, load, analysis);
  }
};

TEST_F(EmbStressSurfaceCli, SurfaceFieldMatchesTheHotSpotChannels) {
  const auto bar = Bar({"z1", "y0"}, true);
  WriteScene("surf.yaml", bar,
             "  - name: s\n    body: bar\n    field_times: [0.01]\n"
             "    surface_field_times: [0.0101, 0.02]\n");
  const CliResult r = Run("run -q --json surf.yaml -o surf.h5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  emb::H5File res((dir_ / "surf.h5").string(), emb::H5File::Mode::kRead);
  const auto channels = res.ReadStrings("/model/output_point_channels");
  const std::vector<double> values = res.ReadDoubles("/output_points");
  const std::vector<double> time = res.ReadDoubles("/time");
  const std::size_t width = channels.size();
  ASSERT_EQ(values.size(), width * time.size());

  emb::H5File f((dir_ / "surf.stress.h5").string(), emb::H5File::Mode::kRead);
  const std::vector<int> nodes = f.ReadInts("/s/surface/nodes");
  const std::uint64_t s = nodes.size();
  const std::vector<double> times = f.ReadDoubles("/s/surface/times");
  ASSERT_EQ(times.size(), 2u);
  EXPECT_EQ(f.Shape("/s/surface/coordinates"), (std::vector<std::uint64_t>{s, 3}));
  EXPECT_EQ(f.Shape("/s/surface/stress"), (std::vector<std::uint64_t>{2, s, 6}));
  for (const char* m : {"von_mises", "max_principal", "signed_von_mises"})
    EXPECT_EQ(f.Shape(std::string("/s/surface/") + m), (std::vector<std::uint64_t>{2, s}));
  // The bar's boundary: one Quad8 per grid square, 2 (12·2 + 2·2 + 2·12) = 104; the groups'
  // fields carry their faces too (z1: 12·2, y0: 12·2).
  EXPECT_EQ(f.Shape("/s/surface/faces/Quad8"), (std::vector<std::uint64_t>{104, 8}));
  EXPECT_EQ(f.Shape("/s/z1/faces/Quad8"), (std::vector<std::uint64_t>{24, 8}));
  EXPECT_EQ(f.Shape("/s/y0/faces/Quad8"), (std::vector<std::uint64_t>{24, 8}));
  const std::vector<double> vm = f.ReadDoubles("/s/surface/von_mises");
  const std::vector<double> p1 = f.ReadDoubles("/s/surface/max_principal");
  for (std::size_t k = 0; k < times.size(); ++k) {
    // The field is the first sample at or after its time: that sample of the results.
    const auto row = std::find(time.begin(), time.end(), times[k]);
    ASSERT_TRUE(row != time.end()) << "field time " << times[k] << " is no sample time";
    EXPECT_GE(times[k], k == 0 ? 0.0101 : 0.02);
    const std::size_t i = static_cast<std::size_t>(row - time.begin());
    for (const std::string g : {"z1", "y0"}) {
      const auto at = [&](const std::string& c) {
        const auto it = std::find(channels.begin(), channels.end(), "s." + g + "." + c);
        EXPECT_TRUE(it != channels.end()) << c;
        return values[i * width + static_cast<std::size_t>(it - channels.begin())];
      };
      const std::vector<int> group = f.ReadInts("/s/" + g + "/nodes");
      double vm_max = 0.0, p1_max = -1e300;
      for (int node : group) {
        const auto it = std::lower_bound(nodes.begin(), nodes.end(), node);
        ASSERT_TRUE(it != nodes.end() && *it == node) << g << " node " << node;
        const std::size_t j = k * s + static_cast<std::size_t>(it - nodes.begin());
        vm_max = std::max(vm_max, vm[j]);
        p1_max = std::max(p1_max, p1[j]);
      }
      const double channel_vm = at("von_mises"), channel_p1 = at("max_principal");
      ASSERT_GT(channel_vm, 0.0);
      EXPECT_NEAR(vm_max, channel_vm, kFloat32Rows * channel_vm) << g << " at t = " << times[k];
      EXPECT_NEAR(p1_max, channel_p1, kFloat32Rows * std::abs(channel_vm)) << g;
    }
  }
  std::ifstream xdmf(dir_ / "surf.stress.xdmf");
  const std::string text((std::istreambuf_iterator<char>(xdmf)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("TopologyType=\"Quad_8\""), std::string::npos);
  EXPECT_NE(text.find("surf.stress.h5:/s/surface/faces/Quad8"), std::string::npos);
  EXPECT_NE(text.find("Name=\"signed_von_mises\""), std::string::npos);
}

// Static tip load F along z: sigma_xx on the top and bottom faces at mid-length is beam
// theory's -+F (L - x) h / (2 I) (emb_stress_cli_test asserts 1 % through the group channels;
// here through the surface field, an independent route to the same nodes).
TEST_F(EmbStressSurfaceCli, StaticSurfaceFieldMatchesBeamTheory) {
  constexpr double kBeamTolerance = 0.01;
  const auto bar = Bar({}, true);
  WriteScene("static.yaml", bar, "  - {name: s, body: bar, surface_field_times: [0]}\n",
             "[0, 0, 1]", "{constant: 100}", "{type: static}");
  const CliResult r = Run("run -q static.yaml -o static.h5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  emb::H5File f((dir_ / "static.stress.h5").string(), emb::H5File::Mode::kRead);
  const std::vector<double> xyz = f.ReadDoubles("/s/surface/coordinates");
  const std::vector<double> sigma = f.ReadDoubles("/s/surface/stress");  // (1, s, 6)
  const double I = bar.width * std::pow(bar.height, 3) / 12.0;
  const double beam = 100.0 * (bar.length / 2) * bar.height / (2.0 * I);
  int checked = 0;
  for (std::size_t i = 0; i < xyz.size() / 3; ++i) {
    if (std::abs(xyz[3 * i] - bar.length / 2) > 1e-9 || std::abs(xyz[3 * i + 1] - bar.width / 2) > 1e-9)
      continue;
    const double z = xyz[3 * i + 2];
    if (std::abs(z) > 1e-9 && std::abs(z - bar.height) > 1e-9) continue;
    const double expected = z > 0 ? -beam : beam;  // top in compression
    EXPECT_NEAR(sigma[6 * i], expected, kBeamTolerance * beam) << "z = " << z;
    ++checked;
  }
  EXPECT_EQ(checked, 2);  // the top and bottom nodes at mid-length, mid-width
}

// A body file with the surface only (no group): the field is written, the probe has no
// channels; asking it for a group names what the file lacks.
TEST_F(EmbStressSurfaceCli, SurfaceOnlyBodyFile) {
  const auto bar = Bar({}, true);
  WriteScene("only.yaml", bar, "  - {name: s, body: bar, surface_field_times: [0.005]}\n");
  const CliResult r = Run("run -q only.yaml -o only.h5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  emb::H5File f((dir_ / "only.stress.h5").string(), emb::H5File::Mode::kRead);
  EXPECT_EQ(f.Shape("/s/surface/times")[0], 1u);
  WriteScene("group.yaml", bar,
             "  - {name: s, body: bar, groups: [z1], surface_field_times: [0.005]}\n");
  ExpectFailure("run group.yaml -o group.h5", 1, {"no modal stresses at groups", "--stress-groups"});
}

TEST_F(EmbStressSurfaceCli, SurfaceFieldFromAFileWithoutSurfaceIsRefused) {
  const auto bar = Bar({"z1"}, false);
  WriteScene("nosurf.yaml", bar, "  - {name: s, body: bar, surface_field_times: [0.01]}\n");
  ExpectFailure("run nosurf.yaml -o nosurf.h5", 1,
                {emb::testing::FlexibleBarFile(bar), "no modal stresses on the whole surface",
                 "--stress-surface"});
  EXPECT_FALSE(fs::exists(dir_ / "nosurf.h5"));
  WriteScene("nan.yaml", bar, "  - {name: s, body: bar, surface_field_times: [.nan]}\n");
  ExpectFailure("run nan.yaml -o nan.h5", 1, {"surface_field_times", "expected a number"});
}

}  // namespace
