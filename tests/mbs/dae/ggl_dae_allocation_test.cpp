// The GGL DAE evaluates its residual and iteration matrix without touching the heap once its
// workspace has been through one of each (ggl_workspace.h): counted here with a replaced
// global operator new, on a model with every kind of term an engine run has (a flexible body
// with interface markers, a revolute joint, a bushing, a spring-damper, a torsional
// spring-damper, a journal bearing, an applied load with a time function, a Maxwell arm with a
// state of its own, a finite-width film bearing with its film as states, a driveline lash with a squeeze film and a clutch damper on a joint of the
// flexible body), over many states and over IDA steps.

#include <gtest/gtest.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <memory>
#include <string>
#include <utility>

#include "libemb/driveline/clutch_damper.h"
#include "libemb/driveline/lash.h"
#include "libemb/engine/film_bearing.h"
#include "libemb/engine/journal_bearing.h"
#include "libemb/integrators/ida_solver.h"
#include "libemb/mbs/analysis/analysis.h"
#include "libemb/mbs/dae/ggl_dae.h"
#include "libemb/mbs/forces/applied_load.h"
#include "libemb/mbs/forces/bushing.h"
#include "libemb/mbs/forces/maxwell_arm.h"
#include "libemb/mbs/forces/spring_damper.h"
#include "libemb/mbs/parts/flexible_body.h"
#include "tests/support/pinned_bar.h"

// Every heap allocation goes through malloc (operator new and Eigen's dynamic matrices
// alike): this test binary replaces the malloc family by counting wrappers around glibc's.
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* __libc_memalign(std::size_t, std::size_t);
}

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};

void Count() {
  if (g_counting.load(std::memory_order_relaxed))
    g_allocations.fetch_add(1, std::memory_order_relaxed);
}

// Counts the allocations made (by any thread) while it lives.
class CountAllocations {
 public:
  CountAllocations() {
    g_allocations = 0;
    g_counting = true;
  }
  ~CountAllocations() { g_counting = false; }
  long count() const { return g_allocations.load(); }
};
}  // namespace

extern "C" {
void* malloc(std::size_t size) {
  Count();
  return __libc_malloc(size);
}
void* calloc(std::size_t n, std::size_t size) {
  Count();
  return __libc_calloc(n, size);
}
void* realloc(void* p, std::size_t size) {
  Count();
  return __libc_realloc(p, size);
}
void* memalign(std::size_t alignment, std::size_t size) {
  Count();
  return __libc_memalign(alignment, size);
}
void* aligned_alloc(std::size_t alignment, std::size_t size) {
  Count();
  return __libc_memalign(alignment, size);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t size) {
  Count();
  *out = __libc_memalign(alignment, size);
  return *out ? 0 : ENOMEM;
}
}

