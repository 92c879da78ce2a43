#include "libemb/results/results_reader.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "libemb/common/did_you_mean.h"
#include "libemb/common/error.h"
#include "libemb/io/hdf5_file.h"
#include "libemb/mbs/core/state_layout.h"

namespace emb::results {
namespace {

ResultsStatus ReadStatus(const H5File& h5, const std::string& path) {
  ResultsStatus s;
  s.status = "(none)";
  if (h5.Exists("/")) {
    try {
      s.status = h5.ReadStringAttribute("/", "status");
    } catch (const InputError&) {
    }
    try {
      s.message = h5.ReadStringAttribute("/", "message");
      s.t_reached = h5.ReadDoubleAttribute("/", "t_reached");
    } catch (const InputError&) {
    }
  }
  if (s.status == "success") return s;
  std::ostringstream w;
  w << "'" << path << "' holds an unfinished run (status '" << s.status << "'";
  if (s.status == "running")
    w << ": the run was stopped without a word, e.g. killed, or is still going";
  else if (!s.message.empty())
    w << ": " << s.message;
  w << ")";
  if (std::isfinite(s.t_reached)) w << "; it reached t = " << s.t_reached << " s";
  s.warning = w.str();
  return s;
}

// The time series a reader may use; a run killed between two appends leaves them one row
// apart, so a reader uses the rows they all have.
constexpr const char* kSeries[] = {"/state/q",          "/state/v",       "/reactions/force",
                                   "/reactions/torque", "/energy",        "/residuals",
                                   "/forces/load",      "/sensors",       "/joints",
                                   "/output_points",    "/forces/outputs"};
// Where a body's values sit in a row of /state/q and /state/v: the layout record the writer
// stores (version 3), or for version 2 files mbs::StateLayout's, which they were written with.
struct StateColumns {
  std::size_t q_stride{mbs::StateLayout::kQPerBody}, position{0}, quaternion{3};
  std::size_t v_stride{mbs::StateLayout::kVPerBody}, velocity{0}, angular_velocity{3};
};

struct ResultsFile {
  H5File h5;
  std::vector<std::string> bodies, ports, sensors, forces, joints;
  std::vector<std::string> probe_channels;   // "<probe>.<channel>", columns of /output_points
  std::vector<std::string> output_channels;  // "<element>.<output>", columns of /forces/outputs
  std::vector<double> time;
  std::size_t n{0};
  ResultsStatus status;
  StateColumns state;

