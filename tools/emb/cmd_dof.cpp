// emb dof SCENE: the degrees-of-freedom report of a scene (seed eq. 1.25): the
// Gruebler-Kutzbach count, the true DOF from the rank of the constraint Jacobian at the
// assembled configuration, and the redundant equations by joint and equation.

#include <iostream>
#include <memory>

#include "libemb/common/error.h"
#include "libemb/common/number_check.h"
#include "libemb/mbs/constraints/assembly.h"
#include "libemb/mbs/constraints/dof_analysis.h"
#include "libemb/scene/scene.h"
#include "tools/emb/commands.h"
#include "tools/emb/common_options.h"

namespace emb::cli {
namespace {

struct DofCommand {
  std::string scene_file;
  OutputOptions out;
  double rank_tolerance{mbs::kRankTolerance};
  bool trust_geo{false};

  void Run() const {
    CheckNumber("--rank-tol", rank_tolerance, NumberRange::Open(0.0, 1.0));
    scene::SceneOptions options;
    options.trust_geo_scripts = trust_geo;
    const scene::Scene sc = scene::LoadScene(scene_file, options);
    const mbs::System& sys = sc.system;
    mbs::ConstraintWorkspace ws(sys);
    const mbs::AssemblyResult a = mbs::AssemblePositions(
        sys, sys.InitialPositions(), sc.analysis.t_start, &ws, sc.analysis.assembly);
    const mbs::DofReport r = mbs::AnalyzeDof(sys, a.q, sc.analysis.t_start, &ws, rank_tolerance);

    Table elements("Constraint elements of " + sc.name, {"name", "type", "equations"},
                   {"name", "type", "equations C"});
    for (const auto& e : r.elements)
      elements.AddRow({e.name, e.type, static_cast<long long>(e.count)});
    Table redundant("Redundant equations (later in the list = named)", {"equation"}, {"equation"});
    for (const auto& n : r.redundant_names) redundant.AddRow({n});
    Summary s("Degrees of freedom of " + sc.source);
    s.Add("parts", "parts n (with ground)", r.num_parts);
    s.Add("equations", "constraint equations sum C", r.num_equations);
    s.Add("gruebler_dof", "Gruebler-Kutzbach 6(n-1) - sum C", r.gruebler_dof);
    s.Add("rank", "rank of the constraint Jacobian", r.rank);
    s.Add("true_dof", "true DOF 6(n-1) - rank", r.true_dof);
    s.Add("redundant", "redundant equations", static_cast<long long>(r.redundant.size()));
    s.Add("rank_tolerance", "relative singular-value tolerance", r.rank_tolerance);
    s.Add("smallest_singular_value", "smallest kept singular value (relative)",
          r.smallest_kept_singular_value);
    s.Add("assembled", "assembled", a.converged);
    s.Add("assembly_residual", "assembly residual max|Phi|", a.residual);
    if (!a.converged) s.Add("assembly_message", "assembly", a.message);
    if (out.json) {
      PrintJson({{"summary", s.ToJson()},
                 {"elements", elements.ToJson()},
                 {"redundant", redundant.ToJson()}});
    } else {
      elements.Print(std::cout);
      std::cout << "\n";
      if (!r.redundant.empty()) {
        redundant.Print(std::cout);
        std::cout << "\n";
      }
      s.Print(std::cout);
    }
  }
};

}  // namespace

void RegisterDofCommand(CLI::App& app) {
  auto st = std::make_shared<DofCommand>();
  CLI::App* cmd = app.add_subcommand(
      "dof",
      "Degrees of freedom of a multibody scene: Gruebler-Kutzbach count, true DOF from the "
      "rank of the constraint Jacobian at the assembled pose, and the redundant equations "
      "named by joint and equation");
  cmd->add_option("scene", st->scene_file, "Scene file (YAML), e.g. tools/scenes/engine_a.yaml")
      ->required();
  cmd->add_option("--rank-tol", st->rank_tolerance,
                  "Relative singular-value tolerance for the rank of the constraint Jacobian")
      ->capture_default_str();
  cmd->add_flag("--trust-geo", st->trust_geo,
                "Give the geometry of `model: beam` parts to gmsh without checking it first: "
                "only for files you trust (README: Files from others)");
  st->out.Register(*cmd);
  cmd->callback([st] { st->Run(); });
}

}  // namespace emb::cli
