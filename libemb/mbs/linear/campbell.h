#pragma once
/// @file
/// Campbell diagrams (issue 17): the installed natural frequencies of a model linearised about
/// its steady motion at a list of speeds (rotating_modes.h), followed across speeds by their
/// shapes (mode_tracking.h), classified, and the critical speeds where an engine order
/// crosses them.
///
/// Classification of a mode on a chosen rotor body (the crankshaft) with spin axis a (unit,
/// W): the body's mass lumped equally on its markers (its frame if it has none), the modal
/// velocity phasor (u, w) of each marker (translation, rotation; complex) split into
///   axial    |a . u|^2,
///   bending  |u - a (a . u)|^2 + r_g^2 |w - a (a . w)|^2   (lateral motion and slope),
///   torsion  r_g^2 |a . w|^2,
/// summed over the markers, r_g = sqrt(J_aa / m) the body's radius of gyration about a (it
/// turns a rotation into the speed of the mass it moves). The class is the largest of the
/// three fractions. Whirl (bending modes): the orbit's sense h = -sum Im(conj(U1) U2) of the
/// lateral components (U1, U2) in axes (e1, e2, a) (and r_g^2 times the same for the slopes);
/// forward if h turns the same way as the spin, backward if the other way, "planar" if
/// |h| < 10 % of the lateral energy (a straight-line orbit, e.g. on anisotropic supports).
///
/// Critical speeds: engine order k (k excitations per revolution) excites frequency k n / 60
/// at n rpm; it crosses a tracked mode where g(n) = f(n) - k n / 60 changes sign between two
/// speeds, located by linear interpolation of g (rpm = 60 f / k for a constant f).

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/linear/cycle_average.h"
#include "libemb/mbs/linear/rotating_modes.h"

