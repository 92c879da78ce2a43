#pragma once
/// @file
/// What `emb run` does with the stress outputs of a scene (stress_output.h; the scene section
/// is read by scene/stress_output_reader.h) besides their hot-spot channels (which the results
/// file gets with the other probes, flushed every sample): it keeps the stress measure of every
/// group node for the fatigue summary, and the groups' stress fields at the chosen field times
/// for ParaView.
///
/// Fatigue per group and node: the history of the measure (sigma_1 or signed von Mises,
/// fe/stress_measures.h) over a window [t0, t1] is rainflow counted (periodically for one
/// steady-state cycle: rainflow.h) and its Goodman-corrected Miner damage D computed
/// (fatigue.h); the row reports the node of the largest D. Life = 1 / D windows (engine
/// cycles when the window is one steady cycle).
///
/// Stress fields (stress_field_file.h, written atomically at the end of the run): per
/// output o the fields of its groups, /<o>/<g>, at its field_times, with the group's faces
/// (the boundary faces of the body file's mesh whose nodes are all in the group), and the
/// field on the whole surface, /<o>/surface, at its surface_field_times. A field time is
/// taken by the first sample at or after it.

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/parts/stress_probe.h"
#include "libemb/results/stress_output.h"

namespace emb::results {

/// One row of the fatigue summary.
struct FatigueRow {
  std::string output, group, measure;
  int node{-1};                ///< mesh node of the largest damage
  double damage{0.0};          ///< Miner D per window
  double life{0.0};            ///< 1 / D windows (infinite if D = 0)
  double cycles{0.0};          ///< rainflow cycles counted at that node
  double max_range{0.0};       ///< largest range at that node [Pa]
  double max_equivalent{0.0};  ///< largest Goodman amplitude at that node [Pa]
};

class StressRecorder {
 public:
  /// `system`: the system the run integrates (PreparedRun::system, after any basis change).
  /// @throws InputError if a stress output's probe is missing from `system`.
  StressRecorder(const mbs::System& system, std::vector<StressOutput> outputs);
  bool empty() const { return outputs_.empty(); }
  bool has_fatigue() const;
  bool has_fields() const;
  /// Takes one sample: fatigue measures and, at field times, the fields.
  void Add(const mbs::Sample& sample);
  /// The fatigue summary over the samples with t0 <= t <= t1 (periodic: one steady cycle).
  std::vector<FatigueRow> Fatigue(double t0, double t1, bool periodic) const;
  /// Field times that no sample reached (the run ended before them).
  std::vector<double> MissedFieldTimes() const;
  /// Writes the stress-field file and its XDMF (file comment).
  /// @throws InputError naming the file if it cannot be written.
  void WriteFields(const std::string& h5_path, const std::string& xdmf_path) const;

 private:
  struct Surface {  // per output: the whole-surface field
    std::vector<double> t;
    std::vector<Eigen::MatrixXd> field;  // 6 x s per surface field time
  };
  struct Group {
    int output, index;                     // output and group index in the probe
    std::vector<double> t;                 // sample times (fatigue)
    std::vector<Eigen::VectorXd> measure;  // per sample: the measure at every node
    std::vector<double> field_t;           // field times reached
    std::vector<Eigen::MatrixXd> field;    // 6 x m per field time
  };
  const mbs::System& system_;
  std::vector<StressOutput> outputs_;
  std::vector<std::shared_ptr<const mbs::StressProbe>> probes_;
  std::vector<mbs::StressSnapshot> snapshots_;  // per output: the last sample's stresses
  std::vector<std::size_t> next_field_;         // per output: next field time to take
  std::vector<std::size_t> next_surface_;       // per output: next surface field time to take
  std::vector<Surface> surfaces_;               // per output
  std::vector<Group> groups_;
};

}  // namespace emb::results
