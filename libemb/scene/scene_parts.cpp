#include "libemb/scene/scene_parts.h"

#include <cmath>
#include <map>
#include <numbers>

#include "libemb/common/did_you_mean.h"
#include "libemb/common/error.h"
#include "libemb/mbs/forces/applied_load.h"
#include "libemb/mbs/forces/bushing.h"
#include "libemb/mbs/core/expression_function.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/forces/spring_damper.h"
#include "libemb/scene/driveline_parts.h"
#include "libemb/scene/engine_parts.h"

namespace emb::scene {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// Axes typed with 6+ significant digits (0.707107) count as unit / orthogonal.
constexpr double kUnitTolerance = 1e-6;

Vector3d UnitAxis(const YAML::Node& n, const std::string& file, const std::string& what) {
  const std::vector<double> v = AsDoubles(n, file, what);
  EMB_THROW_IF(v.size() != 3, Where(file, n)
                                  << ": " << what << ": expected 3 numbers, got " << v.size());
  const Vector3d a(v[0], v[1], v[2]);
  EMB_THROW_IF(a.norm() == 0.0, Where(file, n) << ": " << what
                                               << ": expected a unit vector, got "
                                                  "the zero vector");
  EMB_THROW_IF(std::abs(a.norm() - 1.0) > kUnitTolerance,
               Where(file, n) << ": " << what << ": expected a unit vector, got length " << a.norm()
                              << " (normalise it)");
  return a;
}

Eigen::Matrix<double, 6, 6> Read6x6(const YAML::Node& n, const std::string& file,
                                    const std::string& what) {
  const std::vector<double> v = AsDoubles(n, file, what);
  Eigen::Matrix<double, 6, 6> K = Eigen::Matrix<double, 6, 6>::Zero();
  if (v.size() == 6) {
    for (int i = 0; i < 6; ++i) K(i, i) = v[i];
  } else if (v.size() == 36) {
    for (int i = 0; i < 36; ++i) K(i / 6, i % 6) = v[i];
  } else {
    EMB_THROW(InputError, Where(file, n) << ": " << what
                                         << ": expected 6 diagonal entries or 36 entries "
                                            "(row by row), got "
                                         << v.size());
  }
  return K;
}

// A map that must give exactly one of `keys` (a comma-separated list for the message).
void CheckExactlyOne(int given, const YAML::Node& n, const std::string& file,
                     const std::string& what, const char* keys) {
  EMB_THROW_IF(given != 1, Where(file, n) << ": " << what << ": expected exactly one of " << keys
                                          << "; got " << given);
}

}  // namespace

Matrix3d ReadInertia(const YAML::Node& n, const std::string& file, const std::string& what) {
  const std::vector<double> v = AsDoubles(n, file, what);
  Matrix3d I = Matrix3d::Zero();
  if (v.size() == 3) {
    I.diagonal() << v[0], v[1], v[2];
  } else if (v.size() == 6) {
    I << v[0], v[3], v[5], v[3], v[1], v[4], v[5], v[4], v[2];
  } else {
    EMB_THROW(InputError, Where(file, n) << ": " << what
                                         << ": expected [Ixx, Iyy, Izz] or [Ixx, Iyy, Izz, "
                                            "Ixy, Iyz, Izx], got "
                                         << v.size() << " numbers");
  }
  return I;
}