  explicit ResultsFile(const std::string& path) : h5(path, H5File::Mode::kRead) {
    std::string format;
    try {
      format = h5.ReadStringAttribute("/", "format");
    } catch (const std::exception&) {
    }
    EMB_THROW_IF(format != "emb-mbs-results",
                 "'" << path << "': expected a multibody results file (format emb-mbs-results)");
    status = ReadStatus(h5, path);
    bodies = h5.ReadStrings("/model/bodies");
    ports = h5.ReadStrings("/model/reaction_ports");
    if (h5.Exists("/model/sensors")) sensors = h5.ReadStrings("/model/sensors");
    if (h5.Exists("/model/force_elements")) forces = h5.ReadStrings("/model/force_elements");
    if (h5.Exists("/model/joints")) joints = h5.ReadStrings("/model/joints");
    if (h5.Exists("/model/output_point_channels"))
      probe_channels = h5.ReadStrings("/model/output_point_channels");
    if (h5.Exists("/model/force_output_channels"))
      output_channels = h5.ReadStrings("/model/force_output_channels");
    time = h5.ReadDoubles("/time");
    n = time.size();
    for (const char* s : kSeries)
      if (h5.Exists(s)) {
        const auto shape = h5.Shape(s);
        EMB_THROW_IF(shape.size() != 2, "'" << path << "': " << s << ": expected [samples, "
                                            << "columns], got " << shape.size() << " dimensions");
        n = std::min<std::size_t>(n, shape[0]);
      }
    time.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      EMB_THROW_IF(!std::isfinite(time[i]) || (i > 0 && !(time[i] > time[i - 1])),
                   "'" << path << "': /time[" << i << "] = " << time[i]
                       << ": expected finite, increasing sample times (damaged file?)");
    const mbs::StateLayout layout(2);  // one moving body: its offsets within a block
    state.quaternion = layout.quaternion(1) - layout.position(1);
    state.angular_velocity = layout.angular_velocity(1) - layout.velocity(1);
    // A crafted layout record must not index past a row: small, non-negative numbers only
    // (the blocks' fit in the rows is checked where they are read).
    auto column = [&](const char* dataset, const char* name, std::size_t* out) {
      if (!h5.HasAttribute(dataset, name)) return;
      const long long v = h5.ReadIntAttribute(dataset, name);
      EMB_THROW_IF(v < 0 || v > 64, "'" << path << "': " << dataset << " attribute " << name
                                        << " = " << v << ": expected 0 to 64 (damaged file?)");
      *out = static_cast<std::size_t>(v);
    };
    column("/state/q", "values_per_body", &state.q_stride);
    column("/state/q", "position_column", &state.position);
    column("/state/q", "quaternion_column", &state.quaternion);
    column("/state/v", "values_per_body", &state.v_stride);
    column("/state/v", "velocity_column", &state.velocity);
    column("/state/v", "angular_velocity_column", &state.angular_velocity);
    EMB_THROW_IF(state.position + 3 > state.q_stride || state.quaternion + 4 > state.q_stride ||
                     state.velocity + 3 > state.v_stride ||
                     state.angular_velocity + 3 > state.v_stride,
                 "'" << path << "': the state layout record (values_per_body, *_column) puts a "
                     << "block outside a body's values; expected blocks within them (damaged "
                        "file?)");
    for (auto [dataset, stride] :
         {std::pair{"/state/q", state.q_stride}, std::pair{"/state/v", state.v_stride}})
      if (h5.Exists(dataset)) {
        const auto shape = h5.Shape(dataset);  // two dimensions (checked above)
        EMB_THROW_IF(shape[1] != stride * bodies.size(),
                     "'" << path << "': " << dataset << " has " << shape[1] << " columns; "
                         << "expected values_per_body x bodies = " << stride << " x "
                         << bodies.size() << " (damaged file?)");
      }
  }
  /// Column `col` of the [rows, width] dataset `path`, its first n rows.
  std::vector<double> Column(const std::string& path, std::size_t col) const {
    EMB_THROW_IF(!h5.Exists(path), "'" << h5.path() << "': missing " << path);
    const auto shape = h5.Shape(path);
    const std::size_t width = shape.size() == 2 ? shape[1] : 0;
    EMB_THROW_IF(shape.size() != 2 || col >= width || shape[0] < n,
                 "'" << h5.path() << "': " << path << " has no column " << col
                     << " for every sample (damaged file?)");
    const std::vector<double> all = h5.ReadDoubles(path);
    std::vector<double> out(n);
    for (std::size_t i = 0; i < n; ++i) out[i] = all[i * width + col];
    return out;
  }
  /// Body rotations R_WB at every sample.
  std::vector<Eigen::Matrix3d> Rotations(std::size_t body) const {
    const auto shape = h5.Shape("/state/q");
    const std::size_t width = shape.size() == 2 ? shape[1] : 0;
    EMB_THROW_IF(width < state.q_stride * body + state.quaternion + 4 || shape[0] < n,
                 "'" << h5.path() << "': /state/q has no quaternion of body " << body
                     << " for every sample (damaged file?)");
    const std::vector<double> q = h5.ReadDoubles("/state/q");
    std::vector<Eigen::Matrix3d> out(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double* e = &q[i * width + state.q_stride * body + state.quaternion];
      out[i] = Eigen::Quaterniond(e[0], e[1], e[2], e[3]).normalized().toRotationMatrix();
    }
    return out;
  }
};

int Component(const std::string& c) {
  if (c == "x") return 0;
  if (c == "y") return 1;
  if (c == "z") return 2;
  return -1;
}

std::size_t FindName(const std::vector<std::string>& names, const std::string& name,
                     const std::string& what, const std::string& channel) {
  const auto it = std::find(names.begin(), names.end(), name);
  EMB_THROW_IF(it == names.end(), "channel '" << channel << "': unknown " << what << " '" << name
                                              << "'" << DidYouMean(name, names));
  return static_cast<std::size_t>(it - names.begin());
}

}  // namespace

ResultsStatus ReadResultsStatus(const std::string& path) {
  const H5File h5(path, H5File::Mode::kRead);
  return ReadStatus(h5, path);
}

ResultsChannel ReadResultsChannel(const std::string& path, const std::string& channel) {
  const ResultsFile f(path);
  ResultsChannel out;
  out.time = f.time;
  out.warning = f.status.warning;
  const std::size_t dot2 = channel.rfind('.');
  const std::size_t dot1 = dot2 == std::string::npos ? dot2 : channel.rfind('.', dot2 - 1);
  if (channel.rfind("energy.", 0) == 0) {
    const std::vector<std::string> cols{"kinetic", "gravity", "elastic", "total", "dissipated"};
    const std::size_t c = FindName(cols, channel.substr(7), "energy column", channel);
    out.values = f.Column("/energy", c);
    return out;
  }
  // Probes (output points, chord sensors): "<probe>.<channel>" columns of /output_points.
  if (const auto it = std::find(f.probe_channels.begin(), f.probe_channels.end(), channel);
      it != f.probe_channels.end()) {
    out.values =
        f.Column("/output_points", static_cast<std::size_t>(it - f.probe_channels.begin()));
    return out;
  }
  // Force elements' outputs: "<element>.<output>" columns of /forces/outputs.
  if (const auto it = std::find(f.output_channels.begin(), f.output_channels.end(), channel);
      it != f.output_channels.end()) {
    out.values =
        f.Column("/forces/outputs", static_cast<std::size_t>(it - f.output_channels.begin()));
    return out;
  }
  // <sensor>.dx .. .rz (the /sensors columns).
  const std::size_t last = channel.rfind('.');
  if (last != std::string::npos &&
      std::find(f.sensors.begin(), f.sensors.end(), channel.substr(0, last)) != f.sensors.end()) {
    const std::vector<std::string> cols{"dx", "dy", "dz", "rx", "ry", "rz"};
    const std::size_t k =
        std::find(f.sensors.begin(), f.sensors.end(), channel.substr(0, last)) - f.sensors.begin();
    out.values = f.Column(
        "/sensors", 6 * k + FindName(cols, channel.substr(last + 1), "sensor component", channel));
    return out;
  }
  // <joint>.angle|angle_rate|travel|travel_rate (the /joints columns, version 4).
  if (last != std::string::npos &&
      std::find(f.joints.begin(), f.joints.end(), channel.substr(0, last)) != f.joints.end()) {
    const std::vector<std::string> cols{"angle", "angle_rate", "travel", "travel_rate"};
    const std::size_t k =
        std::find(f.joints.begin(), f.joints.end(), channel.substr(0, last)) - f.joints.begin();
    out.values = f.Column("/joints", cols.size() * k + FindName(cols, channel.substr(last + 1),
                                                                "joint coordinate", channel));
    EMB_THROW_IF(
        std::any_of(out.values.begin(), out.values.end(), [](double v) { return std::isnan(v); }),
        "channel '" << channel << "': joint '" << channel.substr(0, last)
                    << "' has no such coordinate (angle: revolute and cylindrical "
                       "joints; travel: translational and cylindrical joints)");
    return out;
  }
  EMB_THROW_IF(dot1 == std::string::npos || dot1 == 0,
               "channel '" << channel
                           << "': expected <body>.p|v|omega.{x,y,z}, <element>.F|T.{x,y,z}, "
                              "<sensor>.dx|dy|dz|rx|ry|rz, <joint>.angle|angle_rate|travel|"
                              "travel_rate, <probe>.<channel> (output points, chord sensors) "
                              "or energy.{kinetic,gravity,elastic,total,dissipated}");
  const std::string owner = channel.substr(0, dot1);
  const std::string quantity = channel.substr(dot1 + 1, dot2 - dot1 - 1);
  const bool is_force_element =
      std::find(f.ports.begin(), f.ports.end(), owner) == f.ports.end() &&
      std::find(f.forces.begin(), f.forces.end(), owner) != f.forces.end();
  if (quantity == "F" && channel.substr(dot2 + 1) == "norm" && is_force_element) {
    // |F| of a force element's load, as the CSV channel <force element>.F.norm.
    ResultsChannel norm = ReadResultsChannel(path, owner + ".F.x");
    const std::vector<double> y = ReadResultsChannel(path, owner + ".F.y").values;
    const std::vector<double> z = ReadResultsChannel(path, owner + ".F.z").values;
    for (std::size_t i = 0; i < norm.values.size(); ++i)
      norm.values[i] = std::sqrt(norm.values[i] * norm.values[i] + y[i] * y[i] + z[i] * z[i]);
    return norm;
  }
  const int comp = Component(channel.substr(dot2 + 1));
  EMB_THROW_IF(comp < 0, "channel '" << channel << "': expected a component x, y or z");
  const auto c = static_cast<std::size_t>(comp);
  if ((quantity == "F" || quantity == "T") && is_force_element) {  // /forces/load
    const std::size_t k = std::find(f.forces.begin(), f.forces.end(), owner) - f.forces.begin();
    out.values = f.Column("/forces/load", 6 * k + c + (quantity == "T" ? 3 : 0));
    EMB_THROW_IF(
        std::any_of(out.values.begin(), out.values.end(), [](double v) { return std::isnan(v); }),
        "channel '" << channel << "': force element '" << owner
                    << "' reports no load (F/T channels exist for bushings and journal "
                       "bearings)");
    return out;
  }
  if (quantity == "F" || quantity == "T") {
    const std::size_t port = FindName(f.ports, owner, "element", channel);
    out.values = f.Column(quantity == "F" ? "/reactions/force" : "/reactions/torque", 3 * port + c);
    return out;
  }
  EMB_THROW_IF(quantity != "p" && quantity != "v" && quantity != "omega",
               "channel '" << channel << "': unknown quantity '" << quantity
                           << "', expected p, v, omega (bodies) or F, T (elements)");
  const std::size_t b = FindName(f.bodies, owner, "body", channel);
  if (quantity == "p") {
    out.values = f.Column("/state/q", f.state.q_stride * b + f.state.position + c);
  } else if (quantity == "v") {
    out.values = f.Column("/state/v", f.state.v_stride * b + f.state.velocity + c);
  } else {
    // omega_B in the file; the CSV convention is W.
    const auto R = f.Rotations(b);
    std::vector<Eigen::Vector3d> w(f.n);
    for (std::size_t k = 0; k < 3; ++k) {
      const std::vector<double> col =
          f.Column("/state/v", f.state.v_stride * b + f.state.angular_velocity + k);
      for (std::size_t i = 0; i < f.n; ++i) w[i][static_cast<Eigen::Index>(k)] = col[i];
    }
    out.values.resize(f.n);
    for (std::size_t i = 0; i < f.n; ++i)
      out.values[i] = (R[i] * w[i])[static_cast<Eigen::Index>(c)];
  }
  return out;
}

ResultsChannel ReadBodyRotationAngle(const std::string& path, const std::string& body,
                                     const std::string& axis, double start_deg) {
  const ResultsFile f(path);
  if (std::find(f.bodies.begin(), f.bodies.end(), body) == f.bodies.end() &&
      std::find(f.joints.begin(), f.joints.end(), body) != f.joints.end()) {
    // A revolute joint's own unwrapped angle (the /joints column), in degrees.
    ResultsChannel out = ReadResultsChannel(path, body + ".angle");
    const double shift =
        out.values.empty() ? 0.0 : start_deg - out.values.front() * 180.0 / std::numbers::pi;
    for (double& x : out.values) x = x * 180.0 / std::numbers::pi + shift;
    return out;
  }
  const int a = Component(axis);
  EMB_THROW_IF(a < 0, "rotation angle axis: expected x, y or z, got '" << axis << "'");
  std::vector<std::string> candidates = f.bodies;
  candidates.insert(candidates.end(), f.joints.begin(), f.joints.end());
  EMB_THROW_IF(std::find(f.bodies.begin(), f.bodies.end(), body) == f.bodies.end(),
               "crank angle: '" << body << "' is neither a body nor a joint with an angle"
                                << DidYouMean(body, candidates));
  const std::size_t b = FindName(f.bodies, body, "body", body + " (angle)");
  const Eigen::Vector3d ax = Eigen::Vector3d::Unit(a);
  const Eigen::Vector3d u = Eigen::Vector3d::Unit((a + 1) % 3), v = ax.cross(u);
  ResultsChannel out;
  out.time = f.time;
  out.warning = f.status.warning;
  out.values.resize(f.n);
  double previous = 0.0, turns = 0.0;
  const auto R = f.Rotations(b);
  for (std::size_t i = 0; i < f.n; ++i) {
    const Eigen::Vector3d r = R[i] * u;
    const double wrapped = std::atan2(r.dot(v), r.dot(u));
    if (i > 0) turns += std::round((previous - wrapped) / (2 * std::numbers::pi));
    previous = wrapped;
    out.values[i] = (wrapped + 2 * std::numbers::pi * turns) * 180.0 / std::numbers::pi;
  }
  const double shift = f.n > 0 ? start_deg - out.values.front() : 0.0;
  for (double& x : out.values) x += shift;
  return out;
}

ResultsSteadyState ReadResultsSteadyState(const std::string& path) {
  const ResultsFile f(path);
  ResultsSteadyState s;
  s.present = f.h5.HasAttribute("/", "steady_state_converged");
  if (!s.present) return s;
  s.converged = f.h5.ReadIntAttribute("/", "steady_state_converged") != 0;
  s.cycles = static_cast<int>(f.h5.ReadIntAttribute("/", "steady_state_cycles"));
  s.change = f.h5.ReadDoubleAttribute("/", "steady_state_change");
  s.tolerance = f.h5.ReadDoubleAttribute("/", "steady_state_tolerance");
  s.cycle_start = f.h5.ReadDoubleAttribute("/", "steady_state_cycle_start");
  s.cycle_end = f.h5.ReadDoubleAttribute("/", "steady_state_cycle_end");
  return s;
}

}  // namespace emb::results
