#pragma once
/// @file
/// Scene readers for engine parts (internal to emb_scene): the `journal-bearing` force
/// element and the `cylinder_pressure` function.

#include <yaml-cpp/yaml.h>

#include <string>

#include "libemb/mbs/core/system.h"
#include "libemb/mbs/core/time_function.h"
#include "libemb/scene/yaml_reader.h"

namespace emb::scene {

/// {name, type: journal-bearing, i, j, radius, length, clearance, viscosity}: adds a
/// mbs::JournalBearing. `r` has read name and type.
void ReadJournalBearing(MapReader& r, const std::string& name, mbs::System* sys);

/// {name, type: film-bearing, i, j, radius, length, clearance, viscosity, grid_circumferential,
///  grid_axial, cavitation, bulk_modulus, oil_holes: [{angle, axial_position, diameter,
///  supply_pressure}], grooves: [{axial_position, width, start_angle, angular_extent,
///  supply_pressure}]}: adds a mbs::FilmBearing (finite-width Reynolds). `r` has read name
/// and type.
void ReadFilmBearing(MapReader& r, const std::string& name, mbs::System* sys);

/// {name, type: torsional-damper, hub, ring_mass, ring_inertia, stiffness, damping}: adds an
/// engine::AddTorsionalDamper ring (its body, marker, joint and spring-damper) on marker `hub`.
/// Instead of stiffness/damping (Kelvin-Voigt) a frequency-dependent `rubber:` map, either
/// {static_stiffness, arms: [{stiffness, relaxation_time}, ...]} or the one-arm fit
/// {dynamic_stiffness, loss_factor, frequency_hz} (engine::FitZenerAtLossPeak), both with
/// optional band_hz and junction_error (the junction rings' band and error bound).
/// @throws InputError naming the key for both forms at once, keys of both rubber forms,
/// unknown keys, non-positive values, a loss factor outside (0, kMaxZenerLossFactor].
/// Returns a note for a rubber damper (its junction rings and the bound up to band_hz), else "".
std::string ReadTorsionalDamper(MapReader& r, const std::string& name, mbs::System* sys);

/// {bore, stroke, rod, compression_ratio, intake_pressure, exhaust_pressure,
///  crankcase_pressure, polytropic_exponent, fired, combustion_start_deg,
///  combustion_duration_deg, wiebe_a, wiebe_m, heat_released | peak_pressure,
///  exhaust_opening_deg, blowdown_deg, step_deg, output: force | pressure}
/// (mbs::CylinderPressureSettings; defaults there): the piston force (p - p_crankcase) A [N]
/// or the pressure p [Pa] as a function of the crank angle [deg] from firing TDC.
mbs::TimeFunction ReadCylinderPressure(const YAML::Node& n, const std::string& file,
                                       const std::string& what);

}  // namespace emb::scene
