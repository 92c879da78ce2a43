#include "libemb/scene/engine_parts.h"

#include <cmath>
#include <memory>
#include <sstream>
#include <vector>

#include "libemb/common/did_you_mean.h"
#include "libemb/common/error.h"
#include "libemb/engine/cylinder_pressure.h"
#include "libemb/engine/film_bearing.h"
#include "libemb/engine/journal_bearing.h"
#include "libemb/engine/torsional_damper.h"

namespace emb::scene {

void ReadJournalBearing(MapReader& r, const std::string& name, mbs::System* sys) {
  const int i = sys->FindMarker(r.GetString("i")), j = sys->FindMarker(r.GetString("j"));
  mbs::JournalBearingParameters p;
  p.radius = r.GetDouble("radius", NumberRange::Positive("m"));
  p.length = r.GetDouble("length", NumberRange::Positive("m"));
  p.clearance = r.GetDouble("clearance", NumberRange::Positive("m"));
  p.viscosity = r.GetDouble("viscosity", NumberRange::Positive("Pa s"));
  sys->AddForceElement(std::make_shared<mbs::JournalBearing>(name, i, j, p));
}

namespace {

tribology::CavitationModel ParseCavitation(const std::string& word, const std::string& what) {
  using M = tribology::CavitationModel;
  if (word == "mass-conserving") return M::kMassConserving;
  if (word == "reynolds") return M::kReynolds;
  if (word == "half-sommerfeld") return M::kHalfSommerfeld;
  if (word == "full-sommerfeld") return M::kFullSommerfeld;
  EMB_THROW(InputError, what << " cavitation: expected mass-conserving, reynolds, half-sommerfeld "
                               "or full-sommerfeld, got '"
                            << word << "'"
                            << DidYouMean(word, {"mass-conserving", "reynolds", "half-sommerfeld",
                                                 "full-sommerfeld"}));
}

// Each entry of the list at `key` (absent: none) as a MapReader of table `table`.
template <class Read>
void ReadEach(MapReader& r, const std::string& key, const std::string& what,
              const std::string& table, Read read) {
  if (!r.Has(key)) {
    r.Optional(key);
    return;
  }
  const YAML::Node list = r.Require(key);
  if (!list.IsSequence())
    EMB_THROW(InputError, Where(r.file(), list) << ": " << what << " " << key
                                                << ": expected a list of maps");
  for (std::size_t k = 0; k < list.size(); ++k) {
    MapReader e(list[k], r.file(), what + " " + key + "[" + std::to_string(k) + "]", table);
    read(e);
    e.Finish();
  }
}

}  // namespace

namespace {

// A film bearing's oil: `viscosity` (constant), or a `lubricant:` map with a viscosity-
// temperature law at an effective temperature and an optional pressure-viscosity law
// (tribology/lubricant.h).
void ReadLubricant(MapReader& r, const std::string& what, tribology::LubricantParameters* l) {
  using T = tribology::ViscosityTemperatureLaw;
  using P = tribology::PressureViscosityLaw;
  const bool constant = r.Has("viscosity"), map = r.Has("lubricant");
  EMB_THROW_IF(constant == map, Where(r.file(), r.node())
                                    << ": " << what
                                    << ": expected either `viscosity` (constant) or a "
                                       "`lubricant:` map, got "
                                    << (constant ? "both" : "neither"));
  if (constant) {
    r.Optional("lubricant");
    l->viscosity = r.GetDouble("viscosity", NumberRange::Positive("Pa s"));
    return;
  }
  r.Optional("viscosity");
  const YAML::Node n = r.Require("lubricant");
  EMB_THROW_IF(!n.IsMap(), Where(r.file(), n) << ": " << what << " lubricant: expected a map");
  MapReader m(n, r.file(), what + " lubricant", "forces: film-bearing lubricant");
  const std::string law = m.GetString("temperature_law", "constant");
  // An effective oil temperature in kelvin: 200-600 K spans every engine oil's use (a value
  // in Celsius, such as 110, is refused here rather than read as 110 K).
  const NumberRange kelvin = NumberRange::Closed(200.0, 600.0, "K");
  if (law == "constant") {
    l->temperature_law = T::kConstant;
    l->viscosity = m.GetDouble("viscosity", NumberRange::Positive("Pa s"));
  } else if (law == "vogel") {
    l->temperature_law = T::kVogel;
    l->vogel_a = m.GetDouble("vogel_a", NumberRange::Positive("Pa s"));
    l->vogel_b = m.GetDouble("vogel_b", NumberRange::Positive("K"));
    l->vogel_c = m.GetDouble("vogel_c", NumberRange::Finite("K"));
    l->temperature = m.GetDouble("temperature", kelvin);
  } else if (law == "walther") {
    l->temperature_law = T::kWalther;
    l->nu_40 = m.GetDouble("nu_40", NumberRange::Positive("m^2/s"));
    l->nu_100 = m.GetDouble("nu_100", NumberRange::Positive("m^2/s"));
    l->density = m.GetDouble("density", NumberRange::Positive("kg/m^3"));
    l->temperature = m.GetDouble("temperature", kelvin);
  } else {
    EMB_THROW(InputError, what << " lubricant temperature_law: expected constant, vogel or "
                                  "walther, got '"
                               << law << "'"
                               << DidYouMean(law, {"constant", "vogel", "walther"}));
  }
  // A key of another law is named as such, not as an unknown key.
  const std::pair<const char*, const char*> owners[] = {
      {"viscosity", "constant"}, {"vogel_a", "vogel"},       {"vogel_b", "vogel"},
      {"vogel_c", "vogel"},      {"nu_40", "walther"},       {"nu_100", "walther"},
      {"density", "walther"},    {"temperature", "vogel or walther"}};
  for (const auto& [key, laws] : owners)
    EMB_THROW_IF(m.Has(key) && std::string(laws).find(law) == std::string::npos,
                 Where(r.file(), n) << ": " << what << " lubricant: " << key
                                    << " belongs to temperature_law " << laws
                                    << "; expected the keys of temperature_law " << law
                                    << ", got " << key);
  const std::string pressure = m.GetString("pressure_law", "none");
  EMB_THROW_IF(pressure == "none" && m.Has("pressure_viscosity_coefficient"),
               Where(r.file(), n) << ": " << what
                                  << " lubricant: pressure_viscosity_coefficient needs a "
                                     "pressure_law; expected barus or roelands, got none");
  if (pressure == "barus" || pressure == "roelands") {
    l->pressure_law = pressure == "barus" ? P::kBarus : P::kRoelands;
    l->pressure_viscosity_coefficient =
        m.GetDouble("pressure_viscosity_coefficient", NumberRange::Positive("1/Pa"));
  } else if (pressure != "none") {
    EMB_THROW(InputError, what << " lubricant pressure_law: expected none, barus or roelands, "
                                  "got '"
                               << pressure << "'"
                               << DidYouMean(pressure, {"none", "barus", "roelands"}));
  }
  m.Finish();  // a key of another law is unknown here
}

}  // namespace

// The smoothed JFO switch of a scene's film bearing (ReynoldsBearingParameters::switch_width;
// docs/reference/tribology.md): 0.01 moved a light load by 0.2 % and a heavy one by 1e-6
// (FilmSolver.SmoothedSwitchMovesTheLoadsLittle), and carries the single-cylinder engine's big
// end through the load reversals where the exact switch stopped IDA at 17.7 ms.
constexpr double kSceneSwitchWidth = 0.01;

void ReadFilmBearing(MapReader& r, const std::string& name, mbs::System* sys) {
  const int i = sys->FindMarker(r.GetString("i")), j = sys->FindMarker(r.GetString("j"));
  const std::string what = "force '" + name + "'";
  tribology::ReynoldsBearingParameters p;
  p.radius = r.GetDouble("radius", NumberRange::Positive("m"));
  p.length = r.GetDouble("length", NumberRange::Positive("m"));
  p.clearance = r.GetDouble("clearance", NumberRange::Positive("m"));
  ReadLubricant(r, what, &p.lubricant);
  p.grid.circumferential = r.GetInt("grid_circumferential", p.grid.circumferential, 8, 4096);
  p.grid.axial = r.GetInt("grid_axial", p.grid.axial, 2, 1024);
  p.cavitation = ParseCavitation(r.GetString("cavitation", "mass-conserving"), what);
  p.bulk_modulus = r.GetDouble("bulk_modulus", p.bulk_modulus, NumberRange::Positive("Pa"));
  p.switch_width = r.GetDouble("switch_width", kSceneSwitchWidth, NumberRange::Closed(0.0, 0.5));
  p.pressure_scale =
      r.GetDouble("pressure_scale", p.pressure_scale, NumberRange::Positive("Pa"));
  if (r.Has("bore_tilt")) {
    const std::vector<double> t = r.GetDoubles("bore_tilt");
    EMB_THROW_IF(t.size() != 2, Where(r.file(), r.node())
                                    << ": " << what << " bore_tilt: expected two slopes "
                                    << "[gamma_x, gamma_y] in rad, got " << t.size() << " numbers");
    p.bore_tilt = Eigen::Vector2d(t[0], t[1]);
  } else {
    r.Optional("bore_tilt");
  }
  ReadEach(r, "oil_holes", what, "forces: film-bearing oil hole", [&](MapReader& e) {
    tribology::OilHole h;
    h.angle = e.GetDouble("angle", NumberRange::Finite("rad"));
    h.axial_position = e.GetDouble("axial_position", 0.0, NumberRange::Finite("m"));
    h.diameter = e.GetDouble("diameter", NumberRange::Positive("m"));
    h.supply_pressure = e.GetDouble("supply_pressure", NumberRange::NonNegative("Pa"));
    p.oil_holes.push_back(h);
  });
  ReadEach(r, "grooves", what, "forces: film-bearing groove", [&](MapReader& e) {
    tribology::Groove g;
    g.axial_position = e.GetDouble("axial_position", 0.0, NumberRange::Finite("m"));
    g.width = e.GetDouble("width", NumberRange::Positive("m"));
    g.start_angle = e.GetDouble("start_angle", 0.0, NumberRange::Finite("rad"));
    g.angular_extent = e.GetDouble("angular_extent", 2.0 * M_PI, NumberRange::Positive("rad"));
    g.supply_pressure = e.GetDouble("supply_pressure", NumberRange::NonNegative("Pa"));
    p.grooves.push_back(g);
  });
  ReadEach(r, "journal_oil_holes", what, "forces: film-bearing journal oil hole",
           [&](MapReader& e) {
             tribology::JournalOilHole h;
             h.angle = e.GetDouble("angle", NumberRange::Finite("rad"));
             h.axial_position = e.GetDouble("axial_position", 0.0, NumberRange::Finite("m"));
             h.diameter = e.GetDouble("diameter", NumberRange::Positive("m"));
             h.supply_pressure = e.GetDouble("supply_pressure", NumberRange::NonNegative("Pa"));
             p.journal_oil_holes.push_back(h);
           });
  p.journal_feed_ratio =
      r.GetDouble("journal_feed_ratio", p.journal_feed_ratio, NumberRange::Positive());
  if (const YAML::Node n = r.Optional("asperity_contact")) {
    EMB_THROW_IF(!n.IsMap(), Where(r.file(), n) << ": " << what << " asperity_contact: expected a map");
    MapReader c(n, r.file(), what + " asperity_contact", "forces: film-bearing asperity contact");
    tribology::AsperityContactParameters a;
    a.roughness = c.GetDouble("roughness", NumberRange::Positive("m"));
    a.composite_modulus = c.GetDouble("composite_modulus", NumberRange::Positive("Pa"));
    a.roughness_parameter =
        c.GetDouble("roughness_parameter", a.roughness_parameter, NumberRange::Positive());
    a.slope_parameter = c.GetDouble("slope_parameter", a.slope_parameter, NumberRange::Positive());
    a.boundary_friction =
        c.GetDouble("boundary_friction", a.boundary_friction, NumberRange::NonNegative());
    const std::string f = c.GetString("function", "integral");
    if (f == "arcoumanis") {
      a.function = tribology::GreenwoodTrippFunction::kArcoumanisFit;
    } else if (f != "integral") {
      EMB_THROW(InputError, what << " asperity_contact function: expected integral or arcoumanis, "
                                    "got '" << f << "'" << DidYouMean(f, {"integral", "arcoumanis"}));
    }
    p.film_floor = c.GetDouble("film_floor", p.film_floor, NumberRange::Positive());
    c.Finish();
    p.asperity_contact = a;
  }
  sys->AddForceElement(std::make_shared<mbs::FilmBearing>(name, i, j, p));
}

namespace {

// The `rubber:` map of a torsional damper into s: {static_stiffness, arms: [{stiffness,
// relaxation_time}, ...]} or {dynamic_stiffness, loss_factor, frequency_hz}, both with the
// optional band_hz and junction_error.
void ReadRubber(const YAML::Node& n, const std::string& file, const std::string& what,
                engine::TorsionalDamperSpec* s) {
  MapReader r(n, file, what, "forces: torsional-damper rubber");
  const bool arms = r.Has("static_stiffness") || r.Has("arms");
  const bool fit = r.Has("dynamic_stiffness") || r.Has("loss_factor") || r.Has("frequency_hz");
  EMB_THROW_IF(arms && fit, Where(file, n)
                                << ": " << what
                                << ": expected either {static_stiffness, arms} or "
                                   "{dynamic_stiffness, loss_factor, frequency_hz}, got keys of "
                                   "both");
  EMB_THROW_IF(!arms && !fit, Where(file, n)
                                  << ": " << what
                                  << ": expected {static_stiffness, arms: [{stiffness, "
                                     "relaxation_time}, ...]} or {dynamic_stiffness, "
                                     "loss_factor, frequency_hz}");
  if (arms) {
    s->stiffness = r.GetDouble("static_stiffness", NumberRange::NonNegative("N m/rad"));
    const YAML::Node list = r.Require("arms");
    if (!list.IsSequence() || list.size() == 0)
      EMB_THROW(InputError, Where(file, list) << ": " << what
                                              << " arms: expected a non-empty list of "
                                                 "{stiffness, relaxation_time}");
    for (std::size_t j = 0; j < list.size(); ++j) {
      MapReader a(list[j], file, what + " arm " + std::to_string(j + 1),
                  "forces: torsional-damper rubber arm");
      engine::MaxwellArm arm;
      arm.stiffness = a.GetDouble("stiffness", NumberRange::Positive("N m/rad"));
      arm.relaxation_time = a.GetDouble("relaxation_time", NumberRange::Positive("s"));
      a.Finish();
      s->arms.push_back(arm);
    }
  } else {
    const double k = r.GetDouble("dynamic_stiffness", NumberRange::Positive("N m/rad"));
    const double eta = r.GetDouble(
        "loss_factor", NumberRange::Closed(0.0, engine::kMaxZenerLossFactor, "(Im k*/Re k*)"));
    EMB_THROW_IF(!(eta > 0.0), Where(file, n) << ": " << what
                                              << " loss_factor: expected > 0, got " << eta);
    const double hz = r.GetDouble("frequency_hz", NumberRange::Positive("Hz"));
    const engine::ZenerRubber z = engine::FitZenerAtLossPeak(k, eta, hz);
    s->stiffness = z.static_stiffness;
    s->arms = z.arms;
  }
  s->band_hz = r.GetDouble("band_hz", s->band_hz, NumberRange::Positive("Hz"));
  s->junction_error =
      r.GetDouble("junction_error", s->junction_error, NumberRange::Closed(1e-12, 0.1));
  r.Finish();
}

}  // namespace

std::string ReadTorsionalDamper(MapReader& r, const std::string& name, mbs::System* sys) {
  engine::TorsionalDamperSpec s;
  s.name = name;
  s.hub_marker = r.GetString("hub");
  s.ring_mass = r.GetDouble("ring_mass", NumberRange::Positive("kg"));
  s.ring_inertia = r.GetDouble("ring_inertia", NumberRange::Positive("kg m^2"));
  if (r.Has("rubber")) {
    EMB_THROW_IF(r.Has("stiffness") || r.Has("damping"),
                 Where(r.file(), r.node())
                     << ": " << r.what()
                     << ": expected either `rubber` or `stiffness`/`damping` (Kelvin-Voigt), "
                        "got both");
    ReadRubber(r.Require("rubber"), r.file(), r.what() + " rubber", &s);
  } else {
    r.Optional("rubber");
    s.stiffness = r.GetDouble("stiffness", 0.0, NumberRange::NonNegative("N m/rad"));
    s.damping = r.GetDouble("damping", 0.0, NumberRange::NonNegative("N m s/rad"));
  }
  // AddTorsionalDamper names the damper in its errors.
  const engine::TorsionalDamperParts parts = engine::AddTorsionalDamper(sys, s);
  if (s.arms.empty()) return "";
  std::ostringstream note;
  note.precision(4);
  note << "torsional damper '" << name << "': rubber k_inf " << s.stiffness << " N m/rad";
  for (std::size_t j = 0; j < s.arms.size(); ++j)
    note << "; arm " << j + 1 << " k " << s.arms[j].stiffness << " N m/rad, tau "
         << s.arms[j].relaxation_time << " s, junction ring " << parts.junction_inertia[j]
         << " kg m^2";
  note << "; k*(w) within " << s.junction_error << " of the rubber up to " << s.band_hz << " Hz";
  return note.str();
}

mbs::TimeFunction ReadCylinderPressure(const YAML::Node& n, const std::string& file,
                                       const std::string& what) {
  MapReader r(n, file, what, "function: cylinder_pressure");
  mbs::CylinderPressureSettings s;
  auto get = [&](const char* key, double& value) { value = r.GetDouble(key, value); };
  get("bore", s.bore);
  get("stroke", s.stroke);
  get("rod", s.rod);
  get("compression_ratio", s.compression_ratio);
  get("intake_pressure", s.intake_pressure);
  get("exhaust_pressure", s.exhaust_pressure);
  get("polytropic_exponent", s.polytropic_exponent);
  s.fired = r.GetBool("fired", s.fired);
  get("combustion_start_deg", s.combustion_start_deg);
  get("combustion_duration_deg", s.combustion_duration_deg);
  get("wiebe_a", s.wiebe_a);
  get("wiebe_m", s.wiebe_m);
  EMB_THROW_IF(r.Has("heat_released") && r.Has("peak_pressure"),
               Where(file, n) << ": " << what
                              << ": expected at most one of heat_released, peak_pressure");
  get("heat_released", s.heat_released);
  get("peak_pressure", s.peak_pressure);
  get("exhaust_opening_deg", s.exhaust_opening_deg);
  get("blowdown_deg", s.blowdown_deg);
  // The cycle is tabulated at every step: a tiny step would be billions of samples.
  s.step_deg = r.GetDouble("step_deg", s.step_deg, NumberRange::Closed(1e-3, 10.0, "deg"));
  const double crankcase =
      r.GetDouble("crankcase_pressure", 1.0e5, NumberRange::NonNegative("Pa"));
  const std::string output = r.GetString("output", "force");
  r.Finish();
  EMB_THROW_IF(output != "force" && output != "pressure",
               Where(file, n) << ": " << what << " output: expected 'force' or 'pressure', got '"
                              << output << "'");
  try {
    const mbs::CylinderPressure c(s);
    return output == "force" ? c.PistonForce(crankcase) : c.pressure();
  } catch (const InputError& e) {
    EMB_THROW(InputError, Where(file, n) << ": " << what << ": " << e.what());
  }
}

}  // namespace emb::scene
