#pragma once
/// @file
/// Writing multibody results as the run goes: an HDF5 file (layout below) and an optional
/// CSV of chosen channels. Every sample is appended and flushed at once, so a run that
/// fails (integrator failure) or is interrupted keeps every sample before it.
///
/// The file is written in place, not atomically: it is a log of the run. Its root attribute
/// `status` says how far it is: "running" while the run goes (and forever if the process was
/// killed outright), then the run's outcome ("success", "integrator-failure", ...), or
/// "interrupted" (SIGINT/SIGTERM) or "failed" (an error), with `message` and `t_reached`
/// (the last sample written). Readers warn on anything but "success" (results_reader.h).
///
/// HDF5 layout (format "emb-mbs-results", version 4, SI units; N samples, nb moving bodies,
/// m equations, ne constraint elements, np >= ne reaction ports; row-major as h5py shows
/// it):
///   /                   attrs format, version, units, scene, analysis, status, message,
///                       t_reached (the last three written at the end of the run); dynamic
///                       runs also atol, multiplier_atol, linear_solver as IDA used them
///   /model/bodies       [nb] names (ground excluded), order of the state blocks
///   /model/elements     [ne] constraint element names (joints, motions, couplers)
///   /model/element_types[ne] "revolute", "motion", ...
///   /model/equations    [m] "revolute 'main': at-point x", ... (order of lambda)
///   /model/reaction_ports [np] the elements in order, then "<coupler>:<joint2>" for the
///                       second joint of every coupler (a coupler loads both its joints)
///   /model/removed_equations  names of redundant equations removed (may be empty)
///   /model/mass [nb], /model/inertia [nb, 3, 3] (about the CM in B)
///   /model/basis_truncation/{parts, kept_modes, available_modes, static_compliance_error}
///                       [n] per flexible part from a body file (RecordTruncations)
///   /time               [N] s
///   /state/q            [N, 7 nb] per body p_WB (m) then e_WB (w, x, y, z); attributes
///                       values_per_body (7), position_column (0), quaternion_column (3)
///                       (mbs::StateLayout; version 2 files lack them, same layout)
///   /state/v            [N, 6 nb] per body v_WB (m/s, in W) then omega_B (rad/s, in B);
///                       attributes values_per_body (6), velocity_column (0),
///                       angular_velocity_column (3)
///   /state/vdot         [N, 6 nb] time derivative of v
///   /state/euler313     [N, 3 nb] per body (psi, theta, phi) rad, seed eq. (1.20)
///   /multipliers/lambda [N, m] N or N m
///   /reactions/force    [N, np, 3] N, on the body of marker I from J, at I, in J's axes
///   /reactions/torque   [N, np, 3] N m, about marker I, in J's axes
///                       (stored as [N, 3 np]; version 1 had [N, 3 ne] and no ports)
///   /energy             [N, 5] kinetic, gravity potential, elastic, total (J),
///                       dissipated power (W)
///   /residuals          [N, 2] max |Phi| (m or rad), max |C v + Phi_t| (m/s or rad/s)
///   /model/force_elements, /model/sensors  names
///   /forces/load        [N, 6 nf] per force element F (N) and T (N m) on its first
///                       marker's body in its second marker's axes (NaN if not reported)
///   /sensors            [N, 6 ns] per sensor: position of marker I in J's axes (m) and the
///                       rotation vector of R_J^T R_I (rad)
///   /model/joints       [nj] the joints with a coordinate (revolute, cylindrical,
///                       translational) (version 4)
///   /joints             [N, 4 nj] per joint: angle (rad, unwrapped across turns), angle
///                       rate (rad/s), travel (m), travel rate (m/s); NaN where the joint has
///                       no such coordinate (mbs/analysis/joint_coordinates.h) (version 4)
///   with output points or chord sensors (probes, mbs/flexible/output_points.h,
///   mbs/core/chord_sensor.h)
///   /model/output_points, /model/output_point_channels  names, "<point>.<channel>"
///   /output_points      [N, channels] their values (units in the dataset's attribute)
///   with flexible bodies also
///   /model/flexible_bodies [nf] names, /model/num_modes [nf]
///   /state/eta, /state/eta_dot, /state/eta_ddot [N, sum num_modes] modal coordinates,
///                       rates and accelerations, body after body (/state/q, /state/v and
///                       /state/vdot hold the rigid-body part only)
///   with impact elements (dynamic runs with events, mbs/analysis/event_handling.h)
///   /events/contacts    [nc, 7] per contact: force element index, side (+1 upper stop,
///                       -1 lower), t_onset [s], closing speed, peak force [N or N m],
///                       t_separation [s] (NaN: closed at the end), opening speed
///   /events/elements    [nc] the force element of each contact; root attributes
///                       num_events (located events) and num_restarts (law switches)

