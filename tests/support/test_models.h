#pragma once
// Small models built in code for the multibody tests (scene files are tested in tests/scene).

#include <cmath>
#include <numbers>

#include <memory>

#include "libemb/mbs/forces/applied_load.h"
#include "libemb/mbs/forces/bushing.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/forces/spring_damper.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs::testing {

// Rotation whose z axis is the world z (identity) or x.
inline Eigen::Matrix3d AxesZ() { return Eigen::Matrix3d::Identity(); }

// Slender rod of mass m [kg] and length l [m] along its body x axis.
inline RigidBody Rod(const std::string& name, double m, double l, const Eigen::Vector3d& p_WB,
                     double angle_z) {
  RigidBody b;
  b.name = name;
  b.mass = m;
  // Thin rod about x, plus a small polar moment so the tensor is positive definite.
  const double It = m * l * l / 12.0;
  const double Ip = 1e-3 * It;
  b.inertia_B = Eigen::Vector3d(Ip, It, It).asDiagonal();
  b.p_WB = p_WB;
  b.R_WB = Eigen::AngleAxisd(angle_z, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return b;
}

// A door on two revolute joints at the same hinge (about world z through p_hinge): the second
// repeats all 5 equations of the first. The door's CM is at p_WB.
inline System RepeatedHinge(const Eigen::Vector3d& p_WB = Eigen::Vector3d::Zero(),
                            const Eigen::Vector3d& p_hinge = Eigen::Vector3d::Zero()) {
  System s;
  RigidBody b;
  b.name = "door";
  b.mass = 10;
  b.inertia_B = Eigen::Vector3d(1, 1, 1).asDiagonal();
  b.p_WB = p_WB;
  s.AddBody(b);
  s.AddMarker("frame", "ground", p_hinge, Eigen::Matrix3d::Identity());
  s.AddMarker("hinge", "door", p_hinge - p_WB, Eigen::Matrix3d::Identity());
  s.AddJoint("upper", JointType::kRevolute, "hinge", "frame");
  s.AddJoint("lower", JointType::kRevolute, "hinge", "frame");
  s.Finalize();
  return s;
}

// Planar pendulum in the xy-plane, revolute about world z at the origin, gravity -y.
// theta0 [rad] from the downward vertical. Rod of length l along body x with the pivot at
// its end.
inline System Pendulum(double m, double l, double theta0, double g = 9.81) {
  System s;
  const double a = -std::numbers::pi / 2 + theta0;  // body x axis angle from world x
  const Eigen::Vector3d p(0.5 * l * std::cos(a), 0.5 * l * std::sin(a), 0.0);
  s.AddBody(Rod("rod", m, l, p, a));
  s.AddMarker("pivot_ground", "ground", Eigen::Vector3d::Zero(), AxesZ());
  s.AddMarker("pivot_rod", "rod", Eigen::Vector3d(-0.5 * l, 0, 0), AxesZ());
  s.AddJoint("pivot", JointType::kRevolute, "pivot_rod", "pivot_ground");
  s.SetGravity(Eigen::Vector3d(0, -g, 0));
  s.Finalize();
  return s;
}

// Double pendulum of two identical rods, both revolute about z.
inline System DoublePendulum(double m, double l, double theta1, double theta2, double g = 9.81) {
  System s;
  const double a1 = -std::numbers::pi / 2 + theta1, a2 = -std::numbers::pi / 2 + theta2;
  const Eigen::Vector3d e1(std::cos(a1), std::sin(a1), 0), e2(std::cos(a2), std::sin(a2), 0);
  s.AddBody(Rod("upper", m, l, 0.5 * l * e1, a1));
  s.AddBody(Rod("lower", m, l, l * e1 + 0.5 * l * e2, a2));
  s.AddMarker("o", "ground", Eigen::Vector3d::Zero(), AxesZ());
  s.AddMarker("upper_top", "upper", Eigen::Vector3d(-0.5 * l, 0, 0), AxesZ());
  s.AddMarker("upper_end", "upper", Eigen::Vector3d(0.5 * l, 0, 0), AxesZ());
  s.AddMarker("lower_top", "lower", Eigen::Vector3d(-0.5 * l, 0, 0), AxesZ());
  s.AddJoint("shoulder", JointType::kRevolute, "upper_top", "o");
  s.AddJoint("elbow", JointType::kRevolute, "lower_top", "upper_end");
  s.SetGravity(Eigen::Vector3d(0, -g, 0));
  s.Finalize();
  return s;
}

// A planar chain of `links` rods of 1 kg and 0.3 m along world x, joined by revolute joints
// about z (the first to the ground at the origin), gravity -y.
inline System RodChain(int links) {
  System s;
  const double l = 0.3;
  s.AddMarker("o", "ground", Eigen::Vector3d::Zero(), AxesZ());
  for (int k = 0; k < links; ++k) {
    const std::string name = "link" + std::to_string(k);
    s.AddBody(Rod(name, 1.0, l, Eigen::Vector3d((k + 0.5) * l, 0, 0), 0.0));
    s.AddMarker(name + "_a", name, Eigen::Vector3d(-0.5 * l, 0, 0), AxesZ());
    s.AddMarker(name + "_b", name, Eigen::Vector3d(0.5 * l, 0, 0), AxesZ());
    s.AddJoint("j" + std::to_string(k), JointType::kRevolute, name + "_a",
               k == 0 ? "o" : "link" + std::to_string(k - 1) + "_b");
  }
  s.SetGravity(Eigen::Vector3d(0, -9.81, 0));
  s.Finalize();
  return s;
}

// Slider-crank in the xy-plane: crank (radius r) revolute about z at the origin with a
// prescribed angle omega t, rod of length l, piston sliding along world x
// (translational joint). Piston position x = r cos(wt) + sqrt(l^2 - r^2 sin^2(wt)).
struct SliderCrankData {
  double r{0.05}, l{0.2}, omega{2 * std::numbers::pi * 10};
};
// Adds the slider-crank's bodies, markers, joints and motion to `s` (not finalized).
inline void AddSliderCrank(System& s, const SliderCrankData& d) {
  RigidBody crank = Rod("crank", 2.0, d.r, Eigen::Vector3d(0.5 * d.r, 0, 0), 0.0);
  RigidBody rod = Rod("rod", 1.0, d.l, Eigen::Vector3d(d.r + 0.5 * d.l, 0, 0), 0.0);
  RigidBody piston;
  piston.name = "piston";
  piston.mass = 0.5;
  piston.inertia_B = 1e-4 * Eigen::Matrix3d::Identity();
  piston.p_WB = Eigen::Vector3d(d.r + d.l, 0, 0);
  s.AddBody(crank);
  s.AddBody(rod);
  s.AddBody(piston);
  Eigen::Matrix3d z_along_x;  // marker axes with z along world x (for the slider)
  z_along_x << 0, 0, 1, 0, 1, 0, -1, 0, 0;
  s.AddMarker("o", "ground", Eigen::Vector3d::Zero(), AxesZ());
  s.AddMarker("crank_o", "crank", Eigen::Vector3d(-0.5 * d.r, 0, 0), AxesZ());
  s.AddMarker("crank_pin", "crank", Eigen::Vector3d(0.5 * d.r, 0, 0), AxesZ());
  s.AddMarker("rod_big", "rod", Eigen::Vector3d(-0.5 * d.l, 0, 0), AxesZ());
  Eigen::Matrix3d z_along_body_y;  // cross axis of the universal on the rod side
  z_along_body_y << 0, 1, 0, 0, 0, 1, 1, 0, 0;
  s.AddMarker("rod_small_cross", "rod", Eigen::Vector3d(0.5 * d.l, 0, 0), z_along_body_y);
  s.AddMarker("piston_pin", "piston", Eigen::Vector3d::Zero(), AxesZ());
  s.AddMarker("piston_slide", "piston", Eigen::Vector3d::Zero(), z_along_x);
  s.AddMarker("bore", "ground", Eigen::Vector3d::Zero(), z_along_x);
  s.AddJoint("main", JointType::kRevolute, "crank_o", "o");
  // Exactly constrained in 3-D: a spherical big end and a universal small end (the
  // rod's spin about its own axis is fixed by the universal's perpendicular equation).
  s.AddJoint("big_end", JointType::kSpherical, "rod_big", "crank_pin");
  s.AddJoint("small_end", JointType::kUniversal, "rod_small_cross", "piston_pin");
  s.AddJoint("slider", JointType::kTranslational, "piston_slide", "bore");
  s.AddMotion("drive", "main", JointCoordinate::kRotation,
              TimeFunction::Polynomial({0.0, d.omega}));
}

inline System SliderCrank(const SliderCrankData& d) {
  System s;
  AddSliderCrank(s, d);
  s.Finalize();
  return s;
}

// The slider-crank plus a spring-damper from the piston pin to the crank centre
// (k = 1000 N/m, free length 0.1 m) and optional gravity along −y.
inline System SliderCrankWithSpring(const SliderCrankData& d, double damping, double g) {
  System s;
  AddSliderCrank(s, d);
  s.AddForceElement(std::make_shared<TranslationalSpringDamper>(
      "spring", s.FindMarker("piston_pin"), s.FindMarker("o"), 1000.0, damping, 0.1));
  if (g != 0.0) s.SetGravity(Eigen::Vector3d(0, -g, 0));
  s.Finalize();
  return s;
}

// A load argument: the rotation angle of the joint between markers i and j, in degrees.
inline LoadArgument JointAngleInDegrees(const System& s, const std::string& i,
                                        const std::string& j) {
  LoadArgument arg;
  arg.joint_angle = true;
  arg.marker_i = s.FindMarker(i);
  arg.marker_j = s.FindMarker(j);
  arg.scale = 180.0 / std::numbers::pi;
  return arg;
}

// Every force element and a coupler at generic poses, for derivative checks (not finalized
// so a test can add to it; ForceElementZoo() finalizes):
//  - gears "gear1", "gear2" on revolutes "shaft1", "shaft2" about world z, coupled with ratio
//    -2; a rotational spring-damper on shaft1 (aligned axes);
//  - a torque on gear2 in its marker frame, a function of shaft1's angle in degrees,
//    reacting on gear1;
//  - a "block" held by gear2 through a coupled 6x6 bushing whose relative rotation starts at
//    `bushing_angle` [rad] about a skew axis, a spring-damper from the block to the ground
//    and a harmonic world-frame force on it;
//  - a "bob" on a spherical joint to the ground with a rotational spring-damper between
//    tilted axes (x_I not in J's xy-plane).
inline void AddForceElementZoo(System& s, double bushing_angle) {
  using Eigen::AngleAxisd;
  using Eigen::Matrix3d;
  using Eigen::Vector3d;
  const Matrix3d I3 = Matrix3d::Identity();
  auto body = [&](const std::string& name, double m, const Vector3d& J, const Vector3d& p,
                  const Matrix3d& R, const Vector3d& v, const Vector3d& w) {
    RigidBody b;
    b.name = name;
    b.mass = m;
    b.inertia_B = J.asDiagonal();
    b.p_WB = p;
    b.R_WB = R;
    b.v_WB = v;
    b.omega_W = w;
    s.AddBody(b);
  };
  body("gear1", 0.5, Vector3d(2e-4, 2e-4, 4e-4), Vector3d::Zero(),
       AngleAxisd(0.3, Vector3d::UnitZ()).toRotationMatrix(), Vector3d::Zero(), Vector3d(0, 0, 2));
  body("gear2", 3.0, Vector3d(7e-3, 7e-3, 1.4e-2), Vector3d(0.3, 0, 0),
       AngleAxisd(-0.15, Vector3d::UnitZ()).toRotationMatrix(), Vector3d::Zero(),
       Vector3d(0, 0, -1));
  s.AddMarker("o1", "ground", Vector3d::Zero(), I3);
  s.AddMarker("o2", "ground", Vector3d(0.3, 0, 0), I3);
  s.AddMarker("hub1", "gear1", Vector3d::Zero(), I3);
  s.AddMarker("hub2", "gear2", Vector3d::Zero(), I3);
  s.AddJoint("shaft1", JointType::kRevolute, "hub1", "o1");
  s.AddJoint("shaft2", JointType::kRevolute, "hub2", "o2");
  s.AddCoupler("mesh", "shaft1", JointCoordinate::kRotation, "shaft2", JointCoordinate::kRotation,
               -2.0, 0.0);
  s.AddForceElement(std::make_shared<RotationalSpringDamper>(
      "shaft1_torsion", s.FindMarker("hub1"), s.FindMarker("o1"), 3.0, 0.02, 0.1));
  s.AddForceElement(std::make_shared<AppliedLoad>(
      "drag", AppliedLoad::Kind::kTorque, s.FindMarker("hub2"), Vector3d(0.6, 0, 0.8),
      AppliedLoad::Frame::kMarker, TimeFunction::Table({-360, 0, 360}, {-5, 1, 7}, false),
      s.FindMarker("hub1"), JointAngleInDegrees(s, "hub1", "o1")));

  // Block on a bushing to gear2: relative rotation bushing_angle about a skew axis.
  const Matrix3d R_mount = RotationFromEuler313(0.3, 0.2, -0.4);
  const Vector3d s_mount(0.05, -0.02, 0.01);
  s.AddMarker("mount", "gear2", s_mount, R_mount);
  const Matrix3d R_W2 = s.body(s.FindBody("gear2")).R_WB;
  const Matrix3d R_Wmount = R_W2 * R_mount;
  const Vector3d p_mount = Vector3d(0.3, 0, 0) + R_W2 * s_mount;
  const Matrix3d R_block =
      R_Wmount * AngleAxisd(bushing_angle, Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const Vector3d s_seat(0.01, 0.02, -0.03);
  const Vector3d p_seat = p_mount + R_Wmount * Vector3d(0.004, -0.002, 0.003);
  body("block", 2.0, Vector3d(0.01, 0.02, 0.025), p_seat - R_block * s_seat, R_block,
       Vector3d(0.1, 0, -0.2), Vector3d(0.3, 0.2, -0.1));
  s.AddMarker("seat", "block", s_seat, I3);
  s.AddMarker("hook", "block", Vector3d(0, 0.05, 0), I3);
  s.AddMarker("anchor", "ground", Vector3d(0.5, -0.4, 0.1), I3);
  Bushing::Matrix6d K;
  K << 1e5, 2e3, 0, 0, 1e2, 0,  //
      2e3, 2e5, 0, 0, 0, 3e2,   //
      0, 0, 3e5, 2e2, 0, 0,     //
      0, 0, 2e2, 80, 5, 0,      //
      1e2, 0, 0, 5, 120, 10,    //
      0, 3e2, 0, 0, 10, 150;
  Bushing::Matrix6d D = 1e-3 * K;
  D(0, 3) += 0.05;  // a non-symmetric damping part is allowed
  s.AddForceElement(
      std::make_shared<Bushing>("bearing", s.FindMarker("seat"), s.FindMarker("mount"), K, D));
  s.AddForceElement(std::make_shared<TranslationalSpringDamper>(
      "tether", s.FindMarker("hook"), s.FindMarker("anchor"), 500.0, 4.0, 0.3));
  s.AddForceElement(std::make_shared<AppliedLoad>(
      "shake", AppliedLoad::Kind::kForce, s.FindMarker("hook"), Vector3d(0, 0, 1),
      AppliedLoad::Frame::kWorld, TimeFunction::Harmonic(20.0, 30.0, 0.2, 5.0)));

  // Bob on a spherical joint with a torsion spring between tilted axes.
  const Vector3d pivot(-0.4, 0, 0);
  const Matrix3d R_bob = RotationFromEuler313(0.4, 0.3, 0.2);
  const Vector3d p_bob(-0.4, -0.3, 0.05);
  body("bob", 1.0, Vector3d(0.01, 0.012, 0.008), p_bob, R_bob, Vector3d::Zero(),
       Vector3d(0.5, -1.0, 0.3));
  s.AddMarker("pivot", "ground", pivot, RotationFromEuler313(0.2, 0.5, 0.1));
  s.AddMarker("ball", "bob", R_bob.transpose() * (pivot - p_bob), I3);
  s.AddJoint("socket", JointType::kSpherical, "ball", "pivot");
  s.AddForceElement(std::make_shared<RotationalSpringDamper>(
      "bob_torsion", s.FindMarker("ball"), s.FindMarker("pivot"), 4.0, 0.05, -0.2));
  s.SetGravity(Eigen::Vector3d(0, -9.81, 0));
}

inline System ForceElementZoo(double bushing_angle) {
  System s;
  AddForceElementZoo(s, bushing_angle);
  s.Finalize();
  return s;
}

}  // namespace emb::mbs::testing
