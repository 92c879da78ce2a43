#include "libemb/results/results_writer.h"

#include <iomanip>

#include "libemb/common/error.h"
#include "libemb/mbs/analysis/joint_coordinates.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/results/channels.h"

namespace emb::results {
namespace {

std::vector<std::string> ElementTypes(const mbs::System& s) {
  std::vector<std::string> t;
  for (const auto& e : s.elements())
    t.push_back(e.kind == mbs::ElementKind::kJoint    ? mbs::Name(e.type)
                : e.kind == mbs::ElementKind::kMotion ? "motion"
                                                      : "coupler");
  return t;
}

// Elements with a joint coordinate (joint_coordinates.h): their indices.
std::vector<int> CoordinateJoints(const mbs::System& s) {
  std::vector<int> k;
  for (std::size_t e = 0; e < s.elements().size(); ++e)
    if (mbs::HasJointCoordinate(s.elements()[e], mbs::JointCoordinate::kRotation) ||
        mbs::HasJointCoordinate(s.elements()[e], mbs::JointCoordinate::kTranslation))
      k.push_back(static_cast<int>(e));
  return k;
}

Eigen::VectorXd Euler(const mbs::System& s, const Eigen::VectorXd& q) {
  const auto& L = s.layout();
  Eigen::VectorXd e(3 * L.num_moving());
  for (int b = 1; b < s.num_bodies(); ++b)
    e.segment<3>(3 * (b - 1)) =
        mbs::Euler313FromRotation(mbs::RotationFromQuaternion(q.segment<4>(L.quaternion(b))));
  return e;
}

}  // namespace

ResultsWriter::ResultsWriter(const std::string& path, const mbs::System& system,
                             const std::string& scene, const std::string& analysis)
    : system_(system), file_(path) {
  file_.SetAttribute("/", "format", std::string("emb-mbs-results"));
  file_.SetAttribute("/", "version", 4LL);
  file_.SetAttribute("/", "units", std::string("SI (m, kg, s, N, rad)"));
  file_.SetAttribute("/", "scene", scene);
  file_.SetAttribute("/", "analysis", analysis);
  file_.SetAttribute("/", "status", std::string("running"));
  const int nb = system.layout().num_moving();
  const int np = static_cast<int>(system.reaction_ports().size());
  const int m = system.num_equations();
  std::vector<std::string> bodies, elements, equations;
  std::vector<double> mass, inertia;
  for (int b = 1; b < system.num_bodies(); ++b) {
    bodies.push_back(system.body(b).name);
    mass.push_back(system.body(b).mass);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) inertia.push_back(system.body(b).inertia_B(i, j));
  }
  for (const auto& e : system.elements()) elements.push_back(e.name);
  for (int k = 0; k < m; ++k) equations.push_back(system.EquationName(k));
  file_.WriteStrings("/model/bodies", bodies);
  file_.WriteStrings("/model/elements", elements);
  file_.WriteStrings("/model/element_types", ElementTypes(system));
  file_.WriteStrings("/model/equations", equations);
  std::vector<std::string> ports;
  for (const auto& p : system.reaction_ports()) ports.push_back(p.name);
  file_.WriteStrings("/model/reaction_ports", ports);
  file_.WriteStrings("/model/removed_equations", system.removed_equations());
  file_.WriteDoubles("/model/mass", mass, {static_cast<std::uint64_t>(nb)});
  file_.WriteDoubles("/model/inertia", inertia, {static_cast<std::uint64_t>(nb), 3, 3});
  time_ = file_.AddScalarSeries("/time");
  // The rigid-body part of q and v (the modal coordinates follow it in the state and go to
  // /state/eta): its layout is recorded so that a reader needs no hard-coded widths.
  const mbs::StateLayout& L = system.layout();
  const int rigid_nq = L.nq() - L.num_elastic_total(), rigid_nv = L.nv() - L.num_elastic_total();
  q_ = file_.AddSeries("/state/q", rigid_nq);
  v_ = file_.AddSeries("/state/v", rigid_nv);
  vdot_ = file_.AddSeries("/state/vdot", rigid_nv);
  const long long q_stride = mbs::StateLayout::kQPerBody, v_stride = mbs::StateLayout::kVPerBody;
  file_.SetAttribute("/state/q", "values_per_body", q_stride);
  file_.SetAttribute("/state/q", "position_column", 0LL);
  file_.SetAttribute("/state/q", "quaternion_column",
                     static_cast<long long>(nb > 0 ? L.quaternion(1) - L.position(1) : 3));
  file_.SetAttribute("/state/v", "values_per_body", v_stride);
  file_.SetAttribute("/state/v", "velocity_column", 0LL);
  file_.SetAttribute("/state/v", "angular_velocity_column",
                     static_cast<long long>(nb > 0 ? L.angular_velocity(1) - L.velocity(1) : 3));
  euler_ = file_.AddSeries("/state/euler313", 3 * nb);
  lambda_ = file_.AddSeries("/multipliers/lambda", m);
  // Stored as [N, 3 np] rows; the attribute says how to reshape to [N, np, 3].
  force_ = file_.AddSeries("/reactions/force", 3 * np);
  torque_ = file_.AddSeries("/reactions/torque", 3 * np);
  file_.SetAttribute("/reactions/force", "shape",
                     std::string("[N, 3 * num_ports]: reshape to [N, num_ports, 3] "
                                 "(/model/reaction_ports)"));
  file_.SetAttribute("/reactions/torque", "shape",
                     std::string("[N, 3 * num_ports]: reshape to [N, num_ports, 3] "
                                 "(/model/reaction_ports)"));
  energy_ = file_.AddSeries("/energy", 5);
  file_.SetAttribute("/energy", "columns",
                     std::string("kinetic J, gravity potential J, elastic J, total J, "
                                 "dissipated power W"));
  residuals_ = file_.AddSeries("/residuals", 2);
  file_.SetAttribute("/residuals", "columns",
                     std::string("max |Phi| (m or rad), max |C v + Phi_t| (m/s or rad/s)"));
  if (L.num_elastic_total() > 0) {
    std::vector<std::string> flexible;
    std::vector<double> counts;
    for (int b = 1; b < system.num_bodies(); ++b)
      if (L.num_elastic(b)) {
        flexible.push_back(system.body(b).name);
        counts.push_back(L.num_elastic(b));
      }
    file_.WriteStrings("/model/flexible_bodies", flexible);
    file_.WriteDoubles("/model/num_modes", counts, {static_cast<std::uint64_t>(counts.size())});
    eta_ = file_.AddSeries("/state/eta", L.num_elastic_total());
    eta_dot_ = file_.AddSeries("/state/eta_dot", L.num_elastic_total());
    eta_ddot_ = file_.AddSeries("/state/eta_ddot", L.num_elastic_total());
    file_.SetAttribute("/state/eta", "columns",
                       std::string("modal coordinates of /model/flexible_bodies, body after "
                                   "body (/model/num_modes each) [kg^0.5 m]"));
  }
  std::vector<std::string> forces, sensors;
  for (const auto& f : system.force_elements()) forces.push_back(f->name());
  for (const auto& s : system.sensors()) sensors.push_back(s.name);
  file_.WriteStrings("/model/force_elements", forces);
  file_.WriteStrings("/model/sensors", sensors);
  if (!forces.empty()) {
    loads_ = file_.AddSeries("/forces/load", 6 * static_cast<int>(forces.size()));
    file_.SetAttribute("/forces/load", "columns",
                       std::string("per /model/force_elements: force x y z [N] and moment x y z "
                                   "[N m] on the first marker's body, in the second marker's "
                                   "axes (NaN: not reported)"));
  }
  if (const std::vector<std::string> outputs = ForceOutputChannels(system); !outputs.empty()) {
    file_.WriteStrings("/model/force_output_channels", outputs);
    file_.WriteStrings("/model/force_output_units", ForceOutputUnits(system));
    outputs_ = file_.AddSeries("/forces/outputs", static_cast<int>(outputs.size()));
    file_.SetAttribute("/forces/outputs", "columns",
                       std::string("per /model/force_output_channels, in /model/"
                                   "force_output_units: the force elements' outputs beyond "
                                   "their loads (a film bearing's h_min, p_max, ...; NaN: not "
                                   "evaluated)"));
  }
  if (!system.probes().empty()) {
    std::vector<std::string> names, channels;
    for (const auto& p : system.probes()) {
      names.push_back(p->name());
      for (const auto& c : p->channels()) channels.push_back(p->name() + "." + c);
    }
    file_.WriteStrings("/model/output_points", names);
    file_.WriteStrings("/model/output_point_channels", channels);
    probes_ = file_.AddSeries("/output_points", system.num_probe_channels());
    file_.SetAttribute("/output_points", "columns",
                       std::string("per /model/output_point_channels (mbs/flexible/"
                                   "output_points.h): u elastic displacement [m], v velocity "
                                   "[m/s], a acceleration [m/s^2] in the part's axes, n along "
                                   "the point's direction; power: integral of v_n^2 over a "
                                   "surface [m^4/s^2]; chord sensors (mbs/core/chord_sensor.h): "
                                   "dx dy dz deflection from the chord in the first end's axes "
                                   "[m], norm its length [m], s position along the chord [-]"));
  }
  if (!sensors.empty()) {
    sensors_ = file_.AddSeries("/sensors", 6 * static_cast<int>(sensors.size()));
    file_.SetAttribute("/sensors", "columns",
                       std::string("per /model/sensors: position of I in J's axes [m], "
                                   "rotation vector of R_J^T R_I [rad]"));
  }
  joint_elements_ = CoordinateJoints(system);
  std::vector<std::string> joints;
  for (int e : joint_elements_) joints.push_back(system.elements()[e].name);
  file_.WriteStrings("/model/joints", joints);
  if (!joints.empty()) {
    joints_ =
        file_.AddSeries("/joints", mbs::kJointCoordinateColumns * static_cast<int>(joints.size()));
    file_.SetAttribute("/joints", "columns",
                       std::string("per /model/joints: angle [rad] (unwrapped), angle rate "
                                   "[rad/s], travel [m], travel rate [m/s] (NaN: the joint has "
                                   "no such coordinate)"));
  }
  file_.Flush();
}

