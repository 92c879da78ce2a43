#pragma once
/// @file
/// Named scalar channels of a run's samples, shared by the CSV writer and the steady-state
/// monitor: <body>.p.{x,y,z} (CM position, m), <body>.v.{x,y,z} (m/s), <body>.a.{x,y,z}
/// (m/s^2), <body>.omega.{x,y,z} (rad/s, in W), <body>.euler.{psi,theta,phi} (rad),
/// <element>.F.{x,y,z} and <element>.T.{x,y,z} (reactions, joint axes; for a coupler at its
/// first joint), <coupler>.F2.{x,y,z} and <coupler>.T2.{x,y,z} (a coupler's reaction at its
/// second joint), <force element>.F.{x,y,z} and .T.{x,y,z} (its load, ForceElement::CalcLoad),
/// <force element>.F.norm (|F|), <sensor>.{dx,dy,dz,rx,ry,rz}, <joint>.angle (rad,
/// unwrapped) and <joint>.angle_rate (rad/s) of revolute and cylindrical joints,
/// <joint>.travel (m) and <joint>.travel_rate (m/s) of translational and cylindrical joints
/// (mbs/analysis/joint_coordinates.h), <output point>.<channel>
/// (probes: u|v|a.{x,y,z,n}, power; mbs/flexible/output_points.h), <chord sensor>.dx|dy|dz|
/// norm|s (probes, mbs/core/chord_sensor.h),
/// <force element>.<output> (ForceElement::outputs: a film bearing's h_min, p_max, ...),
/// energy.{kinetic,gravity,elastic,total}, residual.{position,velocity}.

#include <string>
#include <vector>

#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/core/system.h"

namespace emb::results {

/// Every channel name `system` has.
std::vector<std::string> ValidChannelNames(const mbs::System& system);

/// The force elements' outputs (ForceElement::outputs) as channels "<element>.<name>" and
/// their units, in Sample::force_outputs order.
std::vector<std::string> ForceOutputChannels(const mbs::System& system);
std::vector<std::string> ForceOutputUnits(const mbs::System& system);

class ChannelSet {
 public:
  /// @throws InputError naming the first unknown channel (with a did-you-mean).
  ChannelSet(const mbs::System& system, const std::vector<std::string>& names);
  int size() const { return static_cast<int>(channels_.size()); }
  const std::vector<std::string>& names() const { return names_; }
  /// Value of channel k at a sample.
  double Value(const mbs::Sample& sample, int k) const;

 private:
  struct Channel {
    enum class Kind {
      kPosition,
      kVelocity,
      kAcceleration,
      kOmega,
      kEuler,
      kForce,
      kTorque,
      kEnergy,
      kResidual,
      kForceElement,
      kForceElementNorm,
      kSensor,
      kJoint,
      kProbe,
      kForceOutput
    } kind;
    int index;      // body, reaction port, force element, sensor or joint element
    int component;  // 0..5
  };
  const mbs::System& system_;
  std::vector<std::string> names_;
  std::vector<Channel> channels_;
};

}  // namespace emb::results
