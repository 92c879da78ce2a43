// A program outside emb, built against an installed emb (find_package(emb), emb::emb).
// It uses the FE and the multibody parts of the library and checks two closed forms:
//  1. the consistent mass matrix of a meshed steel box carries the box's mass rho Lx Ly Lz
//     (every translational rigid motion u = e_x: u^T M u = m);
//  2. a compound pendulum (uniform rod of length l on a revolute joint at one end, released
//     at theta0) swings with the period T = 2 pi sqrt(2 l / (3 g)) (1 + theta0^2 / 16).
// Usage: pendulum           exit code 0 if both checks pass, 1 otherwise.

#include <cmath>
#include <iostream>
#include <numbers>
#include <vector>

#include "libemb/fe/assembly.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/core/system.h"
#include "libemb/mesh/box_mesh.h"

namespace {

// Round-off of summing ~1e4 element contributions of a ~1 kg mass.
constexpr double kMassTolerance = 1e-12;
// The period from linearly interpolated zero crossings of samples T/400 apart at rtol 1e-9:
// interpolation and integration errors are ~1e-8 of T; the dropped amplitude term
// (11/3072) theta0^4 is 2e-8. 1e-6 leaves margin and still tests the theta0^2 correction
// (theta0^2 / 16 = 1.6e-4).
constexpr double kPeriodTolerance = 1e-6;

bool CheckBoxMass() {
  const Eigen::Vector3d size(0.2, 0.1, 0.05);  // [m]
  const emb::Mesh mesh = emb::MakeBoxMesh(size, Eigen::Vector3i(4, 2, 2), emb::CellType::kHex20);
  const emb::IsotropicMaterial steel;
  const emb::SystemMatrices fe = emb::AssembleSystem(mesh, steel);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(fe.num_dofs());
  for (int n = 0; n < fe.num_nodes; ++n) u[3 * n] = 1.0;
  const double m_exact = steel.density * size.prod();
  const double m_fe = u.dot(fe.M * u);
  const bool ok = std::abs(m_fe - m_exact) <= kMassTolerance * m_exact;
  std::cout << "box: " << fe.num_dofs() << " dof, u^T M u = " << m_fe << " kg, rho V = " << m_exact
            << " kg: " << (ok ? "PASSED" : "FAILED") << "\n";
  return ok;
}

bool CheckPendulumPeriod() {
  const double m = 1.0, l = 0.5, g = 9.81, theta0 = 0.04;  // [kg, m, m/s^2, rad]
  emb::mbs::System sys;
  emb::mbs::RigidBody rod;
  rod.name = "rod";
  rod.mass = m;
  rod.inertia_B = Eigen::Vector3d(1e-6, m * l * l / 12, m * l * l / 12).asDiagonal();
  // Body x along the rod, pointing down from the pivot at angle theta0.
  const double a = -std::numbers::pi / 2 + theta0;
  rod.R_WB = Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  rod.p_WB = 0.5 * l * Eigen::Vector3d(std::cos(a), std::sin(a), 0.0);
  sys.AddBody(rod);
  sys.AddMarker("pivot_ground", "ground", Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  sys.AddMarker("pivot_rod", "rod", Eigen::Vector3d(-0.5 * l, 0, 0), Eigen::Matrix3d::Identity());
  sys.AddJoint("pivot", emb::mbs::JointType::kRevolute, "pivot_rod", "pivot_ground");
  sys.SetGravity(Eigen::Vector3d(0, -g, 0));
  sys.Finalize();

  const double T = 2 * std::numbers::pi * std::sqrt(2 * l / (3 * g)) * (1 + theta0 * theta0 / 16);
  emb::mbs::AnalysisSettings s;
  s.type = emb::mbs::AnalysisType::kDynamic;
  s.t_end = 3.2 * T;
  s.output_step = T / 400;
  s.ida.rtol = 1e-9;
  s.ida.atol = 1e-11;
  const emb::mbs::PreparedRun run = emb::mbs::PrepareRun(sys, s);
  const int x = run.system.layout().position(run.system.FindBody("rod"));
  // Upward zero crossings of the CM's x (the angle's sign), linearly interpolated.
  std::vector<double> crossings;
  double t_prev = 0.0, x_prev = 0.0;
  const emb::mbs::RunResult r = emb::mbs::RunAnalysis(run, s, [&](const emb::mbs::Sample& smp) {
    const double xc = smp.q[x];
    if (smp.t > 0 && x_prev < 0 && xc >= 0)
      crossings.push_back(t_prev + (smp.t - t_prev) * (-x_prev) / (xc - x_prev));
    t_prev = smp.t;
    x_prev = xc;
  });
  if (!r.ok() || crossings.size() < 3) {
    std::cout << "pendulum: run " << emb::mbs::Name(r.status) << " " << r.message << ", "
              << crossings.size() << " crossings: FAILED\n";
    return false;
  }
  const double T_run = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  const double error = std::abs(T_run - T) / T;
  const bool ok = error <= kPeriodTolerance;
  std::cout << "pendulum: period " << T_run << " s, closed form " << T << " s, relative error "
            << error << ": " << (ok ? "PASSED" : "FAILED") << "\n";
  return ok;
}

}  // namespace

int main() {
  try {
    const bool box = CheckBoxMass();
    const bool pendulum = CheckPendulumPeriod();
    return box && pendulum ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "pendulum: " << e.what() << "\n";
    return 1;
  }
}
