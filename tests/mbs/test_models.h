#pragma once
// Small models built in code for the multibody tests (scene files are tested in tests/scene).

#include <cmath>
#include <numbers>

#include <memory>

#include "libemb/mbs/rotation.h"
#include "libemb/mbs/spring_damper.h"
#include "libemb/mbs/system.h"

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

}  // namespace emb::mbs::testing