namespace emb {
namespace {

// A rigid rotor at p spinning about z at omega [rad/s], held in its plane by a planar joint
// between a marker at its centre and one on the ground there: (rotor marker, ground marker).
std::pair<int, int> AddSpinningRotor(mbs::System* sys, const std::string& name,
                                     const std::string& rotor_marker,
                                     const std::string& ground_marker, const Eigen::Vector3d& p,
                                     double mass, const Eigen::Vector3d& inertia, double omega) {
  mbs::RigidBody b;
  b.name = name;
  b.mass = mass;
  b.inertia_B = inertia.asDiagonal();
  b.p_WB = p;
  b.omega_W = Eigen::Vector3d(0, 0, omega);
  sys->AddBody(b);
  const int on_rotor = sys->AddMarker(rotor_marker, name, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  const int on_ground = sys->AddMarker(ground_marker, "ground", p, Eigen::Matrix3d::Identity());
  sys->AddJoint(name + "_plane", mbs::JointType::kPlanar, rotor_marker, ground_marker);
  return {on_rotor, on_ground};
}

// A flexible bar pinned at x0, spinning about the pin, held at x1 by a bushing and a
// spring-damper to the ground, with a rigid disc on a journal bearing beside it whose shaft is
// loaded by a harmonic force, a torsional spring and a Maxwell arm (a state of its own).
mbs::System Model() {
  testing::PinnedBar m = testing::PinnedSpinningBar();
  mbs::System& sys = m.sys;
  const int tip = m.tip, spring_end = m.spring_end;
  sys.AddForceElement(std::make_shared<mbs::TranslationalSpringDamper>("tip_spring", tip, spring_end,
                                                                       2.0e3, 5.0, 0.01));
  // A disc on a journal bearing (Ocvirk), its shaft axis z, spinning.
  const auto [shaft, bore] = AddSpinningRotor(&sys, "disc", "shaft", "bore", Eigen::Vector3d(1.0, 0.5, 0.0),
                                              2.0, Eigen::Vector3d(2e-3, 2e-3, 3e-3), 200.0);
  mbs::JournalBearingParameters jb;
  jb.radius = 0.02;
  jb.length = 0.015;
  jb.clearance = 5e-5;
  jb.viscosity = 0.01;
  sys.AddForceElement(std::make_shared<mbs::JournalBearing>("bearing", shaft, bore, jb));
  sys.AddForceElement(std::make_shared<mbs::RotationalSpringDamper>("torsion", shaft, bore, 50.0,
                                                                    0.1, 0.0));
  // An element with a continuous state (force_element.h): its rows and blocks too.
  sys.AddForceElement(std::make_shared<mbs::MaxwellArm>("rubber", shaft, bore, 30.0, 0.05));
  // A rotor in a finite-width film bearing with its JFO film as states (film_bearing.h): the
  // film's residual, its five-point block and the marker and force-by-state blocks.
  const auto [journal, shell] = AddSpinningRotor(&sys, "rotor", "journal", "shell",
                                                 Eigen::Vector3d(-1.0, 0.5, 0.0), 3.0,
                                                 Eigen::Vector3d(3e-3, 3e-3, 4e-3), 300.0);
  tribology::ReynoldsBearingParameters film;
  film.radius = 0.02;
  film.length = 0.015;
  film.clearance = 5e-5;
  film.grid = {16, 4};
  film.lubricant.viscosity = 0.01;
  film.oil_holes.push_back({1.5, 0.0, 0.006, 2e5});
  sys.AddForceElement(std::make_shared<mbs::FilmBearing>("film", journal, shell, film));
  // Driveline elements on the pin's rotation (a marker of the flexible bar): a lash whose stops
  // are far (open, its squeeze film resisting the approach) and a two-stage clutch damper.
  driveline::LashParameters lash;
  lash.lower = -100.0;
  lash.upper = 100.0;
  lash.contact.stiffness = 1e6;
  lash.contact.exponent = 1.5;
  lash.contact.restitution = 0.8;
  lash.squeeze_film = driveline::SqueezeFilmParameters{0.05, 0.01, 0.02, 0.03, 1e-6};
  sys.AddForceElement(std::make_shared<driveline::Lash>(
      "lash",
      std::vector<driveline::CoordinateTerm>{driveline::JointCoordinateTerm(
          sys, "pin", mbs::JointCoordinate::kRotation, 1.0, "lash")},
      lash));
  driveline::ClutchDamperParameters clutch;
  clutch.stiffness_1 = 5.0;
  clutch.stiffness_2 = 50.0;
  clutch.knee_angle = 0.1;
  clutch.damping = 0.01;
  clutch.hysteresis_torque = 0.5;
  sys.AddForceElement(std::make_shared<driveline::ClutchDamper>(
      "clutch",
      driveline::JointCoordinateTerm(sys, "pin", mbs::JointCoordinate::kRotation, 1.0, "clutch"),
      clutch));
  sys.AddForceElement(std::make_shared<mbs::AppliedLoad>(
      "shake", mbs::AppliedLoad::Kind::kForce, shaft, Eigen::Vector3d::UnitX(),
      mbs::AppliedLoad::Frame::kWorld, mbs::TimeFunction::Harmonic(20.0, 50.0, 0.0, 0.0)));
  sys.Finalize();
  return std::move(m.sys);
}

TEST(GglDaeAllocation, ResidualAndIterationMatrixAllocateNothing) {
  const mbs::System sys = Model();
  ASSERT_EQ(sys.num_force_states(), 1 + 16 * 3);  // the arm's deflection, the film's grid
  // The caller's workspace (Model/Data): the DAE fills it and nothing else.
  mbs::GglWorkspace data(sys);
  const mbs::GglDae dae(sys, &data);
  ASSERT_EQ(&dae.data(), &data);
  mbs::AnalysisSettings s;
  const mbs::PreparedRun run = mbs::PrepareRun(sys, s);
  mbs::ConstraintWorkspace& ws = dae.workspace();
  const mbs::AccelerationSolution acc = mbs::SolveAccelerations(sys, run.q0, run.v0, 0.0, &ws);
  Eigen::VectorXd y, yp;
  dae.MakeInitialValues(run.q0, run.v0, acc.vdot, acc.lambda, &y, &yp);
  const int n = dae.size();
  Eigen::VectorXd r(n);
  Eigen::MatrixXd J(n, n);
  SparseMatrixd Js;
  // Warm-up: one of each sizes the workspace and fixes the sparse structure.
  ASSERT_TRUE(dae.CalcResidual(0.0, y, yp, r));
  dae.CalcJacobian(0.0, 100.0, y, yp, J);
  dae.CalcSparseJacobian(0.0, 100.0, y, yp, &Js);
  constexpr int kStates = 20;
  Eigen::VectorXd y1 = y, yp1 = yp;
  long residual_allocations = 0, dense_allocations = 0, sparse_allocations = 0;
  for (int k = 0; k < kStates; ++k) {
    for (int i = 0; i < n; ++i) y1[i] = y[i] + 1e-6 * std::sin(1.0 + i + 7.0 * k);
    const double t = 1e-3 * k;
    {
      const CountAllocations count;
      ASSERT_TRUE(dae.CalcResidual(t, y1, yp1, r));
      residual_allocations += count.count();
    }
    {
      const CountAllocations count;
      dae.CalcJacobian(t, 100.0 + k, y1, yp1, J);
      dense_allocations += count.count();
    }
    {
      const CountAllocations count;
      dae.CalcSparseJacobian(t, 100.0 + k, y1, yp1, &Js);
      sparse_allocations += count.count();
    }
  }
  EXPECT_EQ(residual_allocations, 0) << "over " << kStates << " residuals";
  EXPECT_EQ(dense_allocations, 0) << "over " << kStates << " dense iteration matrices";
  EXPECT_EQ(sparse_allocations, 0) << "over " << kStates << " sparse iteration matrices";
}

// The GGL DAE behind a DaeProblem that counts the allocations made inside its residual and
// iteration-matrix evaluations only (not the integrator's or the linear solver's own work).
class CountingDae final : public DaeProblem {
 public:
  explicit CountingDae(const mbs::GglDae& dae) : dae_(dae) {}
  long allocations() const { return allocations_; }
  long evaluations() const { return evaluations_; }

 protected:
  int DoSize() const override { return dae_.size(); }
  bool DoCalcResidual(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                      const Eigen::Ref<const Eigen::VectorXd>& yp,
                      Eigen::Ref<Eigen::VectorXd> r) const override {
    return Counted([&] { return dae_.CalcResidual(t, y, yp, r); });
  }
  bool DoHasJacobian() const override { return true; }
  bool DoCalcJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                      const Eigen::Ref<const Eigen::VectorXd>& yp,
                      Eigen::Ref<Eigen::MatrixXd> J) const override {
    return Counted([&] { return dae_.CalcJacobian(t, cj, y, yp, J); });
  }
  bool DoHasSparseJacobian() const override { return true; }
  bool DoCalcSparseJacobian(double t, double cj, const Eigen::Ref<const Eigen::VectorXd>& y,
                            const Eigen::Ref<const Eigen::VectorXd>& yp,
                            SparseMatrixd* J) const override {
    // The first call builds the structure (allocates by design): not counted.
    if (J->nonZeros() == 0) return dae_.CalcSparseJacobian(t, cj, y, yp, J);
    return Counted([&] { return dae_.CalcSparseJacobian(t, cj, y, yp, J); });
  }
  Eigen::VectorXd DoDifferentialMask() const override { return dae_.DifferentialMask(); }
  std::vector<std::vector<int>> DoDenseBlocks() const override { return dae_.DenseBlocks(); }

 private:
  template <class Fn>
  bool Counted(Fn&& fn) const {
    const CountAllocations count;
    const bool ok = fn();
    // The first evaluation of each kind sizes the workspace: counted from the second on.
    if (++evaluations_ > 2) allocations_ += count.count();
    return ok;
  }
  const mbs::GglDae& dae_;
  mutable long allocations_{0}, evaluations_{0};
};

// Over IDA steps (dense and KLU iteration matrices): every residual and iteration matrix the
// integrator asks for, at the states it visits, allocates nothing.
TEST(GglDaeAllocation, NoAllocationInTheEvaluationsOfIdaSteps) {
  const mbs::System sys = Model();
  for (const LinearSolverKind solver : {LinearSolverKind::kDense, LinearSolverKind::kKlu}) {
    const mbs::GglDae dae(sys);
    mbs::AnalysisSettings s;
    const mbs::PreparedRun run = mbs::PrepareRun(sys, s);
    const mbs::AccelerationSolution acc =
        mbs::SolveAccelerations(sys, run.q0, run.v0, 0.0, &dae.workspace());
    Eigen::VectorXd y, yp;
    dae.MakeInitialValues(run.q0, run.v0, acc.vdot, acc.lambda, &y, &yp);
    const CountingDae counting(dae);
    IdaOptions o;
    o.rtol = 1e-6;
    o.atol = 1e-8;
    o.algebraic_atol = 1e-3;
    o.linear_solver = solver;
    IdaSolver ida(counting, 0.0, y, yp, o);
    const IntegratorReport rep = ida.AdvanceTo(0.02);
    ASSERT_TRUE(rep.ok()) << rep.message;
    ASSERT_GT(ida.stats().steps, 20) << "too few steps to say anything";
    EXPECT_EQ(counting.allocations(), 0)
        << Name(solver) << ": over " << ida.stats().steps << " steps and "
        << counting.evaluations() << " evaluations";
  }
}

}  // namespace
}  // namespace emb
