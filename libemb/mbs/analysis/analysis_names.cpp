// Names and parsing of the analyses' enumerations (analysis.h).
#include <string>

#include "libemb/common/error.h"
#include "libemb/mbs/analysis/analysis.h"

namespace emb::mbs {
namespace {

struct TypeName {
  AnalysisType type;
  const char* name;
};
constexpr TypeName kTypeNames[] = {{AnalysisType::kAssemble, "assemble"},
                                   {AnalysisType::kKinematic, "kinematic"},
                                   {AnalysisType::kStatic, "static"},
                                   {AnalysisType::kQuasiStatic, "quasi-static"},
                                   {AnalysisType::kDynamic, "dynamic"}};

}  // namespace

const char* Name(AnalysisType type) {
  for (const auto& t : kTypeNames)
    if (t.type == type) return t.name;
  return "unknown";
}

const char* Name(PrepareStatus status) {
  switch (status) {
    case PrepareStatus::kReady:
      return "ready";
    case PrepareStatus::kNotAssembled:
      return "not-assembled";
    case PrepareStatus::kNoElasticStart:
      return "no-elastic-start";
  }
  return "unknown";
}

AnalysisType ParseAnalysisType(const std::string& name) {
  std::string valid;
  for (const auto& t : kTypeNames) {
    if (name == t.name) return t.type;
    valid += std::string(valid.empty() ? "" : ", ") + t.name;
  }
  EMB_THROW(InputError, "unknown analysis type '" << name << "': expected one of " << valid);
}

const char* Name(DynamicIntegrator integrator) {
  return integrator == DynamicIntegrator::kIda ? "ida" : "generalized-alpha";
}

DynamicIntegrator ParseDynamicIntegrator(const std::string& name) {
  for (DynamicIntegrator i : {DynamicIntegrator::kIda, DynamicIntegrator::kGeneralizedAlpha})
    if (name == Name(i)) return i;
  EMB_THROW(InputError, "integrator: expected 'ida' or 'generalized-alpha', got '" << name << "'");
}

const char* Name(ElasticStart start) {
  return start == ElasticStart::kAsGiven ? "as-given" : "quasi-static";
}

ElasticStart ParseElasticStart(const std::string& name) {
  for (ElasticStart s : {ElasticStart::kAsGiven, ElasticStart::kQuasiStatic})
    if (name == Name(s)) return s;
  EMB_THROW(InputError,
            "elastic_start: expected 'as-given' or 'quasi-static', got '" << name << "'");
}

const char* Name(RunStatus status) {
  switch (status) {
    case RunStatus::kSuccess:
      return "success";
    case RunStatus::kIntegratorFailure:
      return "integrator-failure";
    case RunStatus::kNewtonFailure:
      return "newton-failure";
    case RunStatus::kNotKinematic:
      return "not-kinematic";
  }
  return "unknown";
}

const char* Name(NewtonStatus status) {
  switch (status) {
    case NewtonStatus::kConverged:
      return "converged";
    case NewtonStatus::kMaxIterations:
      return "max-iterations";
    case NewtonStatus::kLineSearchFailed:
      return "line-search-failed";
    case NewtonStatus::kNonFinite:
      return "non-finite";
  }
  return "unknown";
}


}  // namespace emb::mbs