void ResultsWriter::Write(const mbs::Sample& s) {
  file_.Append(time_, &s.t);
  file_.Append(q_, s.q.data());
  if (loads_ >= 0) {
    const Eigen::MatrixXd rows = s.force_loads.transpose();  // column-major: 6 per element
    file_.Append(loads_, rows.data());
  }
  if (sensors_ >= 0) {
    const Eigen::MatrixXd rows = s.sensors.transpose();
    file_.Append(sensors_, rows.data());
  }
  if (joints_ >= 0) {
    Eigen::VectorXd row(mbs::kJointCoordinateColumns * joint_elements_.size());
    for (std::size_t k = 0; k < joint_elements_.size(); ++k)
      row.segment<mbs::kJointCoordinateColumns>(mbs::kJointCoordinateColumns * k) =
          s.joints.row(joint_elements_[k]).transpose();
    file_.Append(joints_, row.data());
  }
  if (probes_ >= 0) file_.Append(probes_, s.probes.data());
  if (outputs_ >= 0) file_.Append(outputs_, s.force_outputs.data());
  if (eta_ >= 0) {
    const mbs::StateLayout& L = system_.layout();
    const int rigid_q = L.nq() - L.num_elastic_total(), rigid_v = L.nv() - L.num_elastic_total();
    file_.Append(eta_, s.q.data() + rigid_q);
    file_.Append(eta_dot_, s.v.data() + rigid_v);
    file_.Append(eta_ddot_, s.vdot.data() + rigid_v);
  }
  file_.Append(v_, s.v.data());
  file_.Append(vdot_, s.vdot.data());
  const Eigen::VectorXd e = Euler(system_, s.q);
  file_.Append(euler_, e.data());
  file_.Append(lambda_, s.lambda.data());
  const int np = static_cast<int>(s.reactions.rows());
  EMB_CHECK(np == static_cast<int>(system_.reaction_ports().size()));
  Eigen::VectorXd f(3 * np), t(3 * np);
  for (int k = 0; k < np; ++k) {
    f.segment<3>(3 * k) = s.reactions.row(k).head<3>().transpose();
    t.segment<3>(3 * k) = s.reactions.row(k).tail<3>().transpose();
  }
  file_.Append(force_, f.data());
  file_.Append(torque_, t.data());
  const double en[5] = {s.energies.kinetic, s.energies.gravity, s.energies.elastic,
                        s.energies.total(), s.energies.dissipated_power};
  file_.Append(energy_, en);
  const double res[2] = {s.position_residual, s.velocity_residual};
  file_.Append(residuals_, res);
  file_.Flush();
}

