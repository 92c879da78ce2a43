#pragma once
/// @file
/// Reading channels back from a multibody results file (results_writer.h layout) by the
/// CSV channel names, for post-processing (emb spectrum, plots).

#include <limits>
#include <string>
#include <vector>

namespace emb::results {

/// One channel of a results file: the time samples and the values.
struct ResultsChannel {
  std::vector<double> time;
  std::vector<double> values;
  /// Non-empty when the file holds an unfinished run (ResultsStatus::warning): callers
  /// should show it, the data end early.
  std::string warning;
};

/// How the run that wrote a results file ended (root attributes, results_writer.h).
struct ResultsStatus {
  std::string status;  ///< "success", "running" (never finished), "interrupted", "failed", ...
  std::string message;
  double t_reached{std::numeric_limits<double>::quiet_NaN()};  ///< [s]
  std::string warning;  ///< a sentence for the user; empty for "success"
};

/// @throws InputError if the file cannot be read as HDF5.
ResultsStatus ReadResultsStatus(const std::string& path);

/// Channels: <body>.p|v|omega.{x,y,z} (omega in W, as in the CSV), <port>.F|T.{x,y,z}
/// (reactions in J's axes), <force element>.F|T.{x,y,z} and .F.norm (|F|),
/// <sensor>.dx|dy|dz|rx|ry|rz, <joint>.angle|angle_rate|travel|travel_rate (rad, rad/s, m, m/s; the
/// angle unwrapped), <probe>.<channel> (output points u|v|a.{x,y,z,n}, power; chord sensors
/// dx|dy|dz|norm|s), energy.{kinetic,gravity,elastic,total,dissipated}.
/// @throws InputError for a file that is not emb-mbs-results or an unknown channel (with
/// a did-you-mean).
ResultsChannel ReadResultsChannel(const std::string& path, const std::string& channel);

/// The rotation angle [deg] of `body` about the world axis `axis` ("x", "y" or "z"),
/// unwrapped across turns and shifted so that it starts at `start_deg`: the angle of the
/// body's image of a unit vector u normal to the axis, atan2((R u) . (a x u), (R u) . u).
/// If `body` names no body but a joint with an angle (/model/joints), that joint's unwrapped
/// angle (joint_coordinates.h) instead, and `axis` is not used.
/// @throws InputError as ReadResultsChannel, for an unknown body or axis.
ResultsChannel ReadBodyRotationAngle(const std::string& path, const std::string& body,
                                     const std::string& axis, double start_deg);

/// The steady-state search of a run (ResultsWriter::RecordSteadyState), if it had one.
struct ResultsSteadyState {
  bool present{false};    ///< the run searched for a periodic steady state
  bool converged{false};  ///< and found it
  int cycles{0};
  double change{0.0}, tolerance{0.0};
  double cycle_start{0.0}, cycle_end{0.0};  ///< the last (steady) cycle [s]
};
/// @throws InputError for a file that is not emb-mbs-results.
ResultsSteadyState ReadResultsSteadyState(const std::string& path);

}  // namespace emb::results
