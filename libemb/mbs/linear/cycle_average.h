#pragma once
/// @file
/// The cycle-averaged linearisation of a steady periodic motion (Campbell diagrams of
/// reciprocating engines, issue 17).
///
/// Linearised about its motion, a crank–rod–piston mechanism running at speed Omega is a
/// periodic system  M(theta) y'' + G(theta) y' + K(theta) y = 0,  theta = Omega t: the pistons
/// add m_rec (ds/dtheta)^2 to the crank's torsional inertia, nothing at the dead centres and
/// about m_rec r^2 at mid-stroke (mean m_rec r^2 (1/2 + lambda^2/8 + ...) per throw,
/// lambda = r / l). A linearisation frozen at one angle (campbell.h) sees that angle's
/// inertia. The averaging method (Krylov–Bogoliubov; the zeroth harmonic of the Floquet
/// system) keeps the constant part:
///   Mbar = (1/N) sum_k M_r(theta_k),  Gbar, Kbar likewise,
/// over N crank angles theta_k = theta_0 + ((k + 1/2) / N - 1/2) 2 pi (one revolution centred
/// on the start angle theta_0), whose eigenvalues are the Campbell frequencies. Its error is
/// the parametric part (harmonics of M, G, K coupling frequencies f and f +- j Omega / 2 pi):
/// small away from parametric resonances; the spread of the frozen frequencies over the angles
/// (hz_min..hz_max) measures how large the periodic part is.
///
/// Coordinates common to all angles: the matrices of different angles can only be summed in
/// the same coordinates. Here they are rows S of v that are independent at every angle (chosen
/// at the start angle from the rotor body's rows first, then the other bodies in order: for an
/// engine, the crankshaft's rigid and modal velocities; the rods and pistons follow them), the
/// dependent velocities condensed through the velocity constraints,
///   v = T(theta) y,  T = Z (Z_S)^-1  (Z = null(C), Z_S its rows S),
///   M_r = T^T M T,  G_r = T^T (G - M W) T,  K_r = T^T K T  (W: rotating_modes.h).
/// Each angle's state: the start state (assembled, loaded, velocities projected) advanced
/// along the steady motion with y' fixed (rotor at its constant spin, dependent bodies
/// re-assembled about it, Newton on their coordinates only), then prepared as the start is
/// (PrepareRun: the quasi-static elastic start at that angle's loads).
///
/// One revolution: the reciprocating inertia of any engine repeats every revolution; the gas
/// loads of an even-firing engine with z cylinders repeat every 720/z degrees, so an inline-4's
/// revolution holds its whole cycle's gas-load content (an odd-firing engine's would not). The
/// angles stay within +-180 degrees of the start, where an applied load's angle argument is
/// read on its start branch.

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/linear/rotating_modes.h"

namespace emb::mbs {

/// How a Campbell diagram linearises the steady motion.
enum class Linearisation {
  kFrozen,        ///< at the start angle (campbell.h, CalcOperatingPointModes)
  kCycleAverage,  ///< the mean over one revolution (this file)
};
const char* Name(Linearisation l);
/// "frozen" or "cycle-average". @throws InputError otherwise.
Linearisation ParseLinearisation(const std::string& name);

/// The modes of the cycle-averaged model.
struct CycleAveragedModes {
  /// Frequencies and decays of (Mbar, Gbar, Kbar); shapes v = T(theta_0) s y at the start
  /// angle, normalised with the start's M (`mass`), for classification and MAC tracking.
  RotatingModes modes;
  /// Per mode: the smallest and largest frequency of its partner (MAC >= 0.5 in y with
  /// Mbar) among the frozen modes of the N angles [Hz]; NaN if no angle has a partner.
  Eigen::VectorXd hz_min, hz_max;
  int num_angles{0};
  double period_s{0.0};          ///< one rotor revolution [s]
  std::vector<int> coordinates;  ///< S: the rows of v used as y
};

/// The cycle-averaged modes about `start` (PrepareRun(system, settings) at settings.t_start,
/// settings as CalcOperatingPointModes sets them) of a model whose body `rotor` spins, over
/// `num_angles` angles of one revolution, up to pool_hz. @throws InputError for num_angles
/// < 1 or a rotor that does not spin; NumericalError if no rows of v are independent at every
/// angle, a state's dependent bodies cannot be re-assembled, or an eigen-solve fails.
CycleAveragedModes CalcCycleAveragedModes(const System& system, AnalysisSettings settings,
                                          const PreparedRun& start, int rotor, int num_angles,
                                          double pool_hz, bool stationary_frame);

}  // namespace emb::mbs
