#pragma once
/// @file
/// Probes: output-only quantities computed from a sample's state (q, v, v'), like sensors
/// but of any kind, e.g. the displacement, velocity and acceleration of mesh points of a
/// flexible body (mbs/flexible/output_points.h). A probe has a name and named channels
/// ("u.x", "a.n", ...); results and CSV files call them "<probe>.<channel>".

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "libemb/mbs/core/kinematics.h"

namespace emb::mbs {

class System;

class Probe {
 public:
  explicit Probe(std::string name) : name_(std::move(name)) {}
  virtual ~Probe() = default;
  const std::string& name() const { return name_; }
  /// The names of its channels (constant).
  const std::vector<std::string>& channels() const { return channels_; }
  int num_channels() const { return static_cast<int>(channels_.size()); }
  /// The channels' values at body kinematics `bodies` (at q, v) and accelerations `vdot`
  /// (size nv). @pre values.size() == num_channels().
  void Eval(const System& system, const std::vector<BodyKinematics>& bodies,
            const Eigen::VectorXd& vdot, Eigen::Ref<Eigen::VectorXd> values) const;
  /// Bodies it reads (to validate indices at Finalize).
  virtual std::vector<int> bodies() const = 0;
  /// The probe after body `body`'s modal coordinates became eta = T xi
  /// (System::WithElasticBases), or null if it does not depend on them.
  virtual std::shared_ptr<const Probe> WithElasticBasis(int body, const Eigen::MatrixXd& T) const {
    return nullptr;
  }

 protected:
  virtual void DoEval(const System& system, const std::vector<BodyKinematics>& bodies,
                      const Eigen::VectorXd& vdot, Eigen::Ref<Eigen::VectorXd> values) const = 0;
  std::vector<std::string> channels_;  ///< set by the derived constructor

 private:
  std::string name_;
};

}  // namespace emb::mbs
