#include "libemb/tribology/reynolds_bearing.h"

#include <cmath>
#include <numbers>
#include <sstream>
#include <utility>

#include "libemb/common/error.h"

namespace emb::tribology {
namespace {

constexpr int kMinCircumferential = 8;
constexpr int kMinAxialIntervals = 2;

// The geometry checks run before any member that uses the geometry is built.
const ReynoldsBearingParameters& Checked(const ReynoldsBearingParameters& p,
                                         const std::string& who) {
  auto positive = [&](double v, const char* key) {
    EMB_THROW_IF(!(std::isfinite(v) && v > 0.0),
                 who << ": expected a positive " << key << ", got " << v << " m");
  };
  positive(p.radius, "radius");
  positive(p.length, "length");
  positive(p.clearance, "clearance");
  EMB_THROW_IF(p.clearance >= p.radius, who << ": expected a clearance smaller than the radius, "
                                               "got c = " << p.clearance << " m, R = "
                                            << p.radius << " m");
  EMB_THROW_IF(p.grid.circumferential < kMinCircumferential,
               who << ": expected grid.circumferential >= " << kMinCircumferential << ", got "
                   << p.grid.circumferential);
  EMB_THROW_IF(p.grid.axial < kMinAxialIntervals,
               who << ": expected grid.axial >= " << kMinAxialIntervals << " intervals, got "
                   << p.grid.axial);
  return p;
}

}  // namespace

std::string ReynoldsBearing::BeyondViscosityLawMessage() const {
  std::ostringstream o;
  o << who_ << ": the film pressure exceeds the pressure-viscosity law's range (the reduced "
    << "pressure reached its limit " << lubricant_.reduced_pressure_limit()
    << " Pa; with rigid surfaces a piezoviscous film has no solution beyond it: an isoviscous "
       "oil, without pressure_law, carries such loads)";
  return o.str();
}

ReynoldsBearing::ReynoldsBearing(std::string name, const ReynoldsBearingParameters& p)
    : name_(std::move(name)),
      who_("bearing '" + name_ + "'"),
      p_(Checked(p, who_)),
      grid_(p.radius, p.length, p.grid),
      lubricant_(p.lubricant, who_),
      supply_(MarkSupplyNodes(grid_, p.oil_holes, p.grooves, who_)) {
  EMB_THROW_IF(!(p.bore_tilt.allFinite()),
               who_ << ": expected a finite bore_tilt, got (" << p.bore_tilt.transpose() << ")");
  const double edge_offset = p.bore_tilt.norm() * 0.5 * p.length;
  EMB_THROW_IF(edge_offset >= p.clearance,
               who_ << ": the bore's misalignment takes up the clearance at an edge: expected "
                       "|bore_tilt| L/2 < c = " << p.clearance << " m, got " << edge_offset
                    << " m");
  EMB_THROW_IF(!(std::isfinite(p.pressure_scale) && p.pressure_scale > 0.0),
               who_ << ": expected a positive pressure_scale, got " << p.pressure_scale << " Pa");
  EMB_THROW_IF(!(std::isfinite(p.bulk_modulus) && p.bulk_modulus > 0.0),
               who_ << ": expected a positive bulk_modulus, got " << p.bulk_modulus << " Pa");
  EMB_THROW_IF(!(p.switch_width >= 0.0 && p.switch_width <= 0.5),
               who_ << ": expected a switch_width in [0, 0.5], got " << p.switch_width);
  EMB_THROW_IF(p.switch_width > 0.0 && p.complementarity != ComplementaritySolver::kElrodAdamsSwitch,
               who_ << ": a smoothed switch (switch_width " << p.switch_width
                    << ") expected the Elrod-Adams switch solver, got Fischer-Burmeister");
  EMB_THROW_IF(!(std::isfinite(p.film_floor) && p.film_floor > 0.0),
               who_ << ": expected a positive film_floor, got " << p.film_floor);
  EMB_THROW_IF(p.max_iterations < 1,
               who_ << ": expected max_iterations >= 1, got " << p.max_iterations);
  auto reduced = [&](double ps, const std::string& key) {
    const double psi = lubricant_.ReducedPressure(ps);
    EMB_THROW_IF(!(psi < lubricant_.reduced_pressure_limit()),
                 who_ << ": " << key << ": expected a supply pressure within the "
                      << "pressure-viscosity law's range, got " << ps << " Pa");
    return psi;
  };
  // Features are numbered holes first, then grooves (supply_features.h).
  for (size_t f = 0; f < supply_.pressure.size(); ++f) {
    const size_t holes = p.oil_holes.size();
    const std::string key = f < holes ? "oil_holes[" + std::to_string(f) + "]"
                                      : "grooves[" + std::to_string(f - holes) + "]";
    supply_u_.push_back(reduced(supply_.pressure[f], key + ".supply_pressure") /
                        p.pressure_scale);
  }
  CheckJournalOilHoles(grid_, p.journal_oil_holes, who_);
  EMB_THROW_IF(!(std::isfinite(p.journal_feed_ratio) && p.journal_feed_ratio > 0.0),
               who_ << ": expected a positive journal_feed_ratio, got " << p.journal_feed_ratio);
  for (size_t h = 0; h < p.journal_oil_holes.size(); ++h)
    journal_psi_.push_back(reduced(p.journal_oil_holes[h].supply_pressure,
                                   "journal_oil_holes[" + std::to_string(h) + "].supply_pressure"));
  journal_conductance_ = p.journal_feed_ratio * std::numbers::pi * std::pow(p.clearance, 3) /
                         (6.0 * lubricant_.ambient_viscosity());
  if (p.asperity_contact) contact_.emplace(*p.asperity_contact, who_);
}

}  // namespace emb::tribology
