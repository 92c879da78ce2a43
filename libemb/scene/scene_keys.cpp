// The key table of the scene readers: its sections and the keys of the model (the top level,
// bodies, markers, joints, motions, couplers, orientations, functions); the keys of the force
// elements, the outputs and the analysis are in scene_keys_run.cpp.
#include "libemb/scene/scene_keys.h"

#include <algorithm>
#include <vector>

#include "libemb/scene/scene_keys_parts.h"

namespace emb::scene {
namespace {

using T = KeyType;

// One entry a line, as the table it is (clang-format would spread each over three lines).
// clang-format off
constexpr SceneSection kSections[] = {
    {"scene", "the top level of the file", "What the model is made of, what to run and what to write."},
    {"bodies", "every entry of `bodies:`", "A part. `model:` says which kind; the keys of the other kinds may stay in a body-file or beam entry (ignored), so that one word switches a part between rigid, cms and beam."},
    {"bodies: rigid", "an entry of `bodies:` without `body_file` (`model: rigid`, the default)", "A rigid body given by its mass properties."},
    {"bodies: body file", "an entry of `bodies:` with `body_file` (`model: rigid` or `model: cms`)", "A part reduced by `emb reduce`: `cms` makes it a flexible body (floating frame, modal coordinates), `rigid` takes only its mass properties and interface points."},
    {"bodies: beam", "an entry of `bodies:` with `model: beam`", "A part generated from its geometry as Eulerian beams between lumped rigid parts (node bodies and beam forces)."},
    {"bodies: beam material", "`material:` of a `model: beam` entry", "The beam's material."},
    {"orientation", "every `orientation:` (bodies, markers, parts)", "Exactly one of `euler313`, `euler313_deg`, `quaternion`, `z_axis`; internally every pose is a unit quaternion."},
    {"markers", "an entry of `markers:`", "A frame fixed on a body, or on an interface of a part from a body file or a beam part."},
    {"joints", "an entry of `joints:`", "A standard joint or primitive constraint between two markers (`i` on the first body, `j` on the second; the joint axis is z of `j`)."},
    {"motions", "an entry of `motions:`", "A joint coordinate prescribed as a function of time (one equation)."},
    {"couplers", "an entry of `couplers:`", "A gear or coupler: g1 − ratio·g2 − offset = 0 between two joint coordinates (one equation)."},
    {"function", "every `function:` (motions, loads)", "Exactly one of `constant`, `polynomial`, `rpm`, `harmonic`, `table`, `cylinder_pressure`, `expression`."},
    {"function: harmonic", "`harmonic:` of a function", "amplitude · sin(2π f t + phase) + offset."},
    {"function: table", "`table:` of a function", "Piecewise linear through (x, y), or the periodic C² cubic spline."},
    {"function: cylinder_pressure", "`cylinder_pressure:` of a function", "The gas force (or pressure) of one cylinder against the crank angle in degrees from its firing TDC: single-zone polytropic model with Wiebe heat release (`libemb/engine/cylinder_pressure.h`). Every key is optional."},
    {"forces", "every entry of `forces:`", "A force element; `type:` says which, and the keys of that type follow."},
    {"forces: spring-damper", "`type: spring-damper`", "A linear spring and damper along the line between the two markers."},
    {"forces: rotational-spring-damper", "`type: rotational-spring-damper`", "A spring and damper on the angle a of x_I about z_J: the gradient of k(a − a₀)²/2 plus c·a′."},
    {"forces: bushing", "`type: bushing`", "A 6×6 linear bushing: load on I from J in J's axes, rotation measured by the rotation vector (exactly conservative)."},
    {"forces: journal-bearing", "`type: journal-bearing`", "Short-bearing (Ocvirk) hydrodynamic film with half-Sommerfeld cavitation between journal marker `i` and bearing marker `j` (axis z_J)."},
    {"forces: film-bearing", "`type: film-bearing`", "Finite-width Reynolds film (libemb/tribology/notation.h) between journal marker `i` and shell marker `j` (axis z_J): misalignment, oil holes and grooves, and a cavitation model; mass-conserving (JFO) films are states of the run."},
    {"forces: film-bearing oil hole", "an entry of `oil_holes:`", "A circular oil hole in the shell held at its supply pressure."},
    {"forces: film-bearing asperity contact", "`asperity_contact:` of a film bearing", "Greenwood–Tripp asperity contact where the film is thinner than a few roughnesses (mixed lubrication)."},
    {"forces: film-bearing journal oil hole", "an entry of `journal_oil_holes:`", "An oil hole in the journal that turns with it (a crankpin drilling), feeding the film through a conductance."},
    {"forces: film-bearing lubricant", "`lubricant:` of a film bearing", "The oil: a viscosity–temperature law at an effective temperature and an optional pressure–viscosity law."},
    {"forces: film-bearing groove", "an entry of `grooves:`", "A circumferential groove (full or partial; a narrow one along the length is an axial groove) held at its supply pressure."},
    {"forces: torsional-damper", "`type: torsional-damper`", "A torsional vibration damper: an inertia ring on a Kelvin–Voigt rubber (`stiffness`, `damping`) or a frequency-dependent rubber (`rubber:`)."},
    {"forces: torsional-damper rubber", "`rubber:` of a torsional damper", "Either `{static_stiffness, arms}` (generalised Maxwell) or `{dynamic_stiffness, loss_factor, frequency_hz}` (one Zener arm fitted at its loss peak)."},
    {"forces: torsional-damper rubber arm", "an entry of `arms:` of a rubber", "One Maxwell arm: a spring in series with a dashpot c = k·τ."},
    {"forces: lash", "`type: lash`", "Backlash with impacts on x = g₁ − ratio·g₂ − offset, free between its stops."},
    {"forces: lash contact", "`contact:` of a lash", "The contact law at a closed stop, with the coefficient of restitution as input."},
    {"forces: lash squeeze_film", "`squeeze_film:` of a lash", "A lubricant squeeze film while the lash is open (seed appendix A1, eq. A1.5)."},
    {"forces: clutch-damper", "`type: clutch-damper`", "Two-stage spring, viscous damping and friction hysteresis on a joint's rotation (`joint`) or on the angle of x_I about z_J (`i`, `j`)."},
    {"forces: force, torque", "`type: force` or `type: torque`", "An applied force or torque of a function of time (or of a joint angle) on a marker."},
    {"forces: load argument", "`argument:` of a force or torque", "The function's argument is an angle instead of the time: a joint's rotation (`joint`) or the angle of x_I about z_J (`i`, `j`)."},
    {"sensors", "an entry of `sensors:`", "Output only: `pose` (marker i relative to marker j) or `chord` (the deflection of a marker from the line through two others)."},
    {"output_points", "an entry of `output_points:`", "Output only: a mesh node or surface group of a part from a body file (motion, or the radiated-power noise proxy)."},
    {"output_points: axis", "`axis:` of an output point", "The axis of `direction: radial`."},
    {"stress_outputs", "an entry of `stress_outputs:`", "Hot-spot stresses, stress fields and a fatigue summary on a `model: cms` part whose body file holds modal stresses."},
    {"stress_outputs: fatigue", "`fatigue:` of a stress output", "Rainflow, Goodman and Miner against a Basquin curve or S–N points, per node, after the run."},
    {"analysis", "`analysis:`", "What `emb run` does with the model and the integrator's settings (why each default: `libemb/mbs/analysis/analysis.h`)."},
    {"analysis: steady_state", "`steady_state:` of the analysis", "Run whole periods until the chosen channels repeat (dynamic analysis only; replaces `t_end`)."},
    {"planar", "`planar:` as a map", "`planar: true` is a mechanism in the world xy plane; the map gives another plane."},
    {"output", "`output:`", "Where the results go; relative paths are relative to the scene file's directory."},
};
// clang-format on

// One entry a line, as the table it is (clang-format would spread each over three lines).
// clang-format off
constexpr SceneKey kModelKeys[] = {
    // scene
    {"scene", "name", T::kString, "", "", "scene", "The model's name in the results."},
    {"scene", "description", T::kString, "", "", "", "Free text."},
    {"scene", "gravity", T::kVector3, "m/s^2", "", "—", "Gravity in the world frame W; none if absent."},
    {"scene", "bodies", T::kList, "", "", "required", "The parts (section *bodies*); the ground exists already, named `ground`."},
    {"scene", "markers", T::kList, "", "", "—", "Frames on bodies (section *markers*)."},
    {"scene", "joints", T::kList, "", "", "—", "Section *joints*."},
    {"scene", "motions", T::kList, "", "", "—", "Section *motions*."},
    {"scene", "couplers", T::kList, "", "", "—", "Section *couplers*."},
    {"scene", "forces", T::kList, "", "", "—", "Force elements (section *forces*)."},
    {"scene", "sensors", T::kList, "", "", "—", "Section *sensors*."},
    {"scene", "output_points", T::kList, "", "", "—", "Section *output_points*."},
    {"scene", "stress_outputs", T::kList, "", "", "—", "Section *stress_outputs*."},
    {"scene", "analysis", T::kMap, "", "", "—", "Section *analysis*; absent: a dynamic run with the defaults."},
    {"scene", "planar", T::kAny, "", "", "—", "`true` (plane normal z), `false` or a map (section *planar*): the redundant equations of a planar mechanism that act only out of its plane are dropped without a word."},
    {"scene", "output", T::kMap, "", "", "—", "Section *output*."},
    // bodies
    {"bodies", "name", T::kString, "", "", "required", "The part's name (markers, joints and channels use it)."},
    {"bodies", "model", T::kString, "", "rigid | cms | beam", "rigid", "`rigid`: a rigid body (mass properties given, or taken from `body_file`); `cms`: a flexible body from `body_file`; `beam`: generated from `geometry`."},
    // bodies: rigid
    {"bodies: rigid", "mass", T::kNumber, "kg", "", "required", "Mass; must be > 0."},
    {"bodies: rigid", "inertia", T::kAny, "kg m^2", "", "required", "About the centre of mass in body axes: [Ixx, Iyy, Izz] or [Ixx, Iyy, Izz, Ixy, Iyz, Izx]; must be a possible mass distribution."},
    {"bodies: rigid", "position", T::kVector3, "m", "", "[0, 0, 0]", "Centre of mass in W at t = 0."},
    {"bodies: rigid", "orientation", T::kMap, "", "", "—", "Section *orientation*; absent: the world axes."},
    {"bodies: rigid", "velocity", T::kVector3, "m/s", "", "[0, 0, 0]", "Centre-of-mass velocity in W (projected onto the constraints)."},
    {"bodies: rigid", "angular_velocity", T::kVector3, "rad/s", "", "[0, 0, 0]", "In W."},
    // bodies: body file
    {"bodies: body file", "body_file", T::kString, "", "", "required", "The body file of `emb reduce`, relative to the scene file."},
    {"bodies: body file", "basis", T::kString, "", "free-free | installed", "free-free", "`installed`: at the start, the model's installed modes up to `dynamic_band_hz` plus the static responses at loaded markers (cms only); `free-free`: the file's modes as selected by `modes`/`fmax_hz`."},
    {"bodies: body file", "modes", T::kInteger, "", "[0, 100000]", "-1", "Keep the lowest N elastic modes of the file; −1 (absent): all; 0: the part is rigid."},
    {"bodies: body file", "fmax_hz", T::kNumber, "Hz", "> 0", "-1", "Keep the elastic modes up to this frequency; −1 (absent): no limit."},
    {"bodies: body file", "dynamic_band_hz", T::kNumber, "Hz", "> 0", "-1", "Kept modes above it are quasi-static (massless); with `basis: installed` the band of installed modes kept dynamic (then required); −1 (absent): all dynamic."},
    {"bodies: body file", "quasi_static_relaxation", T::kNumber, "", "in [0, 10]", "0.1", "`basis: installed` only: the quasi-static coordinates relax with time constant this/(2π·dynamic_band_hz)."},
    {"bodies: body file", "geometric_stiffening", T::kBool, "", "", "—", "Geometric (centrifugal) stiffening from the file's nine matrices; absent: on when the file has them; `true` without them is an error."},
    {"bodies: body file", "expect_mesh_hash", T::kString, "", "", "", "Refuse a body file reduced from another mesh (a stale basis); empty: no check."},
    {"bodies: body file", "position", T::kVector3, "m", "", "[0, 0, 0]", "Where the mesh origin goes in W."},
    {"bodies: body file", "orientation", T::kMap, "", "", "—", "Section *orientation*, of the mesh axes."},
    {"bodies: body file", "velocity", T::kVector3, "m/s", "", "—", "Centre-of-mass velocity in W; absent: ω × (CM − position), spinning about the mesh origin."},
    {"bodies: body file", "angular_velocity", T::kVector3, "rad/s", "", "[0, 0, 0]", "In W."},
    {"bodies: body file", "modal_coordinates", T::kNumbers, "", "", "—", "Initial modal coordinates η(t₀), one per kept mode; absent: zero (or the quasi-static start)."},
    {"bodies: body file", "modal_velocities", T::kNumbers, "", "", "—", "Initial modal rates η̇(t₀), one per kept mode."},
    // bodies: beam
    {"bodies: beam", "geometry", T::kString, "", "", "required", "A .geo with beam parts (`beam_parts = 1`), relative to the scene file."},
    {"bodies: beam", "parameters", T::kMap, "", "", "—", "`{name: value}` overrides of the .geo's `DefineConstant`s."},
    {"bodies: beam", "webs", T::kString, "", "rigid | elastic", "rigid", "Crank webs as rigid parts (the seed's dummy parts) or as elastic radial arms."},
    {"bodies: beam", "web_width", T::kNumber, "m", ">= 0", "0", "Elastic webs: the arm width; 0: the .geo's `web_r_main + web_r_pin`."},
    {"bodies: beam", "beam_nodes", T::kString, "", "condensed | all", "—", "`condensed` keeps bodies only at rigid parts and interfaces (the default with rigid parts); `all` makes every beam node a body (the default without)."},
    {"bodies: beam", "element_length", T::kNumber, "m", "in [0.0001, 100]", "0.02", "Largest beam element."},
    {"bodies: beam", "stiffness_damping", T::kNumber, "s", ">= 0", "-1", "β of D = βK; −1 (absent): ζ = 1 % at the model's first elastic frequency."},
    {"bodies: beam", "material", T::kMap, "", "", "—", "Section *bodies: beam material*."},
    {"bodies: beam", "position", T::kVector3, "m", "", "[0, 0, 0]", "Where the part frame (the .geo's frame) goes in W."},
    {"bodies: beam", "orientation", T::kMap, "", "", "—", "Section *orientation*, of the part frame."},
    {"bodies: beam", "angular_velocity", T::kVector3, "rad/s", "", "[0, 0, 0]", "In W."},
    {"bodies: beam", "body_file", T::kString, "", "", "—", "The 3-D part's body file: the mesh its output points use."},
    {"bodies: beam material", "E", T::kNumber, "Pa", "", "2.1e11", "Young's modulus."},
    {"bodies: beam material", "nu", T::kNumber, "", "", "0.3", "Poisson's ratio."},
    {"bodies: beam material", "rho", T::kNumber, "kg/m^3", "", "7850", "Density."},
    // orientation
    {"orientation", "euler313", T::kNumbers, "rad", "", "—", "[ψ, θ, φ]: Rz(ψ) Rx(θ) Rz(φ), seed eq. (1.20)."},
    {"orientation", "euler313_deg", T::kNumbers, "deg", "", "—", "The same in degrees."},
    {"orientation", "quaternion", T::kNumbers, "", "", "—", "[w, x, y, z], unit length."},
    {"orientation", "z_axis", T::kVector3, "", "", "—", "The frame's z axis in the parent axes, a unit vector."},
    {"orientation", "x_axis", T::kVector3, "", "", "—", "With `z_axis`: the x axis, a unit vector perpendicular to it; absent: any perpendicular."},
    // markers
    {"markers", "name", T::kString, "", "", "required", "The marker's name."},
    {"markers", "body", T::kString, "", "", "required", "The body (or part) it sits on."},
    {"markers", "frame", T::kString, "", "body | world", "body", "`body`: position and orientation in the body frame (mesh coordinates on a body-file part); `world`: in W at the initial configuration."},
    {"markers", "interface", T::kString, "", "", "", "An interface of a body-file or beam part: the marker sits on its reference point and, on a cms part, follows the deformation (required on a flexible part)."},
    {"markers", "position", T::kVector3, "m", "", "[0, 0, 0]", "With `interface`: must be the interface's point (body file) or a point of the interface's node body (beam)."},
    {"markers", "orientation", T::kMap, "", "", "—", "Section *orientation*; absent: the body axes."},
    // joints
    {"joints", "name", T::kString, "", "", "required", "The joint's name (reactions `<joint>.F|T.*`, coordinates `<joint>.angle`, `.travel`)."},
    {"joints", "type", T::kString, "", "at-point | in-line | in-plane | perpendicular | parallel | fixed | revolute | translational | cylindrical | universal | spherical | planar", "required", "Built from the seed's primitives (1.21)–(1.23)."},
    {"joints", "i", T::kString, "", "", "required", "Marker on the first body."},
    {"joints", "j", T::kString, "", "", "required", "Marker on the second body; its z axis is the joint axis."},
    // motions
    {"motions", "name", T::kString, "", "", "required", "The motion's name."},
    {"motions", "joint", T::kString, "", "", "required", "The driven joint."},
    {"motions", "coordinate", T::kString, "", "rotation | translation", "rotation", "Which joint coordinate (rad or m)."},
    {"motions", "function", T::kMap, "", "", "required", "Section *function*: the coordinate against time."},
    // couplers
    {"couplers", "name", T::kString, "", "", "required", "The coupler's name."},
    {"couplers", "joint1", T::kString, "", "", "required", "First joint."},
    {"couplers", "coordinate1", T::kString, "", "rotation | translation", "rotation", "Its coordinate."},
    {"couplers", "joint2", T::kString, "", "", "required", "Second joint."},
    {"couplers", "coordinate2", T::kString, "", "rotation | translation", "rotation", "Its coordinate."},
    {"couplers", "ratio", T::kNumber, "", "", "required", "g1 = ratio · g2 + offset; ratio ≠ 0, joint2 another coordinate than joint1."},
    {"couplers", "offset", T::kNumber, "", "", "0", "In the first coordinate's unit."},
    // function
    {"function", "constant", T::kNumber, "", "", "—", "c."},
    {"function", "polynomial", T::kNumbers, "", "", "—", "[c0, c1, ...]: Σ c_k t^k."},
    {"function", "rpm", T::kNumber, "rpm", "", "—", "The angle 2π N t / 60 (a motion at constant speed; `emb sweep` and `emb campbell` scale it)."},
    {"function", "harmonic", T::kMap, "", "", "—", "Section *function: harmonic*."},
    {"function", "table", T::kMap, "", "", "—", "Section *function: table*."},
    {"function", "cylinder_pressure", T::kMap, "", "", "—", "Section *function: cylinder_pressure*."},
    {"function", "expression", T::kString, "", "", "—", "A formula of `t` (also `x`, for a load of a joint angle), parsed by muParser; derivatives by extrapolated central differences."},
    {"function", "constants", T::kMap, "", "", "—", "With `expression`: `{name: value}` used in it."},
    {"function", "scale", T::kNumber, "", "> 0", "0.001", "With `expression`: the first step of the numerical derivatives, in the argument's unit (s); about a tenth of the function's shortest period or ramp."},
    {"function: harmonic", "amplitude", T::kNumber, "", "", "required", "A."},
    {"function: harmonic", "frequency_hz", T::kNumber, "Hz", ">= 0", "required", "f."},
    {"function: harmonic", "phase", T::kNumber, "rad", "", "0", "Phase."},
    {"function: harmonic", "offset", T::kNumber, "", "", "0", "Offset."},
    {"function: table", "x", T::kNumbers, "", "", "required", "Abscissae, rising."},
    {"function: table", "y", T::kNumbers, "", "", "required", "Values, one per x."},
    {"function: table", "periodic", T::kBool, "", "", "false", "Periodic with period x_last − x_first (e.g. a 720° cycle)."},
    {"function: table", "interpolation", T::kString, "", "linear | cubic", "linear", "`cubic` (with `periodic: true`, y_last = y_first): the periodic C² cubic spline."},
    {"function: cylinder_pressure", "bore", T::kNumber, "m", "", "0.086", "Bore."},
    {"function: cylinder_pressure", "stroke", T::kNumber, "m", "", "0.086", "Stroke."},
    {"function: cylinder_pressure", "rod", T::kNumber, "m", "", "0.1435", "Connecting-rod centre distance."},
    {"function: cylinder_pressure", "compression_ratio", T::kNumber, "", "", "10.5", "Compression ratio."},
    {"function: cylinder_pressure", "intake_pressure", T::kNumber, "Pa", "", "1e5", "Manifold pressure (full load)."},
    {"function: cylinder_pressure", "exhaust_pressure", T::kNumber, "Pa", "", "110000", "Exhaust pressure."},
    {"function: cylinder_pressure", "polytropic_exponent", T::kNumber, "", "", "1.32", "n of p V^n = const."},
    {"function: cylinder_pressure", "fired", T::kBool, "", "", "true", "`false`: motored, p = p_intake (V_max/V)^n."},
    {"function: cylinder_pressure", "combustion_start_deg", T::kNumber, "deg", "", "-15", "Wiebe start, from firing TDC."},
    {"function: cylinder_pressure", "combustion_duration_deg", T::kNumber, "deg", "", "50", "Wiebe duration."},
    {"function: cylinder_pressure", "wiebe_a", T::kNumber, "", "", "5", "x_b = 1 − exp(−a ((θ − start)/duration)^(m+1))."},
    {"function: cylinder_pressure", "wiebe_m", T::kNumber, "", "", "2", "Wiebe form factor m."},
    {"function: cylinder_pressure", "heat_released", T::kNumber, "J", "", "0", "Heat per cycle; 0: found from `peak_pressure` (give at most one of the two)."},
    {"function: cylinder_pressure", "peak_pressure", T::kNumber, "Pa", "", "7500000", "Target peak pressure (full load)."},
    {"function: cylinder_pressure", "exhaust_opening_deg", T::kNumber, "deg", "", "130", "Blowdown starts here ..."},
    {"function: cylinder_pressure", "blowdown_deg", T::kNumber, "deg", "", "90", "... and reaches the exhaust pressure over this angle."},
    {"function: cylinder_pressure", "step_deg", T::kNumber, "deg", "in [0.001, 10]", "0.5", "Spline step (720 / step an integer)."},
    {"function: cylinder_pressure", "crankcase_pressure", T::kNumber, "Pa", ">= 0", "1e5", "Under the piston."},
    {"function: cylinder_pressure", "output", T::kString, "", "force | pressure", "force", "`force`: (p − p_crankcase) π bore²/4 [N]; `pressure`: p [Pa]."},
};
// clang-format on

std::vector<SceneKey> AllKeys() {
  std::vector<SceneKey> keys(std::begin(kModelKeys), std::end(kModelKeys));
  for (std::span<const SceneKey> part : {internal::ForceKeys(), internal::RunKeys()})
    keys.insert(keys.end(), part.begin(), part.end());
  // Grouped by section in the order of kSections (a stable sort keeps each section's order).
  auto rank = [](std::string_view section) {
    for (std::size_t i = 0; i < std::size(kSections); ++i)
      if (kSections[i].id == section) return i;
    return std::size(kSections);
  };
  std::stable_sort(keys.begin(), keys.end(), [&](const SceneKey& a, const SceneKey& b) {
    return rank(a.section) < rank(b.section);
  });
  return keys;
}

}  // namespace

std::string_view Name(KeyType t) {
  switch (t) {
    case KeyType::kNumber:
      return "number";
    case KeyType::kInteger:
      return "integer";
    case KeyType::kBool:
      return "true/false";
    case KeyType::kString:
      return "text";
    case KeyType::kVector3:
      return "[x, y, z]";
    case KeyType::kNumbers:
      return "list of numbers";
    case KeyType::kList:
      return "list";
    case KeyType::kMap:
      return "map";
    case KeyType::kAny:
      return "see meaning";
  }
  return "?";
}

std::span<const SceneSection> SceneSections() { return kSections; }

std::span<const SceneKey> SceneKeys() {
  static const std::vector<SceneKey> keys = AllKeys();
  return keys;
}

const SceneKey* FindSceneKey(std::string_view section, std::string_view key) {
  for (const SceneKey& k : SceneKeys())
    if (k.section == section && k.key == key) return &k;
  return nullptr;
}

}  // namespace emb::scene