namespace emb::mbs {

enum class ModeClass { kTorsion, kBending, kAxial };
const char* Name(ModeClass c);
enum class Whirl { kNone, kForward, kBackward, kPlanar };
const char* Name(Whirl w);

/// Energy fractions of one mode on the rotor body (see the file comment); they sum to 1.
struct ModeSplit {
  double torsion{0.0}, bending{0.0}, axial{0.0};
  /// The rotor body's share of the mode's kinetic energy, phi_b^H M_bb phi_b (phi M-normalised).
  double body_energy{0.0};
  ModeClass kind{ModeClass::kTorsion};
  Whirl whirl{Whirl::kNone};
};

/// The split of mode shape `phi` (a velocity phasor, size nv, M-normalised) on body `body`
/// about spin axis `axis_W` (unit) at positions q. @throws InputError for a ground body or a
/// zero axis.
ModeSplit ClassifyMode(const System& system, const Eigen::VectorXd& q, int body,
                       const Eigen::Vector3d& axis_W, const Eigen::VectorXcd& phi,
                       const Eigen::MatrixXd& M);

/// The modes at one speed.
struct CampbellPoint {
  double rpm{0.0};
  RotatingModes modes;
  std::vector<ModeSplit> splits;  ///< one per mode
  /// Cycle average (cycle_average.h): per mode the range of its frozen frequency over the
  /// angles [Hz] (NaN: no partner); empty for the frozen linearisation.
  Eigen::VectorXd hz_angle_min, hz_angle_max;
};

/// The modes of a model at one steady operating point, and what they were computed about.
struct OperatingPointModes {
  CampbellPoint point;  ///< modes and their splits on the rotor body
  System system;        ///< the prepared system (marker look-ups)
  Eigen::VectorXd q, v; ///< the state linearised about
  int rotor_body{-1};
  Eigen::Vector3d axis_W{Eigen::Vector3d::UnitX()};  ///< the rotor's spin axis (unit, W)
};

/// The steady-motion approximation a Campbell diagram linearises about: the model (set to its
/// speed by the caller, e.g. scene/scene_at_speed.h) prepared as a dynamic run would be
/// (PrepareRun: assembled at t_start, velocities projected, flexible bodies on their
/// quasi-static deformation under the initial loads and centrifugal field if
/// settings.elastic_start asks), but with every flexible body on its full basis (the
/// installed basis' massless static shapes carry no frequency: settings.installed_bases is
/// ignored); multipliers and accelerations from SolveAccelerations at t_start (the
/// multipliers' second derivatives and the centrifugal/geometric terms enter K); then
/// CalcLinearizedModel and CalcRotatingModes up to pool_hz, each mode classified on the rotor
/// body (`rotor` empty: the model's one flexible body) about its spin axis. `rpm` only labels
/// the point. @throws InputError for an unknown rotor, none or several flexible bodies
/// without `rotor`, a rotor that does not spin, and what PrepareRun throws.
OperatingPointModes CalcOperatingPointModes(const System& system, AnalysisSettings settings,
                                            double rpm, const std::string& rotor, double pool_hz,
                                            bool stationary_frame = true);

/// How CalcOperatingPointModes linearises.
struct OperatingPointOptions {
  bool stationary_frame{true};
  Linearisation linearisation{Linearisation::kFrozen};
  /// Cycle average: angles per revolution. 16 is converged on the inline-4 (the first torsion
  /// frequency moves < 0.1 % from 16 to 32 angles: benchmarks/README.md, campbell_angles).
  int num_angles{16};
};

/// The same with the linearisation of `options`: kCycleAverage replaces the modes by those of
/// the cycle-averaged model about the same start (CalcCycleAveragedModes; the shapes at the
/// start angle) and fills point.hz_angle_min/max.
OperatingPointModes CalcOperatingPointModes(const System& system, AnalysisSettings settings,
                                            double rpm, const std::string& rotor, double pool_hz,
                                            const OperatingPointOptions& options);

/// One mode followed across the speeds: NaN where it was not found (lost).
struct TrackedMode {
  int index{0};                      ///< 1-based, ascending frequency at the first speed
  std::vector<double> hz, decay;     ///< [Hz], [1/s] per speed
  std::vector<double> mac;           ///< MAC with the previous speed (1 at the first)
  std::vector<ModeSplit> splits;     ///< per speed
  /// Per speed: the range of the frozen frequency over the cycle's angles [Hz] (cycle
  /// average; NaN otherwise or when not found).
  std::vector<double> hz_angle_min, hz_angle_max;
  ModeClass kind{ModeClass::kTorsion};  ///< the class with the largest mean fraction
  Whirl whirl{Whirl::kNone};             ///< at the last speed it was found
};

struct CampbellDiagram {
  std::vector<double> rpm;
  std::vector<TrackedMode> modes;
  /// Modes lost on the way (no shape with MAC >= min_mac at the next speed).
  int num_lost{0};
  double min_mac_seen{1.0};  ///< smallest MAC of an accepted pairing
};

/// Follows the modes of points[0] with frequency <= fmax_hz through the points (each point's
/// modes are candidates; give each a pool above fmax_hz so a rising mode stays followable),
/// pairing by mass-weighted MAC >= min_mac (MatchModes).
/// @throws InputError if points is empty or the speeds are not increasing.
CampbellDiagram TrackCampbell(const std::vector<CampbellPoint>& points, double fmax_hz,
                              double min_mac);

/// A critical speed: order k crossing a tracked mode.
struct Crossing {
  double order{0.0};
  double rpm{0.0};
  double mode_hz{0.0};  ///< = order rpm / 60
  int mode_index{0};    ///< TrackedMode::index
  ModeClass kind{ModeClass::kTorsion};
  Whirl whirl{Whirl::kNone};
  /// The mode's energy split at the grid speed nearest the crossing (ClassifyMode): a mode of
  /// mixed class (e.g. torsion 0.48, bending 0.51) resonates in a torsion channel too.
  double torsion{0.0}, bending{0.0}, axial{0.0};
};

/// All crossings of `orders` (> 0) with the tracked modes inside the speed range, by rpm.
std::vector<Crossing> FindCrossings(const CampbellDiagram& diagram,
                                    const std::vector<double>& orders);

}  // namespace emb::mbs