Matrix3d ReadOrientation(const YAML::Node& n, const std::string& file, const std::string& what) {
  MapReader r(n, file, what, "orientation");
  int given = 0;
  Matrix3d R = Matrix3d::Identity();
  for (const char* key : {"euler313", "euler313_deg"}) {
    if (!r.Has(key)) {
      r.Optional(key);
      continue;
    }
    ++given;
    const std::vector<double> a = r.GetDoubles(key);
    EMB_THROW_IF(a.size() != 3,
                 Where(file, n) << ": " << what << " " << key << ": expected [psi, theta, phi]");
    const double s = std::string(key) == "euler313_deg" ? std::numbers::pi / 180 : 1.0;
    R = mbs::RotationFromEuler313(s * a[0], s * a[1], s * a[2]);
  }
  if (r.Has("quaternion")) {
    ++given;
    const YAML::Node qn = r.Require("quaternion");
    const std::vector<double> q = AsDoubles(qn, file, what + " quaternion");
    EMB_THROW_IF(q.size() != 4, Where(file, qn)
                                    << ": " << what << " quaternion: expected [w, x, y, z]");
    const Eigen::Vector4d e(q[0], q[1], q[2], q[3]);
    EMB_THROW_IF(
        std::abs(e.norm() - 1.0) > kUnitTolerance,
        Where(file, qn) << ": " << what << " quaternion: expected unit length, got " << e.norm());
    R = mbs::RotationFromQuaternion(e);
  } else {
    r.Optional("quaternion");
  }
  if (r.Has("z_axis")) {
    ++given;
    const Vector3d z = UnitAxis(r.Require("z_axis"), file, what + " z_axis");
    Vector3d x;
    if (r.Has("x_axis")) {
      const YAML::Node xn = r.Require("x_axis");
      x = UnitAxis(xn, file, what + " x_axis");
      EMB_THROW_IF(std::abs(x.dot(z)) > kUnitTolerance, Where(file, xn)
                                                            << ": " << what
                                                            << ": expected x_axis perpendicular to "
                                                               "z_axis, got x.z = "
                                                            << x.dot(z));
      x = (x - x.dot(z) * z).normalized();
    } else {
      r.Optional("x_axis");
      // Any x perpendicular to z: the world axis least aligned with z, projected.
      Eigen::Index k = 0;
      z.cwiseAbs().minCoeff(&k);
      x = Vector3d::Unit(k);
      x = (x - x.dot(z) * z).normalized();
    }
    R.col(0) = x;
    R.col(1) = z.cross(x);
    R.col(2) = z;
  } else {
    r.Optional("z_axis");
    EMB_THROW_IF(r.Has("x_axis"), Where(file, n) << ": " << what << ": x_axis needs a z_axis");
    r.Optional("x_axis");
  }
  r.Finish();
  CheckExactlyOne(given, n, file, what, "euler313, euler313_deg, quaternion, z_axis");
  return R;
}

mbs::TimeFunction ReadFunction(const YAML::Node& n, const std::string& file,
                               const std::string& what) {
  MapReader r(n, file, what, "function");
  int given = 0;
  mbs::TimeFunction f;
  if (r.Has("constant"))
    ++given, f = mbs::TimeFunction::Constant(r.GetDouble("constant"));
  else
    r.Optional("constant");
  if (r.Has("polynomial"))
    ++given, f = mbs::TimeFunction::Polynomial(r.GetDoubles("polynomial"));
  else
    r.Optional("polynomial");
  if (r.Has("rpm")) {
    ++given;
    f = mbs::TimeFunction::Polynomial({0.0, 2 * std::numbers::pi * r.GetDouble("rpm") / 60.0});
  } else {
    r.Optional("rpm");
  }
  if (r.Has("harmonic")) {
    ++given;
    MapReader h(r.Require("harmonic"), file, what + " harmonic", "function: harmonic");
    const double amplitude = h.GetDouble("amplitude");
    const double hz = h.GetDouble("frequency_hz", NumberRange::NonNegative("Hz"));
    const double phase = h.GetDouble("phase", 0.0);
    const double offset = h.GetDouble("offset", 0.0);
    h.Finish();
    f = mbs::TimeFunction::Harmonic(amplitude, 2 * std::numbers::pi * hz, phase, offset);
  } else {
    r.Optional("harmonic");
  }
  if (r.Has("table")) {
    ++given;
    const YAML::Node tn = r.Require("table");
    MapReader t(tn, file, what + " table", "function: table");
    auto x = t.GetDoubles("x");
    auto y = t.GetDoubles("y");
    const bool periodic = t.GetBool("periodic", false);
    const std::string interpolation = t.GetString("interpolation", "linear");
    t.Finish();
    EMB_THROW_IF(interpolation != "linear" && !(interpolation == "cubic" && periodic),
                 Where(file, tn) << ": " << what
                                 << " table interpolation: expected 'linear', or 'cubic' with "
                                    "periodic: true, got '"
                                 << interpolation << "'");
    try {
      f = interpolation == "cubic" ? mbs::TimeFunction::PeriodicSpline(std::move(x), std::move(y))
                                   : mbs::TimeFunction::Table(std::move(x), std::move(y), periodic);
    } catch (const InputError& e) {
      EMB_THROW(InputError, Where(file, tn) << ": " << what << ": " << e.what());
    }
  } else {
    r.Optional("table");
  }
  if (r.Has("cylinder_pressure")) {
    ++given;
    f = ReadCylinderPressure(r.Require("cylinder_pressure"), file, what + " cylinder_pressure");
  } else {
    r.Optional("cylinder_pressure");
  }
  if (r.Has("expression")) {
    // expression: "formula of t", constants: {name: value}, scale: s (expression_function.h)
    ++given;
    const std::string text = r.GetString("expression");
    std::map<std::string, double> constants;
    if (const YAML::Node c = r.Optional("constants")) {
      EMB_THROW_IF(!c.IsMap(), Where(file, c) << ": " << what
                                              << " constants: expected a map {name: value}");
      for (const auto& kv : c)
        constants[kv.first.Scalar()] =
            AsDouble(kv.second, file, what + " constant '" + kv.first.Scalar() + "'");
    }
    const double scale =
        r.GetDouble("scale", mbs::ExpressionFunction::kDefaultScale, NumberRange::Positive());
    try {
      f = mbs::TimeFunction::Expression(text, constants, scale);
    } catch (const InputError& e) {
      EMB_THROW(InputError, Where(file, n) << ": " << what << " " << e.what());
    }
  } else {
    for (const char* key : {"constants", "scale"})
      EMB_THROW_IF(r.Has(key), Where(file, n) << ": " << what << " " << key
                                              << ": only with an expression");
    r.Optional("expression");
  }
  r.Finish();
  CheckExactlyOne(given, n, file, what,
                  "constant, polynomial, rpm, harmonic, table, cylinder_pressure, expression");
  return f;
}

