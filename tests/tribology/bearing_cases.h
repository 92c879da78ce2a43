#pragma once
// Bearings and closed forms shared by the tribology tests.

#include <cmath>
#include <numbers>

#include <Eigen/Dense>

#include "libemb/tribology/film_solver.h"

namespace emb::tribology::test {

constexpr double kPi = std::numbers::pi;

// A passenger-car main bearing (R = 30 mm, L = 20 mm, c = 30 um) on a hot 10W-30
// (mu = 8.6 mPa s) at 3000 rpm.
constexpr double kMainRadius = 0.03, kMainLength = 0.02, kMainClearance = 30e-6;
constexpr double kMainViscosity = 0.0086;
constexpr double kMainSpeed = 3000.0 * 2.0 * kPi / 60.0;

inline ReynoldsBearingParameters Plain(double radius, double length, double clearance,
                                       GridSize grid, CavitationModel model,
                                       double viscosity = kMainViscosity) {
  ReynoldsBearingParameters p;
  p.radius = radius;
  p.length = length;
  p.clearance = clearance;
  p.grid = grid;
  p.lubricant.viscosity = viscosity;
  p.cavitation = model;
  return p;
}

inline ReynoldsBearingParameters MainBearing(GridSize grid, CavitationModel model) {
  return Plain(kMainRadius, kMainLength, kMainClearance, grid, model);
}

inline JournalKinematics Rotating(const Eigen::Vector2d& e, double omega) {
  JournalKinematics k;
  k.eccentricity = e;
  k.journal_speed = omega;
  return k;
}

// The main bearing's journal off-centre, tilted and moving, the shell turning too: every term
// of the film is active.
inline JournalKinematics Moving() {
  JournalKinematics k;
  k.eccentricity = Eigen::Vector2d(0.15, -0.6) * kMainClearance;
  k.tilt = Eigen::Vector2d(0.4e-3, -0.25e-3);
  k.eccentricity_rate = Eigen::Vector2d(0.02, 0.015) * kMainClearance * kMainSpeed;
  k.tilt_rate = Eigen::Vector2d(-0.1e-3, 0.05e-3) * kMainSpeed;
  k.journal_speed = kMainSpeed;
  k.shell_speed = 0.1 * kMainSpeed;
  k.journal_angle = 0.3;
  return k;
}

// The kinematic inputs in the Jacobians' column order: KinematicsLayout's positions, then
// its velocities.
constexpr int kNumInputs = KinematicsLayout::kNumPositions + KinematicsLayout::kNumVelocities;

// Central-difference steps for the main bearing's inputs: 1e-6 of each input's scale (c, c/L,
// their rates at the journal speed, 1e-6 rad of the journal angle, 1e-6 of the speed).
inline Eigen::Matrix<double, kNumInputs, 1> InputSteps() {
  const double c = kMainClearance, L = kMainLength, w = kMainSpeed;
  Eigen::Matrix<double, kNumInputs, 1> s;
  s << c, c, c / L, c / L, 1.0, c * w, c * w, c / L * w, c / L * w, w, w;
  return 1e-6 * s;
}

// Adds d to input `col` (InputSteps' order).
inline void Nudge(JournalKinematics* k, int col, double d) {
  using KL = KinematicsLayout;
  constexpr int v = KL::kNumPositions;
  switch (col) {
    case KL::kEx: k->eccentricity.x() += d; break;
    case KL::kEy: k->eccentricity.y() += d; break;
    case KL::kTiltX: k->tilt.x() += d; break;
    case KL::kTiltY: k->tilt.y() += d; break;
    case KL::kJournalAngle: k->journal_angle += d; break;
    case v + KL::kEdotX: k->eccentricity_rate.x() += d; break;
    case v + KL::kEdotY: k->eccentricity_rate.y() += d; break;
    case v + KL::kTiltDotX: k->tilt_rate.x() += d; break;
    case v + KL::kTiltDotY: k->tilt_rate.y() += d; break;
    case v + KL::kOmegaJournal: k->journal_speed += d; break;
    case v + KL::kOmegaShell: k->shell_speed += d; break;
  }
}

// Components of the film force F along e (radial) and along z x e (tangential).
struct Components {
  double radial, tangential;
};
inline Components Split(const Eigen::Vector2d& F, const Eigen::Vector2d& e) {
  const Eigen::Vector2d a = e.normalized(), b(-a.y(), a.x());
  return {F.dot(a), F.dot(b)};
}

// Attitude angle [deg]: between the load the bearing carries, W = -F, and the line of
// centres (journal rotating +z).
inline double AttitudeDeg(const Eigen::Vector2d& F, const Eigen::Vector2d& e) {
  const Components c = Split(F, e);
  return std::atan2(c.tangential, -c.radial) * 180.0 / kPi;
}

// Butenschoen's (DIN 31652) Sommerfeld number So = W psi^2 / (L D mu omega), psi = c / R.
inline double Sommerfeld(double W, double radius, double length, double clearance, double mu,
                         double omega) {
  return W * clearance * clearance / (2.0 * std::pow(radius, 3) * length * mu * omega);
}

// Observed order from three errors of a sequence refined by 2: log2(e_h / e_{h/2}).
inline double Order(double coarse, double fine) { return std::log2(coarse / fine); }

}  // namespace emb::tribology::test
