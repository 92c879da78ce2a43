// The keys of `forces:` (the key table, scene_keys.h).
#include "libemb/scene/scene_keys_parts.h"

namespace emb::scene::internal {
namespace {

using T = KeyType;

constexpr SceneKey kForceKeys[] = {
    {"forces", "name", T::kString, "", "", "required", "The element's name (load channels `<name>.F|T.*`)."},
    {"forces", "type", T::kString, "", "spring-damper | rotational-spring-damper | bushing | journal-bearing | torsional-damper | lash | clutch-damper | force | torque", "required", "The kind of element; its keys are in the section of that type."},
    // spring-damper
    {"forces: spring-damper", "i", T::kString, "", "", "required", "First marker."},
    {"forces: spring-damper", "j", T::kString, "", "", "required", "Second marker."},
    {"forces: spring-damper", "stiffness", T::kNumber, "N/m", ">= 0", "0", "k."},
    {"forces: spring-damper", "damping", T::kNumber, "N s/m", ">= 0", "0", "c."},
    {"forces: spring-damper", "free_length", T::kNumber, "m", ">= 0", "0", "Length at zero force."},
    // rotational-spring-damper
    {"forces: rotational-spring-damper", "i", T::kString, "", "", "required", "First marker."},
    {"forces: rotational-spring-damper", "j", T::kString, "", "", "required", "Second marker (the angle is about its z axis)."},
    {"forces: rotational-spring-damper", "stiffness", T::kNumber, "N m/rad", ">= 0", "0", "k."},
    {"forces: rotational-spring-damper", "damping", T::kNumber, "N m s/rad", ">= 0", "0", "c."},
    {"forces: rotational-spring-damper", "free_angle", T::kNumber, "rad", "", "0", "a₀."},
    // bushing
    {"forces: bushing", "i", T::kString, "", "", "required", "Marker of the loaded body."},
    {"forces: bushing", "j", T::kString, "", "", "required", "Marker whose axes measure the deflection."},
    {"forces: bushing", "stiffness", T::kNumbers, "N/m, N m/rad", "", "required", "6 diagonal entries [kx, ky, kz, krx, kry, krz] or 36 row by row."},
    {"forces: bushing", "damping", T::kNumbers, "N s/m, N m s/rad", "", "—", "Same forms; absent: none."},
    {"forces: bushing", "damping_factor", T::kNumber, "s", ">= 0", "—", "Adds factor × stiffness to the damping (the seed's damping as a fraction of stiffness)."},
    // journal-bearing
    {"forces: journal-bearing", "i", T::kString, "", "", "required", "Journal marker."},
    {"forces: journal-bearing", "j", T::kString, "", "", "required", "Bearing marker; its z axis is the bearing axis."},
    {"forces: journal-bearing", "radius", T::kNumber, "m", "> 0", "required", "Journal radius R."},
    {"forces: journal-bearing", "length", T::kNumber, "m", "> 0", "required", "Bearing length L (L/D ≤ 1)."},
    {"forces: journal-bearing", "clearance", T::kNumber, "m", "> 0", "required", "Radial clearance c (< R)."},
    {"forces: journal-bearing", "viscosity", T::kNumber, "Pa s", "> 0", "required", "Dynamic viscosity μ."},
    // torsional-damper
    {"forces: torsional-damper", "hub", T::kString, "", "", "required", "The hub marker; the ring turns about its z axis."},
    {"forces: torsional-damper", "ring_mass", T::kNumber, "kg", "> 0", "required", "Ring mass."},
    {"forces: torsional-damper", "ring_inertia", T::kNumber, "kg m^2", "> 0", "required", "Ring polar inertia."},
    {"forces: torsional-damper", "stiffness", T::kNumber, "N m/rad", ">= 0", "0", "Kelvin–Voigt rubber k (0: a viscous Houdaille ring); not with `rubber`."},
    {"forces: torsional-damper", "damping", T::kNumber, "N m s/rad", ">= 0", "0", "Kelvin–Voigt rubber c; not with `rubber`."},
    {"forces: torsional-damper", "rubber", T::kMap, "", "", "—", "A frequency-dependent rubber instead (section *forces: torsional-damper rubber*)."},
    {"forces: torsional-damper rubber", "static_stiffness", T::kNumber, "N m/rad", ">= 0", "required", "k∞ (with `arms`)."},
    {"forces: torsional-damper rubber", "arms", T::kList, "", "", "required", "Maxwell arms (with `static_stiffness`), a non-empty list."},
    {"forces: torsional-damper rubber", "dynamic_stiffness", T::kNumber, "N m/rad", "> 0", "required", "|k*| at `frequency_hz` (the supplier form)."},
    {"forces: torsional-damper rubber", "loss_factor", T::kNumber, "(Im k*/Re k*)", "in [0, 1]", "required", "η = Im k*/Re k* at its peak, > 0 (the supplier form)."},
    {"forces: torsional-damper rubber", "frequency_hz", T::kNumber, "Hz", "> 0", "required", "Where the loss factor peaks (the supplier form)."},
    {"forces: torsional-damper rubber", "band_hz", T::kNumber, "Hz", "> 0", "5000", "Up to where the junction rings keep k*(ω) within `junction_error`."},
    {"forces: torsional-damper rubber", "junction_error", T::kNumber, "", "in [1e-12, 0.1]", "0.001", "Bound on the relative error of k*(ω) up to `band_hz`."},
    {"forces: torsional-damper rubber arm", "stiffness", T::kNumber, "N m/rad", "> 0", "required", "kⱼ."},
    {"forces: torsional-damper rubber arm", "relaxation_time", T::kNumber, "s", "> 0", "required", "τⱼ = cⱼ/kⱼ."},
    // lash
    {"forces: lash", "joint1", T::kString, "", "", "required", "The joint of g₁."},
    {"forces: lash", "coordinate1", T::kString, "", "rotation | translation", "rotation", "Its coordinate."},
    {"forces: lash", "joint2", T::kString, "", "", "—", "The joint of g₂ (a gear mesh); absent: x = g₁ − offset."},
    {"forces: lash", "coordinate2", T::kString, "", "rotation | translation", "rotation", "With `joint2`: its coordinate."},
    {"forces: lash", "ratio", T::kNumber, "", "", "required", "With `joint2`: the gear ratio (x in units of joint 1)."},
    {"forces: lash", "lash", T::kNumber, "rad or m", ">= 0", "—", "Free play centred on `offset` (or give `stops`)."},
    {"forces: lash", "offset", T::kNumber, "rad or m", "", "0", "Centre of the free play."},
    {"forces: lash", "stops", T::kNumbers, "rad or m", "", "—", "[lower, upper] instead of `lash` and `offset`."},
    {"forces: lash", "contact", T::kMap, "", "", "required", "Section *forces: lash contact*."},
    {"forces: lash", "squeeze_film", T::kMap, "", "", "—", "Section *forces: lash squeeze_film*; absent: none."},
    {"forces: lash contact", "law", T::kString, "", "hunt-crossley | kelvin-voigt", "hunt-crossley", "Hunt–Crossley kδⁿ(1 + χδ′) or Kelvin–Voigt kδ + cδ′ (tension cut off)."},
    {"forces: lash contact", "stiffness", T::kNumber, "N/m or N m/rad", "> 0", "required", "k."},
    {"forces: lash contact", "exponent", T::kNumber, "", "in [1, 10]", "1", "Hunt–Crossley n."},
    {"forces: lash contact", "restitution", T::kNumber, "", "in (0, 1]", "required", "Coefficient of restitution e (Hunt–Crossley; Kelvin–Voigt without `damping`)."},
    {"forces: lash contact", "min_impact_velocity", T::kNumber, "m/s or rad/s", "> 0", "0.001", "Hunt–Crossley: floor of the closing speed in χ = z(e)/v₋."},
    {"forces: lash contact", "damping", T::kNumber, "N s/m or N m s/rad", ">= 0", "—", "Kelvin–Voigt: c given instead of `restitution` and `effective_inertia`."},
    {"forces: lash contact", "effective_inertia", T::kNumber, "kg or kg m^2", "> 0", "required", "Kelvin–Voigt with `restitution`: the impact's effective inertia (gives c)."},
    {"forces: lash squeeze_film", "viscosity", T::kNumber, "Pa s", "> 0", "required", "Lubricant viscosity η."},
    {"forces: lash squeeze_film", "width", T::kNumber, "m", "> 0", "required", "Contact width b."},
    {"forces: lash squeeze_film", "radius", T::kNumber, "m", "> 0", "required", "Equivalent radius r_x."},
    {"forces: lash squeeze_film", "lever", T::kNumber, "m/rad or m/m", "> 0", "1", "R: film gap per unit of x."},
    {"forces: lash squeeze_film", "min_film", T::kNumber, "m", "> 0", "1e-6", "h_min, the film left at contact."},
    // clutch-damper
    {"forces: clutch-damper", "joint", T::kString, "", "", "—", "The joint whose rotation it acts on; absent: `i` and `j`."},
    {"forces: clutch-damper", "i", T::kString, "", "", "required", "Without `joint`: first marker."},
    {"forces: clutch-damper", "j", T::kString, "", "", "required", "Without `joint`: second marker (angle about its z)."},
    {"forces: clutch-damper", "stiffness", T::kNumbers, "N m/rad", "", "required", "[k1, k2]: below and beyond the knee."},
    {"forces: clutch-damper", "knee_angle", T::kNumber, "rad", ">= 0", "required", "Where the second stage starts."},
    {"forces: clutch-damper", "damping", T::kNumber, "N m s/rad", ">= 0", "0", "Viscous damping."},
    {"forces: clutch-damper", "hysteresis_torque", T::kNumber, "N m", ">= 0", "0", "Friction T_h of T_h tanh(θ′/ω_h)."},
    {"forces: clutch-damper", "hysteresis_speed", T::kNumber, "rad/s", "> 0", "0.1", "ω_h."},
    {"forces: clutch-damper", "free_angle", T::kNumber, "rad", "", "0", "Angle at zero spring torque."},
    // force, torque
    {"forces: force, torque", "marker", T::kString, "", "", "required", "Where the load acts."},
    {"forces: force, torque", "direction", T::kVector3, "", "", "required", "Unit vector."},
    {"forces: force, torque", "frame", T::kString, "", "world | marker", "world", "Axes of `direction`."},
    {"forces: force, torque", "reaction_marker", T::kString, "", "", "—", "An equal and opposite load on this marker's body."},
    {"forces: force, torque", "function", T::kMap, "", "", "required", "Section *function*: magnitude [N or N m]."},
    {"forces: force, torque", "argument", T::kMap, "", "", "—", "Section *forces: load argument*; absent: the time."},
    {"forces: load argument", "joint", T::kString, "", "", "required", "The joint whose rotation angle (continuous across turns) is the argument; or give `i` and `j`."},
    {"forces: load argument", "i", T::kString, "", "", "required", "Without `joint`: the angle of x_I ..."},
    {"forces: load argument", "j", T::kString, "", "", "required", "... about z_J (a crank on bushings)."},
    {"forces: load argument", "unit", T::kString, "", "rad | deg", "rad", "The argument's unit."},
    {"forces: load argument", "offset", T::kNumber, "", "", "0", "Added to the angle, in `unit`."},
};

}  // namespace

std::span<const SceneKey> ForceKeys() { return kForceKeys; }

}  // namespace emb::scene::internal