mbs::JointCoordinate ReadCoordinate(MapReader& r, const std::string& key) {
  const std::string c = r.GetString(key, "rotation");
  if (c == "rotation") return mbs::JointCoordinate::kRotation;
  if (c == "translation") return mbs::JointCoordinate::kTranslation;
  EMB_THROW(InputError, Where(r.file(), r.node())
                            << ": " << r.what() << " " << key
                            << ": expected 'rotation' or 'translation', got '" << c << "'");
}

void ReadForces(const YAML::Node& list, const std::string& file, mbs::System* sys,
                std::vector<std::string>* notes) {
  ReadNamedList(list, file, "forces", "force", [&](MapReader& r, const std::string& name,
                                                   const YAML::Node&) {
    const std::string& what = r.what();
    const std::string type = r.GetString("type");
    r.set_section("forces: " + (type == "force" || type == "torque" ? "force, torque" : type));
    if (type == "spring-damper" || type == "rotational-spring-damper") {
      const int i = sys->FindMarker(r.GetString("i")), j = sys->FindMarker(r.GetString("j"));
      const bool linear = type == "spring-damper";
      const double k =
          r.GetDouble("stiffness", 0.0, NumberRange::NonNegative(linear ? "N/m" : "N m/rad"));
      const double c =
          r.GetDouble("damping", 0.0, NumberRange::NonNegative(linear ? "N s/m" : "N m s/rad"));
      if (linear) {
        const double l0 = r.GetDouble("free_length", 0.0, NumberRange::NonNegative("m"));
        sys->AddForceElement(
            std::make_shared<mbs::TranslationalSpringDamper>(name, i, j, k, c, l0));
      } else {
        const double a0 = r.GetDouble("free_angle", 0.0);
        sys->AddForceElement(std::make_shared<mbs::RotationalSpringDamper>(name, i, j, k, c, a0));
      }
    } else if (type == "bushing") {
      const int i = sys->FindMarker(r.GetString("i")), j = sys->FindMarker(r.GetString("j"));
      const auto K = Read6x6(r.Require("stiffness"), file, what + " stiffness");
      Eigen::Matrix<double, 6, 6> D = Eigen::Matrix<double, 6, 6>::Zero();
      if (r.Has("damping"))
        D = Read6x6(r.Require("damping"), file, what + " damping");
      else
        r.Optional("damping");
      // The seed's choice: damping as a fraction of stiffness, D = beta K, beta in s.
      if (r.Has("damping_factor"))
        D += r.GetDouble("damping_factor", NumberRange::NonNegative("s")) * K;
      else
        r.Optional("damping_factor");
      sys->AddForceElement(std::make_shared<mbs::Bushing>(name, i, j, K, D));
    } else if (type == "journal-bearing") {
      ReadJournalBearing(r, name, sys);
    } else if (type == "film-bearing") {
      ReadFilmBearing(r, name, sys);
    } else if (type == "torsional-damper") {
      const std::string note = ReadTorsionalDamper(r, name, sys);
      if (notes && !note.empty()) notes->push_back(note);
    } else if (type == "lash") {
      ReadLash(r, name, sys);
    } else if (type == "clutch-damper") {
      ReadClutchDamper(r, name, sys);
    } else if (type == "force" || type == "torque") {
      const int m = sys->FindMarker(r.GetString("marker"));
      const std::string frame = r.GetString("frame", "world");
      EMB_THROW_IF(frame != "world" && frame != "marker",
                   what << " frame: expected 'world' or 'marker', got '" << frame << "'");
      const YAML::Node dn = r.Require("direction");
      const Vector3d dir = UnitAxis(dn, file, what + " direction");
      const int reaction = r.Has("reaction_marker")
                               ? sys->FindMarker(r.GetString("reaction_marker"))
                               : (r.Optional("reaction_marker"), -1);
      const mbs::TimeFunction f = ReadFunction(r.Require("function"), file, what + " function");
      mbs::LoadArgument arg;
      if (const YAML::Node an = r.Optional("argument")) {
        // {joint: name, unit: rad|deg, offset: 0}: the function of a joint's rotation angle;
        // {i: marker, j: marker, ...}: of the angle of x_I about z_J without a joint.
        MapReader a(an, file, what + " argument", "forces: load argument");
        const bool by_markers = !a.Has("joint") && a.Has("i");
        const std::string joint = by_markers ? "" : a.GetString("joint");
        if (by_markers) {
          arg.marker_i = sys->FindMarker(a.GetString("i"));
          arg.marker_j = sys->FindMarker(a.GetString("j"));
        }
        const std::string unit = a.GetString("unit", "rad");
        arg.offset = a.GetDouble("offset", 0.0);
        a.Finish();
        EMB_THROW_IF(unit != "rad" && unit != "deg", Where(file, an)
                                                         << ": " << what
                                                         << " argument unit: expected 'rad' or "
                                                            "'deg', got '"
                                                         << unit << "'");
        if (!by_markers) {
          const mbs::ConstraintElement& je = sys->elements().at(sys->FindElement(joint));
          mbs::CoordinateKernel(je.type, mbs::JointCoordinate::kRotation, joint);  // checks
          arg.marker_i = je.marker_i;
          arg.marker_j = je.marker_j;
        }
        arg.joint_angle = true;
        arg.scale = unit == "deg" ? 180.0 / std::numbers::pi : 1.0;
      }
      sys->AddForceElement(std::make_shared<mbs::AppliedLoad>(
          name,
          type == "force" ? mbs::AppliedLoad::Kind::kForce : mbs::AppliedLoad::Kind::kTorque, m,
          dir,
          frame == "world" ? mbs::AppliedLoad::Frame::kWorld : mbs::AppliedLoad::Frame::kMarker,
          f, reaction, arg));
    } else {
      EMB_THROW(InputError,
                what << ": unknown type '" << type
                     << "': expected one of spring-damper, rotational-spring-damper, "
                        "bushing, journal-bearing, film-bearing, torsional-damper, lash, "
                        "clutch-damper, force, torque"
                     << DidYouMean(type, {"spring-damper", "rotational-spring-damper",
                                               "bushing", "journal-bearing", "film-bearing",
                                               "torsional-damper", "lash",
                                               "clutch-damper", "force", "torque"}));
    }
    r.Finish();
  });
}

}  // namespace emb::scene
