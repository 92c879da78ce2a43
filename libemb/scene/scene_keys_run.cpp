// The keys of the force elements, the outputs (sensors, output points, stress outputs,
// output) and the analysis: the second half of the key table (scene_keys.h).
#include "libemb/scene/scene_keys_parts.h"

namespace emb::scene::internal {
namespace {

using T = KeyType;

// One entry a line, as the table it is (clang-format would spread each over three lines).
// clang-format off
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
    {"forces: lash", "ratio", T::kNumber, "", "", "required", "With `joint2` (another coordinate than joint1): the gear ratio ≠ 0 (x in units of joint 1)."},
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

constexpr SceneKey kRunKeys[] = {
    // sensors
    {"sensors", "name", T::kString, "", "", "required", "The sensor's name (channels `<name>.*`)."},
    {"sensors", "type", T::kString, "", "pose | chord", "pose", "`pose`: position of marker i in j's axes and the rotation vector of R_Jᵀ R_I (channels `.dx .dy .dz .rx .ry .rz`); `chord`: deflection of `point` from the line through the two `chord` markers (channels `.dx .dy .dz` in the first end's axes, `.norm`, `.s`)."},
    {"sensors", "i", T::kString, "", "", "required", "`pose`: the marker observed."},
    {"sensors", "j", T::kString, "", "", "required", "`pose`: the reference marker."},
    {"sensors", "point", T::kString, "", "", "required", "`chord`: the marker whose deflection is measured."},
    {"sensors", "chord", T::kList, "", "", "required", "`chord`: [marker_a, marker_b], the chord's ends."},
    // output points
    {"output_points", "name", T::kString, "", "", "required", "The point's name (channels `<name>.u|v|a.{x,y,z,n}` or `<name>.power`)."},
    {"output_points", "body", T::kString, "", "", "required", "A part from a body file (cms, rigid, or beam with `body_file`)."},
    {"output_points", "node", T::kInteger, "", "", "—", "A node of the body file's mesh (0-based); or `position`, or `group`."},
    {"output_points", "position", T::kVector3, "m", "", "—", "Mesh coordinates of a node (within `tolerance`)."},
    {"output_points", "tolerance", T::kNumber, "m", "> 0", "1e-6", "How far `position` may be from the node."},
    {"output_points", "group", T::kString, "", "", "", "A surface group of the mesh: its area-weighted mean."},
    {"output_points", "quantity", T::kString, "", "motion | radiated_power", "motion", "`motion`: displacement Φη, velocity and acceleration; `radiated_power`: ∫(v·n)² dA over the group [m⁴/s²]."},
    {"output_points", "direction", T::kAny, "", "", "—", "`radial` (with `axis`), `normal` (groups) or [x, y, z] (unit): adds the `.n` components."},
    {"output_points", "axis", T::kMap, "", "", "—", "Section *output_points: axis* (with `direction: radial`)."},
    {"output_points: axis", "point", T::kVector3, "m", "", "[0, 0, 0]", "A point of the axis, mesh coordinates."},
    {"output_points: axis", "direction", T::kVector3, "", "", "required", "The axis, a unit vector."},
    // stress outputs
    {"stress_outputs", "name", T::kString, "", "", "required", "The output's name (channels `<name>.<group>.von_mises` ...)."},
    {"stress_outputs", "body", T::kString, "", "", "required", "A `model: cms` part whose body file has modal stresses (`emb reduce --stress-groups`)."},
    {"stress_outputs", "groups", T::kList, "", "", "—", "Stress groups to watch; absent: every group of the body file."},
    {"stress_outputs", "nodes", T::kList, "", "", "—", "Mesh nodes (0-based) whose six stress components become channels `<name>.n<node>.xx` ..."},
    {"stress_outputs", "field_times", T::kNumbers, "s", "", "—", "Times at which the groups' stress fields go to `<results>.stress.h5` + `.xdmf`."},
    {"stress_outputs", "surface_field_times", T::kNumbers, "s", "", "—", "Times at which the whole surface's field is written (`emb reduce --stress-surface`)."},
    {"stress_outputs", "fatigue", T::kMap, "", "", "—", "Section *stress_outputs: fatigue*; absent: no fatigue summary."},
    {"stress_outputs: fatigue", "measure", T::kString, "", "max_principal | signed_von_mises", "max_principal", "The stress counted at every node."},
    {"stress_outputs: fatigue", "fatigue_strength_coefficient", T::kNumber, "Pa", "", "required", "Basquin σ_f′ (> 0); or `sn_points`."},
    {"stress_outputs: fatigue", "exponent", T::kNumber, "", "", "required", "Basquin b, in (−1, 0)."},
    {"stress_outputs: fatigue", "sn_points", T::kList, "", "", "—", "[[N, S], ...] instead of the Basquin pair: N rising, S falling [Pa]."},
    {"stress_outputs: fatigue", "ultimate_strength", T::kNumber, "Pa", "", "required", "Goodman σ_u (> 0)."},
    {"stress_outputs: fatigue", "endurance_limit", T::kNumber, "Pa", "", "0", "Amplitudes below it do no damage."},
    // analysis
    {"analysis", "type", T::kString, "", "assemble | kinematic | static | quasi-static | dynamic", "dynamic", "`assemble`: consistent initial conditions only; `kinematic`: DOF 0; `static`, `quasi-static`: Newton with a line search; `dynamic`: the GGL index-2 DAE."},
    {"analysis", "t_start", T::kNumber, "s", "", "0", "Start time."},
    {"analysis", "t_end", T::kNumber, "s", "", "1", "End time (not with `steady_state`)."},
    {"analysis", "output_step", T::kNumber, "s", "> 0", "0.01", "Time between samples."},
    {"analysis", "rtol", T::kNumber, "", "in (0, 1)", "1e-6", "Relative tolerance."},
    {"analysis", "atol", T::kNumber, "", "> 0", "1e-8", "Absolute tolerance (m, -, m/s, rad/s); raised, with a warning, to the floor below."},
    {"analysis", "atol_floor_relative", T::kNumber, "", "in [0, 1]", "1e-13", "atol floor = this × max(1, model size in m): round-off."},
    {"analysis", "initial_step_fraction", T::kNumber, "", "in [0, 1]", "0.001", "IDA's first step = this × output_step (0: IDA's own estimate)."},
    {"analysis", "newton_convergence_factor", T::kNumber, "", "in (0, 1)", "0.03", "IDA's Newton convergence factor (SUNDIALS' own: 0.33)."},
    {"analysis", "multiplier_atol", T::kNumber, "N", ">= 0", "0", "> 0: the multipliers' absolute tolerance [N, N m] instead of the rules below."},
    {"analysis", "multiplier_atol_relative", T::kNumber, "", "in (0, 1)", "—", "A fixed multiplier atol = this × the largest force at t₀ instead of the rtol rule."},
    {"analysis", "multiplier_atol_rtol_factor", T::kNumber, "", "in (0, 1000000)", "100", "The multipliers' atol = min(1e-4, this × rtol) × the largest force at t₀."},
    {"analysis", "modal_velocity_atol_by_frequency", T::kBool, "", "", "true", "Flexible bodies: atol × max(1, ω_j) on the modal velocity of mode j (velocity and displacement weighed alike); `false`: one atol."},
    {"analysis", "max_step", T::kNumber, "s", ">= 0", "0", "Largest step; 0: unlimited."},
    {"analysis", "max_steps", T::kInteger, "", "[1, 1000000000]", "500000", "Steps per output interval."},
    {"analysis", "max_events", T::kInteger, "", "[1, 1000000000]", "1000000", "Located events (contact closings, openings, force peaks) before the run stops as a failure."},
    {"analysis", "linear_solver", T::kString, "", "auto | dense | klu", "auto", "The iteration matrix's solver; `auto`: KLU from 50 unknowns."},
    {"analysis", "integrator", T::kString, "", "ida | generalized-alpha", "ida", "IDA (variable-order BDF) or generalized-α (second order, numerical damping `rho_inf`; refuses models with events)."},
    {"analysis", "elastic_start", T::kString, "", "as-given | quasi-static", "as-given", "`quasi-static`: flexible parts start on their quasi-static deformation under the initial loads and motion (dynamic only)."},
    {"analysis", "rho_inf", T::kNumber, "", "", "0.5", "generalized-α: spectral radius at h ω → ∞, in [0, 1]."},
    {"analysis", "remove_redundant", T::kBool, "", "", "false", "`true`: drop the redundant equations `emb dof` names, with a warning (otherwise a run with redundant equations stops)."},
    {"analysis", "assembly_tolerance", T::kNumber, "", "in (0, 1)", "1e-10", "Position assembly: largest constraint residual."},
    {"analysis", "assembly_iterations", T::kInteger, "", "[1, 100000]", "50", "Position assembly: Newton iterations."},
    {"analysis", "static_tolerance", T::kNumber, "", "in (0, 1)", "1e-9", "Static and quasi-static: relative force residual."},
    {"analysis", "static_iterations", T::kInteger, "", "[1, 100000]", "100", "Static and quasi-static: Newton iterations per solve."},
    {"analysis", "steady_state", T::kMap, "", "", "—", "Section *analysis: steady_state*."},
    {"analysis: steady_state", "period", T::kNumber, "s", "> 0", "required", "One cycle (an engine cycle: two turns), a whole number of output steps."},
    {"analysis: steady_state", "channels", T::kList, "", "", "required", "CSV channel names that must repeat."},
    {"analysis: steady_state", "tolerance", T::kNumber, "", "> 0", "0.001", "Relative RMS change of every channel, cycle to cycle."},
    {"analysis: steady_state", "min_cycles", T::kInteger, "", "[1, 100000]", "2", "Whole cycles before convergence may be declared."},
    {"analysis: steady_state", "max_cycles", T::kInteger, "", "[1, 100000]", "20", "The run ends here, converged or not (not converged: exit 3, results kept)."},
    // planar, output
    {"planar", "normal", T::kVector3, "", "", "required", "The plane's normal (non-zero)."},
    {"output", "file", T::kString, "", "", "", "HDF5 results file; empty: none unless `-o`."},
    {"output", "csv", T::kString, "", "", "", "CSV of the channels; empty: none unless `--csv`."},
    {"output", "channels", T::kList, "", "", "—", "CSV channel names; absent: all."},
};
// clang-format on

}  // namespace

std::span<const SceneKey> ForceKeys() { return kForceKeys; }
std::span<const SceneKey> RunKeys() { return kRunKeys; }

}  // namespace emb::scene::internal