#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "libemb/io/time_series_file.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/results/channels.h"
#include "libemb/results/steady_state.h"

namespace emb::results {

/// Limits on what one run writes, checked before it starts (`emb run --force` lifts them): the
/// output times are built up front and every sample is appended and flushed (about a
/// millisecond each), so 2 million samples is already half an hour of writing.
inline constexpr double kMaxOutputSamples = 2e6;
inline constexpr double kMaxOutputBytes = 4e9;  ///< [bytes] of one results file

class ResultsWriter {
 public:
  /// Creates the file and writes the model description.
  /// @throws InputError if the file cannot be created.
  ResultsWriter(const std::string& path, const mbs::System& system, const std::string& scene,
                const std::string& analysis);
  /// Appends one sample and flushes.
  void Write(const mbs::Sample& sample);
  /// Records the outcome (status, message, t_reached) as root attributes and flushes.
  void Finish(const mbs::RunResult& result);
  /// Records a run that stopped early: `status` "interrupted" or "failed", the reason and
  /// the time of the last sample written, and flushes.
  void MarkStopped(const std::string& status, const std::string& reason, double t_reached);
  /// Closes the file. @throws InputError if the close fails (disk full, I/O error).
  void Close();
  /// Bytes one sample adds to the file of `system` (for output-size estimates).
  static std::uint64_t BytesPerSample(const mbs::System& system);
  /// Records the steady-state search as root attributes steady_state_{converged (1/0),
  /// cycles, change, tolerance, worst_channel, cycle_start, cycle_end} [s] and flushes;
  /// readers (emb spectrum, the plots) analyse [cycle_start, cycle_end] by default.
  void RecordSteadyState(const SteadyStateReport& report, const SteadyStateSettings& settings);
  /// Records the truncation error indicator of the flexible parts (PreparedRun::
  /// truncations, mbs/analysis/basis_truncation.h), if any: /model/basis_truncation/parts
  /// [n] names, kept_modes [n], available_modes [n], static_compliance_error [n] (relative).
  void RecordTruncations(const std::vector<mbs::TruncationReport>& reports);

 private:
  const mbs::System& system_;
  TimeSeriesFile file_;
  int time_, q_, v_, vdot_, euler_, lambda_, force_, torque_, energy_, residuals_;
  int eta_{-1}, eta_dot_{-1}, eta_ddot_{-1}, loads_{-1}, sensors_{-1}, joints_{-1}, probes_{-1},
      outputs_{-1};
  std::vector<int> joint_elements_;  // System::elements() index of each /model/joints entry
  void WriteEvents(const mbs::EventLog& log);
};

/// A CSV file with a header line "t,<channel>,..." and one line per sample; the channels
/// are those of channels.h.
class CsvWriter {
 public:
  /// @throws InputError for an unknown channel (with a did-you-mean) or an unwritable file.
  CsvWriter(const std::string& path, const mbs::System& system,
            const std::vector<std::string>& channels);
  /// Appends one line and flushes. @throws InputError if the write fails (disk full).
  void Write(const mbs::Sample& sample);
  /// Closes the file. @throws InputError if the close fails.
  void Close();

 private:
  std::string path_;
  std::ofstream out_;
  ChannelSet channels_;
};

}  // namespace emb::results
