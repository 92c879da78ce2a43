#pragma once
/// @file
/// Events of a dynamic analysis: the force elements' event functions (contact onset and
/// separation of impact elements, force peaks) located by IDA's root finding through the
/// GGL DAE (ggl_dae.h, DaeProblem::CalcRoots), handed to the elements (ForceElement::
/// HandleEvent), and a clean restart of the integrator when an element switched its force
/// law: consistent accelerations and multipliers at the event time from
/// [M C^T; C 0] [v'; lambda] = [f; gamma] with the new law (assembly.h), mu = 0, then
/// IDAReInit (BDF order 1). Between two events every force is smooth, so no step of the
/// integrator straddles a contact closing or opening.
///
/// The run keeps a list of contacts: per element and closing, the time and closing speed,
/// the largest force (at the onset and at every located force peak, so the maximum of the
/// force law over the contact exactly, to the root-finding tolerance) and the time and
/// opening speed of the separation.

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace emb::mbs {

class System;
class GglDae;

/// One contact of an impact element, from closing to opening.
struct ContactRecord {
  std::string element;          ///< the force element's name
  int element_index{-1};        ///< in System::force_elements()
  int side{0};                  ///< +1 upper stop / drive flank, -1 lower stop / coast flank
  double t_onset{0.0};          ///< [s]
  double impact_velocity{0.0};  ///< closing speed [m/s or rad/s of the element's coordinate]
  double peak_force{0.0};       ///< largest contact force [N or N m]
  /// [s]; NaN while the contact is still closed at the end of the run.
  double t_separation{0.0};
  double rebound_velocity{0.0};  ///< opening speed [m/s or rad/s]; NaN while closed
};

/// The events of one run.
struct EventLog {
  long num_events{0};    ///< integrator stops at a sign change of an event function
  long num_restarts{0};  ///< of those, the ones where a force law switched
  std::vector<ContactRecord> contacts;
  std::vector<int> open;  ///< per force element: index into contacts of its open contact, or -1
};

/// Hands the event found at time t (state y, y' of the GGL DAE; root_directions from the
/// integrator) to the force elements whose event functions changed sign, records their
/// notes in `log`, and returns true if the integrator must restart (an element switched).
bool HandleEvents(const System& system, const GglDae& dae, double t, const Eigen::VectorXd& y,
                  const Eigen::VectorXd& yp, const std::vector<int>& root_directions,
                  EventLog* log);

/// Asks every force element with events to settle its discrete state at (t, q, v, v')
/// (ForceElement::SettleEventState), records their notes, and returns true if one switched
/// (then the accelerations must be solved again and the elements asked again).
bool SettleEventStates(const System& system, const GglDae& dae, double t, const Eigen::VectorXd& q,
                       const Eigen::VectorXd& v, const Eigen::VectorXd& vdot, EventLog* log);

}  // namespace emb::mbs
