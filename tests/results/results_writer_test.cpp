// Results files: the documented HDF5 layout, rows flushed as the run goes, and an
// integrator failure that keeps every sample before it in the file; the tolerances a
// dynamic run used; a coupler's reaction at both joints; CSV channels.

#include "libemb/results/results_writer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "libemb/common/error.h"
#include "libemb/io/hdf5_file.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/results/results_reader.h"
#include "libemb/scene/scene.h"
#include "tests/support/temp_dir.h"

namespace emb::results {
namespace {

std::string TempPath(const std::string& name) {
  return testing::ProcessTempDir().File("results_" + name);
}

scene::Scene Pendulum() {
  return scene::LoadScene(std::string(EMB_SOURCE_DIR) + "/tools/scenes/pendulum.yaml");
}

TEST(ResultsWriter, LayoutAndRows) {
  scene::Scene sc = Pendulum();
  sc.analysis.t_end = 0.5;
  sc.analysis.output_step = 0.05;
  const std::string path = TempPath("layout.h5");
  const mbs::PreparedRun run = mbs::PrepareRun(sc.system, sc.analysis);
  mbs::RunResult r;
  std::vector<mbs::Sample> samples;
  {
    ResultsWriter w(path, run.system, sc.source, "dynamic");
    r = mbs::RunAnalysis(run, sc.analysis, [&](const mbs::Sample& s) {
      w.Write(s);
      samples.push_back(s);
    });
    w.Finish(r);
  }
  ASSERT_TRUE(r.ok()) << r.message;
  // The reader finds every channel where the writer put it: the last sample's position,
  // velocity and angular velocity (in W) come back bit for bit.
  const mbs::Sample& last = samples.back();
  const mbs::StateLayout& layout = run.system.layout();
  const Eigen::Matrix3d R_last =
      mbs::RotationFromQuaternion(last.q.segment<4>(layout.quaternion(1)));
  const Eigen::Vector3d w_last = R_last * last.v.segment<3>(layout.angular_velocity(1));
  for (int c = 0; c < 3; ++c) {
    const std::string xyz = std::string(1, "xyz"[c]);
    EXPECT_EQ(ReadResultsChannel(path, "rod.p." + xyz).values.back(),
              last.q[layout.position(1) + c]);
    EXPECT_EQ(ReadResultsChannel(path, "rod.v." + xyz).values.back(),
              last.v[layout.velocity(1) + c]);
    // omega in W: the reader rotates omega_B by its own quaternion-to-matrix formula: a few
    // ulps apart.
    constexpr double kRotationRoundOff = 1e-13;
    EXPECT_NEAR(ReadResultsChannel(path, "rod.omega." + xyz).values.back(), w_last[c],
                kRotationRoundOff * (1.0 + w_last.norm()));
  }
  H5File f(path, H5File::Mode::kRead);
  EXPECT_EQ(f.ReadStringAttribute("/", "format"), "emb-mbs-results");
  EXPECT_EQ(f.ReadStringAttribute("/", "status"), "success");
  EXPECT_EQ(f.Shape("/time"), (std::vector<std::uint64_t>{11}));
  EXPECT_EQ(f.Shape("/state/q"), (std::vector<std::uint64_t>{11, 7}));
  EXPECT_EQ(f.Shape("/state/v"), (std::vector<std::uint64_t>{11, 6}));
  EXPECT_EQ(f.Shape("/multipliers/lambda"), (std::vector<std::uint64_t>{11, 5}));
  EXPECT_EQ(f.Shape("/reactions/force"), (std::vector<std::uint64_t>{11, 3}));
  EXPECT_EQ(f.Shape("/energy"), (std::vector<std::uint64_t>{11, 5}));
  EXPECT_EQ(f.ReadStrings("/model/bodies"), (std::vector<std::string>{"rod"}));
  EXPECT_EQ(f.ReadStrings("/model/equations").size(), 5u);
  const auto t = f.ReadDoubles("/time");
  EXPECT_DOUBLE_EQ(t.back(), 0.5);
  EXPECT_EQ(f.ReadIntAttribute("/", "version"), 4);
  // The pendulum's hinge as a joint coordinate: the angle and its rate per sample.
  EXPECT_EQ(f.ReadStrings("/model/joints"), (std::vector<std::string>{"hinge"}));
  EXPECT_EQ(f.Shape("/joints"), (std::vector<std::uint64_t>{11, 4}));
  // The layout record of /state/q and /state/v is mbs::StateLayout's.
  const mbs::StateLayout& L = run.system.layout();
  EXPECT_EQ(f.ReadIntAttribute("/state/q", "values_per_body"), mbs::StateLayout::kQPerBody);
  EXPECT_EQ(f.ReadIntAttribute("/state/q", "quaternion_column"), L.quaternion(1) - L.position(1));
  EXPECT_EQ(f.ReadIntAttribute("/state/v", "values_per_body"), mbs::StateLayout::kVPerBody);
  EXPECT_EQ(f.ReadIntAttribute("/state/v", "angular_velocity_column"),
            L.angular_velocity(1) - L.velocity(1));
  EXPECT_EQ(f.ReadStrings("/model/reaction_ports"), (std::vector<std::string>{"hinge"}));
  EXPECT_DOUBLE_EQ(f.ReadDoubleAttribute("/", "atol"), r.atol);
  EXPECT_GT(f.ReadDoubleAttribute("/", "multiplier_atol"), 0.0);
  EXPECT_EQ(f.ReadStringAttribute("/", "linear_solver"), "dense");
  std::filesystem::remove(path);
}

TEST(ResultsWriter, IntegratorFailureKeepsEarlierSamples) {
  // A torque step to 1e9 N m at t = 0.25 s exhausts IDA's step budget (the scene says).
  const scene::Scene sc =
      scene::LoadScene(std::string(EMB_SOURCE_DIR) + "/tests/scene/data/spin_up.yaml");
  const std::string path = TempPath("failure.h5");
  const mbs::PreparedRun run = mbs::PrepareRun(sc.system, sc.analysis);
  mbs::RunResult r;
  int written = 0;
  std::vector<double> written_t, written_q0;
  {
    ResultsWriter w(path, run.system, sc.source, "dynamic");
    r = mbs::RunAnalysis(run, sc.analysis, [&](const mbs::Sample& s) {
      w.Write(s);
      ++written;
      written_t.push_back(s.t);
      written_q0.push_back(s.q[0]);
    });
    w.Finish(r);
  }
  ASSERT_FALSE(r.ok());
  // emb's behaviour, whatever way SUNDIALS gives up (its step budget, an error test or a
  // Newton failure: the kind depends on the SUNDIALS version and is not emb's to pin): a
  // failure of the integrator, reported as such, after the last good sample.
  EXPECT_EQ(r.status, mbs::RunStatus::kIntegratorFailure);
  EXPECT_NE(r.ida.status, IntegratorStatus::kSuccess) << Name(r.ida.status);
  EXPECT_GT(r.t_reached, 0.25);
  ASSERT_FALSE(written_t.empty());
  EXPECT_GE(r.t_reached, written_t.back());
  // The report names the time, the step size and the worst component.
  EXPECT_NE(r.message.find("at t = "), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("last step accepted"), std::string::npos) << r.message;
  EXPECT_EQ(r.message.find(", ,"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("body 'rod'"), std::string::npos) << r.message;
  // ... and the joint equation furthest from closing at the last accepted state.
  EXPECT_NE(r.message.find("largest constraint residual"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("revolute 'hinge'"), std::string::npos) << r.message;
  EXPECT_GT(r.ida.last_step, 0.0);
  EXPECT_GE(written, 6);  // the samples up to t = 0.25 s at least
  H5File f(path, H5File::Mode::kRead);
  EXPECT_EQ(f.ReadStringAttribute("/", "status"), "integrator-failure");
  EXPECT_EQ(f.Shape("/time")[0], static_cast<std::uint64_t>(written));
  // Every sample before the failure is in the file as it was written, and the file says
  // how far the run got and why it stopped.
  EXPECT_EQ(f.ReadDoubles("/time"), written_t);
  EXPECT_EQ(ReadResultsChannel(path, "rod.p.x").values, written_q0);
  EXPECT_DOUBLE_EQ(f.ReadDoubleAttribute("/", "t_reached"), r.t_reached);
  EXPECT_EQ(f.ReadStringAttribute("/", "message"), r.message);
  std::filesystem::remove(path);
}

TEST(ResultsWriter, FreeBodyWithoutConstraints) {
  // No joints: zero multipliers and reactions still give well-formed (empty-row) datasets.
  const scene::Scene sc = scene::ParseScene(R"(
bodies:
  - {name: ball, mass: 1.0, inertia: [0.1, 0.1, 0.1], velocity: [1, 2, 0], angular_velocity: [0, 0, 3]}
gravity: [0, 0, -9.81]
analysis: {type: dynamic, t_end: 0.5, output_step: 0.1}
)",
                                            "free.yaml");
  const std::string path = TempPath("free.h5");
  const mbs::PreparedRun run = mbs::PrepareRun(sc.system, sc.analysis);
  mbs::Sample last;
  {
    ResultsWriter w(path, run.system, sc.source, "dynamic");
    const mbs::RunResult r = mbs::RunAnalysis(run, sc.analysis, [&](const mbs::Sample& s) {
      w.Write(s);
      last = s;
    });
    ASSERT_TRUE(r.ok()) << r.message;
    w.Finish(r);
  }
  // Ballistic flight: z = -g t^2 / 2 at t = 0.5 s (BDF at the default rtol 1e-6).
  EXPECT_NEAR(last.q[2], -0.5 * 9.81 * 0.25, 1e-5);
  EXPECT_NEAR(last.q[0], 0.5, 1e-6);
  H5File f(path, H5File::Mode::kRead);
  EXPECT_EQ(f.Shape("/multipliers/lambda"), (std::vector<std::uint64_t>{6, 0}));
  EXPECT_EQ(f.Shape("/reactions/force"), (std::vector<std::uint64_t>{6, 0}));
  std::filesystem::remove(path);
}

TEST(ResultsWriter, CouplerReactionAtBothJoints) {
  // The gear pair: 2 joints, the motion and the coupler, plus the coupler's second port.
  scene::Scene sc = scene::LoadScene(std::string(EMB_SOURCE_DIR) + "/tools/scenes/gear_pair.yaml");
  sc.analysis.t_end = 0.05;
  const std::string path = TempPath("gears.h5"), csv_path = TempPath("gears.csv");
  const mbs::PreparedRun run = mbs::PrepareRun(sc.system, sc.analysis);
  {
    ResultsWriter w(path, run.system, sc.source, "kinematic");
    CsvWriter csv(csv_path, run.system, {"mesh.T.z", "mesh.T2.z"});
    w.Finish(mbs::RunAnalysis(run, sc.analysis, [&](const mbs::Sample& s) {
      w.Write(s);
      csv.Write(s);
    }));
  }
  H5File f(path, H5File::Mode::kRead);
  EXPECT_EQ(f.ReadStrings("/model/reaction_ports"),
            (std::vector<std::string>{"pinion_shaft", "wheel_shaft", "drive", "mesh",
                                      "mesh:wheel_shaft"}));
  EXPECT_EQ(f.Shape("/reactions/torque"), (std::vector<std::uint64_t>{6, 15}));
  std::ifstream in(csv_path);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "t,mesh.T.z,mesh.T2.z");
  EXPECT_THROW(CsvWriter(csv_path, run.system, {"drive.T2.z"}), InputError);  // not a coupler
  std::filesystem::remove(path);
  std::filesystem::remove(csv_path);
}

TEST(CsvWriter, ChannelsAndUnknownChannel) {
  scene::Scene sc = Pendulum();
  sc.analysis.t_end = 0.1;
  sc.analysis.output_step = 0.05;
  const std::string path = TempPath("channels.csv");
  const mbs::PreparedRun run = mbs::PrepareRun(sc.system, sc.analysis);
  {
    CsvWriter csv(path, run.system, {"rod.p.x", "hinge.F.y", "energy.total"});
    mbs::RunAnalysis(run, sc.analysis, [&](const mbs::Sample& s) { csv.Write(s); });
  }
  std::ifstream in(path);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "t,rod.p.x,hinge.F.y,energy.total");
  int lines = 0;
  for (std::string l; std::getline(in, l);) ++lines;
  EXPECT_EQ(lines, 3);
  try {
    CsvWriter bad(path, run.system, {"rod.p.q"});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace emb::results
