// PrepareRun: assembly, velocity projection, installed bases and the elastic start before
// any analysis (analysis.h).
#include <cmath>
#include <limits>
#include <sstream>

#include "libemb/common/error.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/analysis/analysis_internal.h"
#include "libemb/mbs/analysis/quasi_static_start.h"
#include "libemb/mbs/constraints/constraint_eval.h"
#include "libemb/mbs/constraints/out_of_plane.h"
#include "libemb/mbs/core/rotation.h"

namespace emb::mbs {

PreparedRun PrepareRun(const System& system, const AnalysisSettings& settings) {
  EMB_CHECK(system.finalized());
  EMB_THROW_IF(!(settings.t_end >= settings.t_start), "analysis: expected t_end >= t_start, got "
                                                          << settings.t_end << " < "
                                                          << settings.t_start);
  EMB_THROW_IF(!(settings.output_step > 0.0),
               "analysis: expected a positive output step, got " << settings.output_step);
  (void)internal::OutputTimes{settings};  // throws for times the output step cannot resolve
  PreparedRun run;
  run.system = system;
  const auto fail = [&run](PrepareStatus status, std::string message) {
    run.status = status;
    run.message = std::move(message);
    return std::move(run);
  };
  ConstraintWorkspace ws(system);
  const AssemblyResult a = AssemblePositions(system, system.InitialPositions(), settings.t_start,
                                             &ws, settings.assembly);
  if (!a.converged)
    return fail(PrepareStatus::kNotAssembled, "the model cannot be assembled: " + a.message);
  run.dof = AnalyzeDof(system, a.q, settings.t_start, &ws);
  const bool planar = settings.plane_normal.squaredNorm() > 0.0;
  EMB_THROW_IF(planar && std::abs(settings.plane_normal.norm() - 1.0) > 1e-12,
               "planar: expected a unit plane normal, got norm " << settings.plane_normal.norm());
  if (planar && !run.dof.redundant.empty()) {
    const std::vector<int> in_plane = EquationsWithInPlaneTerms(
        system, a.q, settings.t_start, run.dof.redundant, settings.plane_normal, &ws);
    if (in_plane.empty()) {  // all out of the plane: dropped quietly
      run.system = system.WithoutEquations(run.dof.redundant);
      run.planar_removed = run.dof.redundant_names;
      run.dof.redundant.clear();
      run.dof.redundant_names.clear();
    } else if (!settings.remove_redundant) {
      std::ostringstream list;
      for (int k : in_plane) list << "\n  " << system.EquationName(k);
      EMB_THROW(InputError, "planar (normal " << settings.plane_normal.transpose()
                                << "): " << in_plane.size()
                                << " redundant constraint equation(s) act in the plane, so "
                                   "the mechanism is not planar about that normal there:"
                                << list.str()
                                << "\ncheck the joint axes (all along the normal for "
                                   "revolutes) or set remove_redundant: true to drop the "
                                   "redundant equations with a warning");
    }
  }
  if (!run.dof.redundant.empty()) {
    std::ostringstream list;
    for (const auto& n : run.dof.redundant_names) list << "\n  " << n;
    if (!settings.remove_redundant)
      EMB_THROW(InputError, run.dof.redundant.size()
                                << " redundant constraint equation(s) (Gruebler count "
                                << run.dof.gruebler_dof << ", true DOF " << run.dof.true_dof
                                << "):" << list.str()
                                << "\nremove them from the model or set "
                                   "remove_redundant: true to drop exactly these");
    run.system = system.WithoutEquations(run.dof.redundant);
    run.warnings.push_back("removed " + std::to_string(run.dof.redundant.size()) +
                           " redundant equation(s):" + list.str());
  }
  ConstraintWorkspace ws2(run.system);
  // Re-assemble in the reduced system so its angle slots are on the same branch.
  const AssemblyResult a2 =
      AssemblePositions(run.system, a.q, settings.t_start, &ws2, settings.assembly);
  if (!a2.converged)
    return fail(PrepareStatus::kNotAssembled, "the model cannot be assembled: " + a2.message);
  run.q0 = a2.q;
  const bool moving =
      settings.type == AnalysisType::kDynamic || settings.type == AnalysisType::kAssemble;
  run.truncations = CalcTruncationReports(run.system, settings.truncated_bases);
  for (const TruncationReport& t : run.truncations)
    if (std::string w = TruncationWarning(t, settings.truncation_warning_threshold); !w.empty())
      run.warnings.push_back(std::move(w));
  if (!settings.installed_bases.empty()) {
    // The installed modes about the assembled start (with its velocities: centrifugal terms).
    Eigen::VectorXd v0 = Eigen::VectorXd::Zero(run.system.layout().nv());
    if (moving)
      v0 = ProjectVelocities(run.system, run.q0, run.system.InitialVelocities(),
                             settings.t_start, &ws2)
               .v;
    const AccelerationSolution acc =
        SolveAccelerations(run.system, run.q0, v0, settings.t_start, &ws2);
    const InstalledBases ib = CalcInstalledBases(run.system, run.q0, v0, settings.t_start,
                                                 acc.lambda, &ws2, settings.installed_bases);
    System changed = run.system.WithElasticBases(ib.changes);
    run.q0 = MapElasticCoordinates(run.system, changed, ib.changes, run.q0, true);
    run.system = std::move(changed);
    run.bases = ib.reports;
    ws2 = ConstraintWorkspace(run.system);
    const AssemblyResult a3 =
        AssemblePositions(run.system, run.q0, settings.t_start, &ws2, settings.assembly);
    if (!a3.converged)
    return fail(PrepareStatus::kNotAssembled, "the model cannot be assembled: " + a3.message);
    run.q0 = a3.q;
  }
  if (moving) {
    const VelocityProjection p = ProjectVelocities(
        run.system, run.q0, run.system.InitialVelocities(), settings.t_start, &ws2);
    run.v0 = p.v;
    if (p.relative_change > settings.velocity_warning_threshold) {
      std::ostringstream o;
      o << "initial velocities were inconsistent with the constraints and were projected "
           "(relative change "
        << p.relative_change << " in the kinetic-energy norm)";
      run.warnings.push_back(o.str());
    }
    if (settings.type == AnalysisType::kDynamic &&
        settings.elastic_start == ElasticStart::kQuasiStatic) {
      QuasiStaticStartOptions qs;
      qs.assembly = settings.assembly;
      const QuasiStaticStartReport start =
          SetQuasiStaticStart(run.system, settings.t_start, &run.q0, &run.v0, &ws2, qs);
      if (!start.converged) return fail(PrepareStatus::kNoElasticStart, start.message);
      run.start_note = start.message;
    }
  } else {
    run.v0 = Eigen::VectorXd::Zero(run.system.layout().nv());
  }
  return run;
}

void ThrowIfNotReady(const PreparedRun& run, const std::string& context) {
  const std::string what = context.empty() ? run.message : context + ": " + run.message;
  switch (run.status) {
    case PrepareStatus::kReady:
      return;
    case PrepareStatus::kNotAssembled:
      throw InputError(what);
    case PrepareStatus::kNoElasticStart:
      throw NumericalError(what);
  }
  throw NumericalError(what);
}


}  // namespace emb::mbs
