#pragma once
/// @file
/// The film of one evaluation: the journal's kinematics (the inputs a force element passes
/// in), the film thickness (notation.h, T1) at nodes and faces, the Poiseuille conductances,
/// the squeeze rate, and the film unknowns in physical form (Psi, theta, p).

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "libemb/tribology/reynolds_bearing.h"

namespace emb::tribology {

/// The journal relative to the shell, in shell axes (notation.h). The Jacobian columns
/// follow KinematicsLayout.
struct JournalKinematics {
  Eigen::Vector2d eccentricity{0.0, 0.0};       ///< e [m]
  Eigen::Vector2d tilt{0.0, 0.0};               ///< gamma = de/dz [rad]
  Eigen::Vector2d eccentricity_rate{0.0, 0.0};  ///< de/dt seen in S [m/s]
  Eigen::Vector2d tilt_rate{0.0, 0.0};          ///< dgamma/dt [rad/s]
  double journal_speed{0.0};                    ///< omega_j about z_S, relative to S [rad/s]
  double shell_speed{0.0};                      ///< omega_s about z_S, relative to S [rad/s]
  /// psi: the journal's rotation about z_S relative to S, the angle of its x axis from x_S
  /// (where its oil holes are: supply_features.h) [rad].
  double journal_angle{0.0};
  /// Optional additive film dh over all nodes (BearingGrid::Node) and its rate; the hook
  /// for elastic shells [m], [m/s]. Null: none.
  const Eigen::VectorXd* film_offset{nullptr};
  const Eigen::VectorXd* film_offset_rate{nullptr};
};

/// Column layout of Jacobians with respect to the kinematics.
struct KinematicsLayout {
  /// Columns of d/dx: e_x, e_y, gamma_x, gamma_y, psi (the film thickness depends on the
  /// first four, the journal holes' feed on psi).
  static constexpr int kNumPositions = 5;
  static constexpr int kEx = 0, kEy = 1, kTiltX = 2, kTiltY = 3, kJournalAngle = 4;
  static constexpr int kNumVelocities = 6;  ///< d/dv: e_dot (2), gamma_dot (2), omega_j, omega_s
  static constexpr int kEdotX = 0, kEdotY = 1, kTiltDotX = 2, kTiltDotY = 3, kOmegaJournal = 4,
                       kOmegaShell = 5;
};

/// Film thickness and conductances for one set of kinematics. Sized once per bearing.
class FilmFields {
 public:
  explicit FilmFields(const ReynoldsBearing& bearing);

  /// Evaluates the film. Returns false if h <= 0 at a node and the bearing has no asperity
  /// contact; then `message` says where (phi, z) and how deep.
  /// @throws InputError if film_offset or its rate has the wrong size.
  bool Set(const JournalKinematics& kin, std::string* message);

  const ReynoldsBearing& bearing() const { return *bearing_; }
  const JournalKinematics& kinematics() const { return kin_; }
  /// Mean surface speed U = R (omega_j + omega_s)/2 [m/s].
  double surface_speed() const { return surface_speed_; }

  /// h at every node (BearingGrid::Node), not floored [m].
  const std::vector<double>& node_film() const { return h_node_; }
  /// The hydrodynamic film at unknown k (floored with contact) and its rate [m], [m/s].
  double film(int k) const { return h_unknown_[k]; }
  double film_rate(int k) const { return hdot_unknown_[k]; }
  bool film_floored(int k) const { return floored_unknown_[k] != 0; }
  /// Circumferential face east of unknown k: film and conductance g = h^3 dz / (12 mu0 R dphi).
  double face_film_c(int k) const { return h_face_c_[k]; }
  double conductance_c(int k) const { return g_c_[k]; }
  bool face_floored_c(int k) const { return floored_c_[k] != 0; }
  /// Axial face f = i (m+1) + jf between rows jf and jf+1 of column i (jf = 0..m):
  /// film and conductance g = h^3 R dphi / (12 mu0 dz).
  double face_film_z(int f) const { return h_face_z_[f]; }
  double conductance_z(int f) const { return g_z_[f]; }
  bool face_floored_z(int f) const { return floored_z_[f] != 0; }
  /// dh/dx at (phi, z): -(cos, sin, z cos, z sin); the face and node tables of the grid.
  static Eigen::Vector4d FilmGradient(double c, double s, double z) {
    return Eigen::Vector4d(-c, -s, -z * c, -z * s);
  }
  /// The journal holes' feed at this journal angle (empty without holes).
  const JournalFeed& feed() const { return feed_; }
  /// The minimum of h over all nodes and where (node index).
  double min_film() const { return min_film_; }
  int min_film_node() const { return min_film_node_; }

 private:
  double Rigid(double c, double s, double z) const;  // h without dh

  const ReynoldsBearing* bearing_;
  JournalKinematics kin_;
  double surface_speed_{0.0};
  double floor_{0.0};
  std::vector<double> h_node_, h_unknown_, hdot_unknown_, h_face_c_, g_c_, h_face_z_, g_z_;
  std::vector<char> floored_unknown_, floored_c_, floored_z_;
  JournalFeed feed_;
  double min_film_{0.0};
  int min_film_node_{0};
};

/// The film unknowns in physical form for the current universal variables (T5) or
/// Fischer-Burmeister pairs: per unknown Psi, theta and their derivatives with respect to
/// the Newton variable, the pressure p = P(Psi) and dp/dPsi.
struct FilmUnknowns {
  std::vector<double> psi, theta, pressure, dp_dpsi;
  /// Column weights of the Jacobian: dPsi/du, dtheta/du (transport), d(slack)/du (the
  /// Swift-Stieber complementarity column of kReynolds).
  std::vector<double> dpsi_du, dtheta_du, dslack_du;
  /// Second derivatives of the smoothed switch (ReynoldsBearingParameters::switch_width):
  /// p_ref / (2 w) and -1 / (2 w) inside its band, else 0.
  std::vector<double> d2psi_du2, d2theta_du2;
  /// Slack term added to the residual (kReynolds): sigma_k min(u_k, 0).
  std::vector<double> slack;
  std::vector<double> slack_scale;  ///< sigma_k [m^3/s]
  void Resize(int n);
};

/// Fills `x` from the universal variables `u` (T5) for the bearing's cavitation model.
/// Returns false if Psi reaches the pressure-viscosity law's limit somewhere.
bool SetUnknownsFromUniversal(const ReynoldsBearing& bearing, const FilmFields& film,
                              const Eigen::VectorXd& u, FilmUnknowns* x);

/// Fills `x` from Fischer-Burmeister pairs: Psi = p_ref a and b = 1 - theta (kMassConserving)
/// or b = the Swift-Stieber slack (kReynolds: residual term -sigma b). The weights dPsi/du
/// etc. are those of the switch at u = a - b. Returns false as above.
bool SetUnknownsFromPairs(const ReynoldsBearing& bearing, const FilmFields& film,
                          const Eigen::VectorXd& a, const Eigen::VectorXd& b, FilmUnknowns* x);

}  // namespace emb::tribology
