#include "libemb/results/results_writer.h"

#include <iomanip>

#include "libemb/common/did_you_mean.h"
#include "libemb/common/error.h"
#include "libemb/mbs/core/rotation.h"

namespace emb::scene {
namespace {

std::vector<std::string> ElementTypes(const mbs::System& s) {
  std::vector<std::string> t;
  for (const auto& e : s.elements())
    t.push_back(e.kind == mbs::ElementKind::kJoint    ? mbs::Name(e.type)
                : e.kind == mbs::ElementKind::kMotion ? "motion"
                                                      : "coupler");
  return t;
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
  file_.SetAttribute("/", "version", 3LL);
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
  if (!sensors.empty()) {
    sensors_ = file_.AddSeries("/sensors", 6 * static_cast<int>(sensors.size()));
    file_.SetAttribute("/sensors", "columns",
                       std::string("per /model/sensors: position of I in J's axes [m], "
                                   "rotation vector of R_J^T R_I [rad]"));
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
  if (eta_ >= 0) {
    const mbs::StateLayout& L = system_.layout();
    const int rigid_q = L.nq() - L.num_elastic_total(), rigid_v = L.nv() - L.num_elastic_total();
    file_.Append(eta_, s.q.data() + rigid_q);
    file_.Append(eta_dot_, s.v.data() + rigid_v);
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
  const std::uint64_t doubles = 1 + 7 * nb + 6 * nb + 6 * nb + 3 * nb + system.num_equations() +
                                6 * np + 5 + 2 + 2 * system.layout().num_elastic_total() +
                                6 * system.force_elements().size() + 6 * system.sensors().size();
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
  file_.Flush();
}

namespace {

int ElementIndex(const mbs::System& system, const std::string& name) {
  for (std::size_t k = 0; k < system.elements().size(); ++k)
    if (system.elements()[k].name == name) return static_cast<int>(k);
  return -1;
}
int ForceElementIndex(const mbs::System& system, const std::string& name) {
  for (std::size_t k = 0; k < system.force_elements().size(); ++k)
    if (system.force_elements()[k]->name() == name) return static_cast<int>(k);
  return -1;
}
int SensorIndex(const mbs::System& system, const std::string& name) {
  for (std::size_t k = 0; k < system.sensors().size(); ++k)
    if (system.sensors()[k].name == name) return static_cast<int>(k);
  return -1;
}

}  // namespace

std::vector<std::string> ValidChannelNames(const mbs::System& system) {
  std::vector<std::string> n;
  const char* xyz[] = {"x", "y", "z"};
  for (int b = 1; b < system.num_bodies(); ++b) {
    const std::string& name = system.body(b).name;
    for (const char* q : {"p", "v", "a", "omega"})
      for (const char* c : xyz) n.push_back(name + "." + q + "." + c);
    for (const char* c : {"psi", "theta", "phi"}) n.push_back(name + ".euler." + c);
  }
  for (const auto& e : system.elements())
    for (const char* q : {"F", "T"})
      for (const char* c : xyz) n.push_back(e.name + "." + q + "." + c);
  for (const auto& e : system.elements())
    if (e.kind == mbs::ElementKind::kCoupler)
      for (const char* q : {"F2", "T2"})
        for (const char* c : xyz) n.push_back(e.name + "." + q + "." + c);
  for (const auto& f : system.force_elements())
    if (f->reports_load())
      for (const char* q : {"F", "T"})
        for (const char* c : xyz) n.push_back(f->name() + "." + q + "." + c);
  for (const auto& s : system.sensors())
    for (const char* c : {"dx", "dy", "dz", "rx", "ry", "rz"}) n.push_back(s.name + "." + c);
  for (const char* c : {"kinetic", "gravity", "elastic", "total"})
    n.push_back(std::string("energy.") + c);
  n.push_back("residual.position");
  n.push_back("residual.velocity");
  return n;
}

void CheckChannels(const mbs::System& system, const std::vector<std::string>& channels) {
  const std::vector<std::string> valid = ValidChannelNames(system);
  for (const auto& c : channels) {
    const auto it = std::find(valid.begin(), valid.end(), c);
    const int k = ForceElementIndex(system, c.substr(0, c.find('.')));
    EMB_THROW_IF(it == valid.end() && k >= 0 && !system.force_elements()[k]->reports_load(),
                 "output channel '" << c << "': force element '"
                                    << system.force_elements()[k]->name()
                                    << "' reports no load (F/T channels exist for bushings and "
                                       "journal bearings)");
    EMB_THROW_IF(it == valid.end(), "output channel '" << c << "' is unknown"
                                                       << DidYouMean(c, valid)
                                                       << " (channels look like crank.p.x, "
                                                          "main.F.y, energy.total)");
  }
}

CsvWriter::CsvWriter(const std::string& path, const mbs::System& system,
                     const std::vector<std::string>& channels)
    : system_(system), path_(path) {
  CheckChannels(system, channels);
  for (const auto& c : channels) {
    const auto dot1 = c.find('.');
    const auto dot2 = c.rfind('.');
    const std::string owner = c.substr(0, dot1);
    const std::string quantity = c.substr(dot1 + 1, dot2 - dot1 - 1);
    const std::string comp = c.substr(dot2 + 1);
    Channel ch{Channel::Kind::kPosition, 0, 0};
    const std::vector<std::string> comps = {"x", "y", "z"};
    auto comp_index = [&](const std::vector<std::string>& names) {
      return static_cast<int>(std::find(names.begin(), names.end(), comp) - names.begin());
    };
    if (owner == "energy") {
      ch = {Channel::Kind::kEnergy, 0, comp_index({"kinetic", "gravity", "elastic", "total"})};
    } else if (owner == "residual") {
      ch = {Channel::Kind::kResidual, 0, comp_index({"position", "velocity"})};
    } else if (SensorIndex(system, owner) >= 0) {
      ch = {Channel::Kind::kSensor, SensorIndex(system, owner),
            comp_index({"dx", "dy", "dz", "rx", "ry", "rz"})};
    } else if ((quantity == "F" || quantity == "T") && ElementIndex(system, owner) < 0) {
      ch = {Channel::Kind::kForceElement, ForceElementIndex(system, owner),
            comp_index(comps) + (quantity == "T" ? 3 : 0)};
    } else if (quantity == "F" || quantity == "T") {
      ch = {quantity == "F" ? Channel::Kind::kForce : Channel::Kind::kTorque,
            system.FindElement(owner), comp_index(comps)};
    } else if (quantity == "F2" || quantity == "T2") {
      ch = {quantity == "F2" ? Channel::Kind::kForce : Channel::Kind::kTorque,
            system.second_reaction_port(system.FindElement(owner)), comp_index(comps)};
    } else {
      const int b = system.FindBody(owner);
      if (quantity == "euler")
        ch = {Channel::Kind::kEuler, b, comp_index({"psi", "theta", "phi"})};
      else if (quantity == "p")
        ch = {Channel::Kind::kPosition, b, comp_index(comps)};
      else if (quantity == "v")
        ch = {Channel::Kind::kVelocity, b, comp_index(comps)};
      else if (quantity == "a")
        ch = {Channel::Kind::kAcceleration, b, comp_index(comps)};
      else
        ch = {Channel::Kind::kOmega, b, comp_index(comps)};
    }
    channels_.push_back(ch);
  }
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
  const auto& L = system_.layout();
  out_ << s.t;
  for (const Channel& c : channels_) {
    double v = 0.0;
    switch (c.kind) {
      case Channel::Kind::kPosition:
        v = s.q[L.position(c.index) + c.component];
        break;
      case Channel::Kind::kVelocity:
        v = s.v[L.velocity(c.index) + c.component];
        break;
      case Channel::Kind::kAcceleration:
        v = s.vdot[L.velocity(c.index) + c.component];
        break;
      case Channel::Kind::kOmega: {
        const Eigen::Matrix3d R =
            mbs::RotationFromQuaternion(s.q.segment<4>(L.quaternion(c.index)));
        v = (R * s.v.segment<3>(L.angular_velocity(c.index)))[c.component];
        break;
      }
      case Channel::Kind::kEuler:
        v = mbs::Euler313FromRotation(
            mbs::RotationFromQuaternion(s.q.segment<4>(L.quaternion(c.index))))[c.component];
        break;
      case Channel::Kind::kForceElement:
        v = s.force_loads(c.index, c.component);
        break;
      case Channel::Kind::kSensor:
        v = s.sensors(c.index, c.component);
        break;
      case Channel::Kind::kForce:
        v = s.reactions(c.index, c.component);
        break;
      case Channel::Kind::kTorque:
        v = s.reactions(c.index, 3 + c.component);
        break;
      case Channel::Kind::kEnergy: {
        const double e[4] = {s.energies.kinetic, s.energies.gravity, s.energies.elastic,
                             s.energies.total()};
        v = e[c.component];
        break;
      }
      case Channel::Kind::kResidual:
        v = c.component == 0 ? s.position_residual : s.velocity_residual;
        break;
    }
    out_ << "," << v;
  }
  out_ << "\n";
  out_.flush();
  EMB_THROW_IF(!out_, "CSV file '" << path_ << "': write failed (disk full?)");
}

}  // namespace emb::scene
