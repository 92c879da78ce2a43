#include "libemb/results/channels.h"

#include <algorithm>

#include "libemb/common/did_you_mean.h"
#include "libemb/common/error.h"
#include "libemb/mbs/analysis/joint_coordinates.h"
#include "libemb/mbs/core/rotation.h"

namespace emb::results {
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
// Index of channel "<probe>.<channel>" in Sample::probes, or -1.
int ProbeChannel(const mbs::System& system, const std::string& name) {
  int offset = 0;
  for (const auto& p : system.probes()) {
    for (int k = 0; k < p->num_channels(); ++k)
      if (name == p->name() + "." + p->channels()[static_cast<std::size_t>(k)]) return offset + k;
    offset += p->num_channels();
  }
  return -1;
}

// Index of channel "<force element>.<output>" in Sample::force_outputs, or -1.
int ForceOutputChannel(const mbs::System& system, const std::string& name) {
  const std::vector<std::string> names = ForceOutputChannels(system);
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? -1 : static_cast<int>(it - names.begin());
}

int SensorIndex(const mbs::System& system, const std::string& name) {
  for (std::size_t k = 0; k < system.sensors().size(); ++k)
    if (system.sensors()[k].name == name) return static_cast<int>(k);
  return -1;
}

}  // namespace

std::vector<std::string> ForceOutputChannels(const mbs::System& system) {
  std::vector<std::string> n;
  for (const auto& f : system.force_elements())
    for (const auto& o : f->outputs()) n.push_back(f->name() + "." + o.name);
  return n;
}

std::vector<std::string> ForceOutputUnits(const mbs::System& system) {
  std::vector<std::string> u;
  for (const auto& f : system.force_elements())
    for (const auto& o : f->outputs()) u.push_back(o.unit);
  return u;
}

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
  for (const auto& f : system.force_elements()) {
    if (!f->reports_load()) continue;  // CalcLoad gives nothing (NaN in the results)
    for (const char* q : {"F", "T"})
      for (const char* c : xyz) n.push_back(f->name() + "." + q + "." + c);
    n.push_back(f->name() + ".F.norm");
  }
  for (const auto& s : system.sensors())
    for (const char* c : {"dx", "dy", "dz", "rx", "ry", "rz"}) n.push_back(s.name + "." + c);
  for (const auto& e : system.elements()) {
    if (mbs::HasJointCoordinate(e, mbs::JointCoordinate::kRotation))
      for (const char* c : {"angle", "angle_rate"}) n.push_back(e.name + "." + c);
    if (mbs::HasJointCoordinate(e, mbs::JointCoordinate::kTranslation))
      for (const char* c : {"travel", "travel_rate"}) n.push_back(e.name + "." + c);
  }
  for (const auto& p : system.probes())
    for (const auto& c : p->channels()) n.push_back(p->name() + "." + c);
  for (const auto& c : ForceOutputChannels(system)) n.push_back(c);
  for (const char* c : {"kinetic", "gravity", "elastic", "total"})
    n.push_back(std::string("energy.") + c);
  n.push_back("residual.position");
  n.push_back("residual.velocity");
  return n;
}

