#include "libemb/scene/engine_parts.h"

#include <memory>

#include "libemb/common/error.h"
#include "libemb/engine/cylinder_pressure.h"
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

void ReadTorsionalDamper(MapReader& r, const std::string& name, mbs::System* sys) {
  engine::TorsionalDamperSpec s;
  s.name = name;
  s.hub_marker = r.GetString("hub");
  s.ring_mass = r.GetDouble("ring_mass", NumberRange::Positive("kg"));
  s.ring_inertia = r.GetDouble("ring_inertia", NumberRange::Positive("kg m^2"));
  s.stiffness = r.GetDouble("stiffness", 0.0, NumberRange::NonNegative("N m/rad"));
  s.damping = r.GetDouble("damping", 0.0, NumberRange::NonNegative("N m s/rad"));
  engine::AddTorsionalDamper(sys, s);  // names the damper in its errors
}

mbs::TimeFunction ReadCylinderPressure(const YAML::Node& n, const std::string& file,
                                       const std::string& what) {
  MapReader r(n, file, what);
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
