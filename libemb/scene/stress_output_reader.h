#pragma once
/// @file
/// The scene section `stress_outputs` (internal to emb_scene): hot-spot stress histories of a
/// flexible part's stress groups (mbs/parts/stress_probe.h), the groups' stress fields at
/// chosen times (XDMF, written by `emb run`) and a fatigue summary (results/stress_recorder.h).
///
///   stress_outputs:
///     - name: fillets                    # channels fillets.<group>.von_mises, ...
///       body: crank                      # a cms part whose body file has modal stresses
///       groups: [crankpin_fillet_1]      # default: every stress group of the body file
///       nodes: [1234]                    # full components: fillets.n1234.xx ... (optional)
///       field_times: [0.05, 0.06]        # XDMF of the groups' stress fields [s] (optional)
///       surface_field_times: [0.05]      # XDMF of the whole surface's field [s] (optional;
///                                        # the body file needs emb reduce --stress-surface)
///       fatigue:                         # optional
///         measure: max_principal         # or signed_von_mises
///         fatigue_strength_coefficient: 1.2e9   # Basquin sigma_f' [Pa]
///         exponent: -0.085                       # Basquin b, in (-1, 0)
///         ultimate_strength: 9.0e8               # Goodman sigma_u [Pa]
///         endurance_limit: 0                     # [Pa], optional

#include <yaml-cpp/yaml.h>

#include <map>
#include <string>
#include <vector>

#include "libemb/mbs/core/system.h"
#include "libemb/mbs/parts/flexible_body.h"
#include "libemb/results/stress_output.h"

namespace emb::scene {

/// The modal stresses a part's body file holds: its groups and (optional) whole surface.
struct PartStresses {
  std::vector<ModalStressGroup> groups;
  ModalStressSurface surface;
};

/// Reads the list (`stresses`: the body files' modal stresses by part), adds a stress probe
/// per entry to `sys` (not finalized) and returns the entries. @throws InputError with
/// file:line naming the entry: unknown body, a rigid part or one without a body file, a body
/// file without modal stresses (or without the surface that surface_field_times need), an
/// unknown group, a node in none of the groups, a bad S-N curve, a non-finite field time,
/// an empty list or a repeated entry of groups, nodes or field times, bad keys.
/// @throws InputError naming the output and key for a field time outside the run's
/// [t_start, t_end] (no sample of the run would be written there).
void CheckStressOutputTimes(const std::vector<results::StressOutput>& outputs, double t_start,
                            double t_end);

std::vector<results::StressOutput> ReadStressOutputs(
    const YAML::Node& list, const std::string& file, mbs::System* sys,
    const std::map<std::string, mbs::FlexiblePart>& body_file_parts,
    const std::map<std::string, PartStresses>& stresses);

}  // namespace emb::scene