ChannelSet::ChannelSet(const mbs::System& system, const std::vector<std::string>& names)
    : system_(system), names_(names) {
  const std::vector<std::string> valid = ValidChannelNames(system);
  for (const auto& c : names) {
    const auto it = std::find(valid.begin(), valid.end(), c);
    const int fe = ForceElementIndex(system, c.substr(0, c.find('.')));
    EMB_THROW_IF(it == valid.end() && fe >= 0 && !system.force_elements()[fe]->reports_load(),
                 "output channel '" << c << "': force element '"
                                    << system.force_elements()[fe]->name()
                                    << "' reports no load (F/T channels exist for bushings and "
                                       "journal bearings)");
    if (it == valid.end() && c.find('.') == c.rfind('.') &&
        ElementIndex(system, c.substr(0, c.find('.'))) >= 0) {  // <joint>.<coordinate>
      const mbs::ConstraintElement& e =
          system.elements()[ElementIndex(system, c.substr(0, c.find('.')))];
      std::string has;
      for (const auto& v : valid)
        if (v.rfind(e.name + ".", 0) == 0 && v.find('.', e.name.size() + 1) == std::string::npos)
          has += (has.empty() ? "" : ", ") + v;
      EMB_THROW(InputError, "output channel '"
                                << c << "': '" << e.name << "' has "
                                << (has.empty() ? std::string("no coordinate "
                                                              "channels (only revolute, "
                                                              "cylindrical and translational "
                                                              "joints have them)")
                                                : has));
    }
    EMB_THROW_IF(it == valid.end(), "output channel '" << c << "' is unknown"
                                                       << DidYouMean(c, valid)
                                                       << " (channels look like crank.p.x, "
                                                          "main.F.y, energy.total)");
    const auto dot1 = c.find('.');
    const auto dot2 = c.rfind('.');
    const std::string owner = c.substr(0, dot1);
    const std::string quantity = c.substr(dot1 + 1, dot2 - dot1 - 1);
    const std::string comp = c.substr(dot2 + 1);
    Channel ch{Channel::Kind::kPosition, 0, 0};
    const std::vector<std::string> comps = {"x", "y", "z"};
    auto comp_index = [&](const std::vector<std::string>& list) {
      return static_cast<int>(std::find(list.begin(), list.end(), comp) - list.begin());
    };
    if (owner == "energy") {
      ch = {Channel::Kind::kEnergy, 0, comp_index({"kinetic", "gravity", "elastic", "total"})};
    } else if (owner == "residual") {
      ch = {Channel::Kind::kResidual, 0, comp_index({"position", "velocity"})};
    } else if (const int probe = ProbeChannel(system, c); probe >= 0) {
      ch = {Channel::Kind::kProbe, probe, 0};
    } else if (const int out = ForceOutputChannel(system, c); out >= 0) {
      ch = {Channel::Kind::kForceOutput, out, 0};
    } else if (SensorIndex(system, owner) >= 0) {
      ch = {Channel::Kind::kSensor, SensorIndex(system, owner),
            comp_index({"dx", "dy", "dz", "rx", "ry", "rz"})};
    } else if (dot1 == dot2 && ElementIndex(system, owner) >= 0) {  // <joint>.angle, ...
      ch = {Channel::Kind::kJoint, ElementIndex(system, owner),
            comp_index({"angle", "angle_rate", "travel", "travel_rate"})};
    } else if (quantity == "F" && comp == "norm") {
      ch = {Channel::Kind::kForceElementNorm, ForceElementIndex(system, owner), 0};
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
}

double ChannelSet::Value(const mbs::Sample& s, int k) const {
  const auto& L = system_.layout();
  const Channel& c = channels_[static_cast<std::size_t>(k)];
  switch (c.kind) {
    case Channel::Kind::kPosition:
      return s.q[L.position(c.index) + c.component];
    case Channel::Kind::kVelocity:
      return s.v[L.velocity(c.index) + c.component];
    case Channel::Kind::kAcceleration:
      return s.vdot[L.velocity(c.index) + c.component];
    case Channel::Kind::kOmega: {
      const Eigen::Matrix3d R = mbs::RotationFromQuaternion(s.q.segment<4>(L.quaternion(c.index)));
      return (R * s.v.segment<3>(L.angular_velocity(c.index)))[c.component];
    }
    case Channel::Kind::kEuler:
      return mbs::Euler313FromRotation(
          mbs::RotationFromQuaternion(s.q.segment<4>(L.quaternion(c.index))))[c.component];
    case Channel::Kind::kForceElement:
      return s.force_loads(c.index, c.component);
    case Channel::Kind::kForceElementNorm:
      return s.force_loads.row(c.index).head<3>().norm();
    case Channel::Kind::kSensor:
      return s.sensors(c.index, c.component);
    case Channel::Kind::kJoint:
      return s.joints(c.index, c.component);
    case Channel::Kind::kProbe:
      return s.probes[c.index];
    case Channel::Kind::kForceOutput:
      return s.force_outputs[c.index];
    case Channel::Kind::kForce:
      return s.reactions(c.index, c.component);
    case Channel::Kind::kTorque:
      return s.reactions(c.index, 3 + c.component);
    case Channel::Kind::kEnergy: {
      const double e[4] = {s.energies.kinetic, s.energies.gravity, s.energies.elastic,
                           s.energies.total()};
      return e[c.component];
    }
    case Channel::Kind::kResidual:
      return c.component == 0 ? s.position_residual : s.velocity_residual;
  }
  return 0.0;
}

}  // namespace emb::results
