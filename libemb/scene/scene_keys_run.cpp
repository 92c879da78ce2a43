// The keys of sensors, output points, stress outputs, the analysis and the output (the key
// table, scene_keys.h).
#include "libemb/scene/scene_keys_parts.h"

namespace emb::scene::internal {
namespace {

using T = KeyType;

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

}  // namespace

std::span<const SceneKey> RunKeys() { return kRunKeys; }

}  // namespace emb::scene::internal
