//          emb Example 03 -- a driven slider-crank as a multibody DAE
//
// Build:   cmake --build build --target ex03_slider_crank          (EMB_BUILD_EXAMPLES=ON)
// Run:     build/examples/ex03_slider_crank            (600 rpm, one revolution, rtol 1e-8)
//          build/examples/ex03_slider_crank 3000 1e-6  arguments: crank speed [rpm], rtol
//
// What it computes: the crank, connecting rod and piston of a single-cylinder engine as
// rigid bodies, the crank driven at constant speed, integrated as a constrained multibody
// system (the stabilised index-2 GGL form of the equations of motion on SUNDIALS IDA).
// The model is built in C++ with the same calls a scene file makes (System: AddBody,
// AddMarker, AddJoint, AddMotion, Finalize); PrepareRun assembles it and reports its
// degrees of freedom (Gruebler-Kutzbach and the rank of the constraint Jacobian).
//
// Two physical statements are checked:
//  1. kinematics: the piston follows the closed form of the slider-crank,
//        x(a) = r cos a + sqrt(l^2 - r^2 sin^2 a),  a = omega t,
//     in position and velocity;
//  2. energy: without gravity or friction, the drive's torque does the work that changes
//     the kinetic energy: integral of T omega dt = E_kin(t) - E_kin(0). The torque is the
//     motion's reaction (the Lagrange multiplier of its equation), which the DAE computes
//     alongside the positions.
//
// Expected output (defaults): DOF 0 (driven), max errors ~8e-10 m and ~3e-8 m/s, work and
// kinetic energy change agreeing to ~2e-4 J of an 11 J swing, "all checks PASSED"; exit 0.

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "examples/example_main.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/core/system.h"

