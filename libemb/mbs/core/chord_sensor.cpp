#include "libemb/mbs/core/chord_sensor.h"

#include <cmath>
#include <limits>

#include "libemb/common/error.h"
#include "libemb/mbs/core/system.h"

namespace emb::mbs {
namespace {

// Below this chord length [m] the chord has no direction.
constexpr double kMinChordLength = 1e-12;

}  // namespace

ChordSensor::ChordSensor(const System& system, std::string name, int point, int end_a, int end_b)
    : Probe(std::move(name)), markers_{point, end_a, end_b} {
  for (int m : markers_)
    EMB_THROW_IF(m < 0 || m >= static_cast<int>(system.markers().size()),
                 "chord sensor '" << this->name() << "': no marker with index " << m);
  EMB_THROW_IF(point == end_a || point == end_b || end_a == end_b,
               "chord sensor '" << this->name()
                                << "': expected three different markers (a point and the two "
                                   "ends of its chord), got '"
                                << system.marker(point).name << "' relative to '"
                                << system.marker(end_a).name << "' - '"
                                << system.marker(end_b).name << "'");
  channels_ = {"dx", "dy", "dz", "norm", "s"};
  for (int m : markers_) bodies_.push_back(system.marker(m).body);
}

std::vector<int> ChordSensor::bodies() const { return bodies_; }

void ChordSensor::DoEval(const System& system, const std::vector<BodyKinematics>& bodies,
                         const Eigen::VectorXd& /*vdot*/,
                         Eigen::Ref<Eigen::VectorXd> values) const {
  const MarkerKinematics P = CalcMarkerKinematics(system, bodies, markers_[0]);
  const MarkerKinematics A = CalcMarkerKinematics(system, bodies, markers_[1]);
  const MarkerKinematics B = CalcMarkerKinematics(system, bodies, markers_[2]);
  const Eigen::Vector3d c = B.p_WM - A.p_WM, r = P.p_WM - A.p_WM;
  const double length = c.norm();
  if (!(length >= kMinChordLength)) {
    values.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  const Eigen::Vector3d u = c / length;
  const double along = r.dot(u);
  const Eigen::Vector3d d_W = r - along * u;
  values.head<3>() = A.R_WM.transpose() * d_W;
  values[3] = d_W.norm();
  values[4] = along / length;
}

}  // namespace emb::mbs