void ResultsWriter::MarkStopped(const std::string& status, const std::string& reason,
                                double t_reached) {
  file_.SetAttribute("/", "status", status);
  file_.SetAttribute("/", "message", reason);
  file_.SetAttribute("/", "t_reached", t_reached);
  file_.Flush();
}

void ResultsWriter::Close() { file_.Close(); }

std::uint64_t ResultsWriter::BytesPerSample(const mbs::System& system) {
  const std::uint64_t nb = system.layout().num_moving();
  const std::uint64_t np = system.reaction_ports().size();
  const std::uint64_t doubles =
      1 + 7 * nb + 6 * nb + 6 * nb + 3 * nb + system.num_equations() + 6 * np + 5 + 2 +
      3 * system.layout().num_elastic_total() + 6 * system.force_elements().size() +
      6 * system.sensors().size() + mbs::kJointCoordinateColumns * CoordinateJoints(system).size() +
      static_cast<std::uint64_t>(system.num_probe_channels()) + ForceOutputChannels(system).size();
  return 8 * doubles;
}

void ResultsWriter::Finish(const mbs::RunResult& r) {
  file_.SetAttribute("/", "status", std::string(mbs::Name(r.status)));
  file_.SetAttribute("/", "message", r.message);
  file_.SetAttribute("/", "t_reached", r.t_reached);
  if (r.atol > 0.0) {  // a dynamic run: the tolerances and solver IDA actually used
    file_.SetAttribute("/", "atol", r.atol);
    file_.SetAttribute("/", "multiplier_atol", r.multiplier_atol);
    file_.SetAttribute("/", "linear_solver", std::string(Name(r.linear_solver)));
  }
  WriteEvents(r.events);
  file_.Flush();
}