namespace {

using emb::mbs::JointType;

// A body with mass m [kg], principal moments J [kg m^2] about its CM at p [m] (axes = world).
emb::mbs::RigidBody Body(const std::string& name, double m, const Eigen::Vector3d& J,
                         const Eigen::Vector3d& p) {
  emb::mbs::RigidBody b;
  b.name = name;
  b.mass = m;
  b.inertia_B = J.asDiagonal();
  b.p_WB = p;
  return b;
}

bool Run(int argc, char** argv) {
  using namespace emb::mbs;
  const double rpm = argc > 1 ? std::stod(argv[1]) : 600.0;
  const double rtol = argc > 2 ? std::stod(argv[2]) : 1e-8;
  const double r = 0.05, l = 0.2;                        // crank radius, rod length [m]
  const double omega = rpm * 2 * std::numbers::pi / 60;  // [rad/s]

  // 1. Bodies at the start pose (crank angle 0: crank, rod and piston on the world x axis,
  //    top dead centre at x = r + l). The ground exists already.
  System sys;
  sys.AddBody(Body("crank", 2.0, {1e-4, 4e-4, 4e-4}, {0.5 * r, 0, 0}));
  sys.AddBody(Body("rod", 1.0, {1e-5, 3.3e-3, 3.3e-3}, {r + 0.5 * l, 0, 0}));
  sys.AddBody(Body("piston", 0.5, {1e-4, 1e-4, 1e-4}, {r + l, 0, 0}));

  // 2. Markers: frames on bodies where joints attach (position from the body's CM, axes).
  const Eigen::Matrix3d I3 = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d z_along_x;  // marker z axis along world x (the slider's direction)
  z_along_x << 0, 0, 1, 0, 1, 0, -1, 0, 0;
  Eigen::Matrix3d z_along_y;  // marker z axis along body y (the small end's cross axis)
  z_along_y << 0, 1, 0, 0, 0, 1, 1, 0, 0;
  sys.AddMarker("o", "ground", Eigen::Vector3d::Zero(), I3);
  sys.AddMarker("bore", "ground", Eigen::Vector3d::Zero(), z_along_x);
  sys.AddMarker("crank_o", "crank", {-0.5 * r, 0, 0}, I3);
  sys.AddMarker("crank_pin", "crank", {0.5 * r, 0, 0}, I3);
  sys.AddMarker("rod_big", "rod", {-0.5 * l, 0, 0}, I3);
  sys.AddMarker("rod_small", "rod", {0.5 * l, 0, 0}, z_along_y);
  sys.AddMarker("piston_pin", "piston", Eigen::Vector3d::Zero(), I3);
  sys.AddMarker("piston_slide", "piston", Eigen::Vector3d::Zero(), z_along_x);

  // 3. Joints. A planar mechanism of revolute joints would be over-constrained in 3-D
  //    (redundant equations); a spherical big end and a universal small end make it exact.
  //    The motion prescribes the main bearing's rotation angle: a = omega t.
  sys.AddJoint("main", JointType::kRevolute, "crank_o", "o");
  sys.AddJoint("big_end", JointType::kSpherical, "rod_big", "crank_pin");
  sys.AddJoint("small_end", JointType::kUniversal, "rod_small", "piston_pin");
  sys.AddJoint("slider", JointType::kTranslational, "piston_slide", "bore");
  const int drive = sys.AddMotion("drive", "main", JointCoordinate::kRotation,
                                  TimeFunction::Polynomial({0.0, omega}));
  sys.Finalize();

  // 4. The analysis: one revolution, dynamic (the DAE, not the kinematic solver).
  AnalysisSettings settings;
  settings.type = AnalysisType::kDynamic;
  settings.t_end = 2 * std::numbers::pi / omega;
  settings.output_step = settings.t_end / 720;  // every 0.5 deg
  settings.ida.rtol = rtol;
  settings.ida.atol = 1e-2 * rtol;
  const PreparedRun run = PrepareRun(sys, settings);
  ThrowIfNotReady(run);  // an assembly that does not close is a status; here it ends the run
  std::printf("slider-crank: %d bodies, %d constraint equations, DOF %d (Gruebler %d)\n",
              run.system.layout().num_moving(), run.system.num_equations(), run.dof.true_dof,
              run.dof.gruebler_dof);

  // 5. Run it; the sink sees every output sample as the integration goes.
  const int piston = run.system.FindBody("piston");
  const int x = run.system.layout().position(piston), vx = run.system.layout().velocity(piston);
  double err_x = 0, err_v = 0, work = 0, err_energy = 0, e_max = 0;
  double e0 = 0, t_prev = 0, power_prev = 0;
  const RunResult result = RunAnalysis(run, settings, [&](const Sample& s) {
    const double a = omega * s.t, sa = std::sin(a), ca = std::cos(a);
    const double root = std::sqrt(l * l - r * r * sa * sa);
    const double x_ref = r * ca + root;
    const double v_ref = -r * omega * sa * (1 + r * ca / root);
    err_x = std::max(err_x, std::abs(s.q[x] - x_ref));
    err_v = std::max(err_v, std::abs(s.v[vx] - v_ref));
    // Drive power T_z omega: the torque about z the motion puts on the crank (row `drive`
    // of the reactions: [F, T] in the axes of the ground marker "o").
    const double power = s.reactions(drive, 5) * omega;
    if (s.t == 0)
      e0 = s.energies.kinetic;
    else
      work += 0.5 * (power + power_prev) * (s.t - t_prev);  // trapezoidal rule
    t_prev = s.t;
    power_prev = power;
    e_max = std::max(e_max, s.energies.kinetic);
    err_energy = std::max(err_energy, std::abs(work - (s.energies.kinetic - e0)));
  });
  std::printf("IDA: %s, %ld steps, %d samples\n", Name(result.status), result.ida_stats.steps,
              result.num_samples);
  if (!result.ok()) return false;

  // 6. Checks. The integration error is ~rtol times the scales r and r omega, with a factor
  //    100 for its growth over a revolution. The work integral's trapezoidal rule over
  //    0.5 deg steps errs by ~2e-5 of the energy swing whatever rtol (measured), the
  //    integrator's error is far below: 1e-4 of the swing is a check a wrong torque fails.
  const double kin_tol = 100 * rtol;
  constexpr double kEnergyTolerance = 1e-4;
  const bool ok_x = err_x <= kin_tol * r;
  const bool ok_v = err_v <= kin_tol * r * omega;
  const bool ok_e = err_energy <= kEnergyTolerance * e_max;
  std::printf("piston position: max error %.2e m (limit %.1e): %s\n", err_x, kin_tol * r,
              emb::examples::Verdict(ok_x));
  std::printf("piston velocity: max error %.2e m/s (limit %.1e): %s\n", err_v, kin_tol * r * omega,
              emb::examples::Verdict(ok_v));
  std::printf("drive work vs kinetic energy change: max difference %.2e J of %.3f J: %s\n",
              err_energy, e_max, emb::examples::Verdict(ok_e));
  const bool ok = run.dof.true_dof == 0 && ok_x && ok_v && ok_e;
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  return emb::examples::Main("ex03_slider_crank", Run, argc, argv);
}
