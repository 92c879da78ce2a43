#include "libemb/scene/driveline_parts.h"

#include <memory>

#include "libemb/common/error.h"
#include "libemb/driveline/clutch_damper.h"
#include "libemb/driveline/lash.h"
#include "libemb/scene/scene_parts.h"

namespace emb::scene {
namespace {

driveline::ContactLawParameters ReadContact(const YAML::Node& n, const std::string& file,
                                            const std::string& what) {
  MapReader r(n, file, what + " contact", "forces: lash contact");
  driveline::ContactLawParameters p;
  try {
    p.kind = driveline::ParseContactLawKind(r.GetString("law", "hunt-crossley"));
  } catch (const InputError& e) {
    EMB_THROW(InputError, Where(file, n) << ": " << what << " " << e.what());
  }
  const bool hc = p.kind == driveline::ContactLawKind::kHuntCrossley;
  p.stiffness = r.GetDouble("stiffness", NumberRange::Positive("N/m or N m/rad"));
  // Restitution e in (0, 1]: 1 is a perfectly elastic contact, 0 is excluded (no rebound
  // needs an infinite Hunt-Crossley damping).
  const NumberRange restitution{0.0, 1.0, true, false, ""};
  if (hc) {
    p.exponent = r.GetDouble("exponent", 1.0, NumberRange::Closed(1.0, 10.0));
    p.restitution = r.GetDouble("restitution", restitution);
    p.min_impact_velocity = r.GetDouble("min_impact_velocity", p.min_impact_velocity,
                                        NumberRange::Positive("m/s or rad/s"));
  } else if (r.Has("damping")) {
    p.damping = r.GetDouble("damping", NumberRange::NonNegative("N s/m or N m s/rad"));
  } else {
    p.restitution = r.GetDouble("restitution", restitution);
    p.effective_mass = r.GetDouble("effective_inertia", NumberRange::Positive("kg or kg m^2"));
  }
  r.Finish();
  return p;
}

driveline::SqueezeFilmParameters ReadSqueezeFilm(const YAML::Node& n, const std::string& file,
                                                 const std::string& what) {
  MapReader r(n, file, what + " squeeze_film", "forces: lash squeeze_film");
  driveline::SqueezeFilmParameters p;
  p.viscosity = r.GetDouble("viscosity", NumberRange::Positive("Pa s"));
  p.width = r.GetDouble("width", NumberRange::Positive("m"));
  p.radius = r.GetDouble("radius", NumberRange::Positive("m"));
  p.lever = r.GetDouble("lever", 1.0, NumberRange::Positive("m/rad or m/m"));
  p.min_film = r.GetDouble("min_film", p.min_film, NumberRange::Positive("m"));
  r.Finish();
  return p;
}

}  // namespace

void ReadLash(MapReader& r, const std::string& name, mbs::System* sys) {
  const std::string& what = r.what();
  std::vector<driveline::CoordinateTerm> terms;
  terms.push_back(driveline::JointCoordinateTerm(*sys, r.GetString("joint1"),
                                                 ReadCoordinate(r, "coordinate1"), 1.0, what));
  if (r.Has("joint2")) {
    const std::string j2 = r.GetString("joint2");
    const mbs::JointCoordinate c2 = ReadCoordinate(r, "coordinate2");
    const double ratio = r.GetDouble("ratio", NumberRange::Finite());
    terms.push_back(driveline::JointCoordinateTerm(*sys, j2, c2, -ratio, what));
  } else {
    for (const char* key : {"coordinate2", "ratio"})
      EMB_THROW_IF(r.Has(key), Where(r.file(), r.node())
                                   << ": " << what << ": '" << key << "' needs a joint2");
  }
  driveline::LashParameters p;
  EMB_THROW_IF(r.Has("stops") == r.Has("lash"),
               Where(r.file(), r.node())
                   << ": " << what << ": expected either 'lash' (with 'offset') or 'stops'");
  if (r.Has("stops")) {
    const std::vector<double> s = r.GetDoubles("stops");
    EMB_THROW_IF(s.size() != 2, Where(r.file(), r.node())
                                    << ": " << what << " stops: expected [lower, upper], got "
                                    << s.size() << " numbers");
    EMB_THROW_IF(!(s[1] >= s[0]), Where(r.file(), r.node()) << ": " << what
                                                            << " stops: expected lower <= upper (a "
                                                               "lash >= 0), got ["
                                                            << s[0] << ", " << s[1] << "]");
    p.lower = s[0];
    p.upper = s[1];
  } else {
    const double lash = r.GetDouble("lash", NumberRange::NonNegative("rad or m"));
    const double offset = r.GetDouble("offset", 0.0, NumberRange::Finite("rad or m"));
    p.lower = offset - 0.5 * lash;
    p.upper = offset + 0.5 * lash;
  }
  p.contact = ReadContact(r.Require("contact"), r.file(), what);
  if (const YAML::Node sf = r.Optional("squeeze_film"))
    p.squeeze_film = ReadSqueezeFilm(sf, r.file(), what);
  r.Finish();
  sys->AddForceElement(std::make_shared<driveline::Lash>(name, terms, p));
}

void ReadClutchDamper(MapReader& r, const std::string& name, mbs::System* sys) {
  driveline::CoordinateTerm term;
  if (r.Has("joint")) {
    term = driveline::JointCoordinateTerm(*sys, r.GetString("joint"),
                                          mbs::JointCoordinate::kRotation, 1.0, r.what());
  } else {
    term.marker_i = sys->FindMarker(r.GetString("i"));
    term.marker_j = sys->FindMarker(r.GetString("j"));
    term.kernel = {mbs::KernelKind::kAngle, 0, 0};
  }
  driveline::ClutchDamperParameters p;
  const std::vector<double> k = r.GetDoubles("stiffness");
  EMB_THROW_IF(k.size() != 2, Where(r.file(), r.node())
                                  << ": " << r.what()
                                  << " stiffness: expected [k1, k2] (first and second stage, "
                                     "N m/rad), got "
                                  << k.size() << " numbers");
  p.stiffness_1 = k[0];
  p.stiffness_2 = k[1];
  p.knee_angle = r.GetDouble("knee_angle", NumberRange::NonNegative("rad"));
  p.damping = r.GetDouble("damping", 0.0, NumberRange::NonNegative("N m s/rad"));
  p.hysteresis_torque = r.GetDouble("hysteresis_torque", 0.0, NumberRange::NonNegative("N m"));
  p.hysteresis_speed =
      r.GetDouble("hysteresis_speed", p.hysteresis_speed, NumberRange::Positive("rad/s"));
  p.free_angle = r.GetDouble("free_angle", 0.0, NumberRange::Finite("rad"));
  r.Finish();
  sys->AddForceElement(std::make_shared<driveline::ClutchDamper>(name, term, p));
}

}  // namespace emb::scene