void ResultsWriter::WriteEvents(const mbs::EventLog& log) {
  if (log.num_events == 0 && log.contacts.empty()) return;
  file_.SetAttribute("/", "num_events", static_cast<long long>(log.num_events));
  file_.SetAttribute("/", "num_restarts", static_cast<long long>(log.num_restarts));
  std::vector<double> rows;
  std::vector<std::string> names;
  for (const mbs::ContactRecord& c : log.contacts) {
    rows.insert(rows.end(),
                {static_cast<double>(c.element_index), static_cast<double>(c.side), c.t_onset,
                 c.impact_velocity, c.peak_force, c.t_separation, c.rebound_velocity});
    names.push_back(c.element);
  }
  file_.WriteDoubles("/events/contacts", rows, {log.contacts.size(), 7});
  file_.WriteStrings("/events/elements", names);
  file_.SetAttribute("/events/contacts", "columns",
                     std::string("force element index (/model/force_elements), side (+1 upper "
                                 "stop / drive flank, -1 lower / coast), t_onset [s], closing "
                                 "speed, peak force [N or N m], t_separation [s] (NaN: still "
                                 "closed), opening speed [m/s or rad/s of the coordinate]"));
}

void ResultsWriter::RecordSteadyState(const SteadyStateReport& report,
                                      const SteadyStateSettings& settings) {
  file_.SetAttribute("/", "steady_state_converged", static_cast<long long>(report.converged));
  file_.SetAttribute("/", "steady_state_cycles", static_cast<long long>(report.cycles));
  file_.SetAttribute("/", "steady_state_change", report.change);
  file_.SetAttribute("/", "steady_state_tolerance", settings.tolerance);
  file_.SetAttribute("/", "steady_state_worst_channel", report.worst_channel);
  file_.SetAttribute("/", "steady_state_cycle_start", report.cycle_start);
  file_.SetAttribute("/", "steady_state_cycle_end", report.cycle_end);
  file_.Flush();
}

void ResultsWriter::RecordTruncations(const std::vector<mbs::TruncationReport>& reports) {
  if (reports.empty()) return;
  std::vector<std::string> parts;
  std::vector<double> kept, available, error;
  for (const auto& r : reports) {
    parts.push_back(r.body);
    kept.push_back(r.num_kept);
    available.push_back(r.num_available);
    error.push_back(r.static_compliance_error);
  }
  const std::vector<std::uint64_t> dims{reports.size()};
  file_.WriteStrings("/model/basis_truncation/parts", parts);
  file_.WriteDoubles("/model/basis_truncation/kept_modes", kept, dims);
  file_.WriteDoubles("/model/basis_truncation/available_modes", available, dims);
  file_.WriteDoubles("/model/basis_truncation/static_compliance_error", error, dims);
  file_.SetAttribute("/model/basis_truncation/static_compliance_error", "meaning",
                     std::string("max |C_kept - C_full| / max |C_full|, C the static compliance "
                                 "at the part's loaded markers"));
  file_.Flush();
}

CsvWriter::CsvWriter(const std::string& path, const mbs::System& system,
                     const std::vector<std::string>& channels)
    : path_(path), channels_(system, channels) {
  out_.open(path);
  EMB_THROW_IF(!out_, "CSV file '" << path << "' cannot be created");
  out_ << "t";
  for (const auto& c : channels) out_ << "," << c;
  out_ << "\n";
  out_ << std::setprecision(12);
  out_.flush();
  EMB_THROW_IF(!out_, "CSV file '" << path << "': write failed (disk full?)");
}

void CsvWriter::Close() {
  out_.close();
  EMB_THROW_IF(!out_, "CSV file '" << path_ << "': closing failed (disk full?)");
}

void CsvWriter::Write(const mbs::Sample& s) {
  out_ << s.t;
  for (int k = 0; k < channels_.size(); ++k) out_ << "," << channels_.Value(s, k);
  out_ << "\n";
  out_.flush();
  EMB_THROW_IF(!out_, "CSV file '" << path_ << "': write failed (disk full?)");
}

}  // namespace emb::results
