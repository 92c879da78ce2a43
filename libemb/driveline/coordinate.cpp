#include "libemb/driveline/coordinate.h"

#include <array>
#include <cmath>

#include "libemb/common/error.h"
#include "libemb/mbs/constraints/constraint_eval.h"
#include "libemb/mbs/constraints/primitive.h"
#include "libemb/mbs/core/rotation.h"
#include "libemb/mbs/core/system.h"
#include "libemb/mbs/forces/force_jacobian.h"

namespace emb::driveline {
namespace {

// The acceleration of the virtual body of marker M (the kernel rows apply to it) from the
// bodies' accelerations v': [v'_WB, omega'_B] on a rigid body, map [v'_b; eta''_b] on a
// flexible marker (its velocity-product term `extra` is added with the kernel's quadratic).
Eigen::Matrix<double, 6, 1> VirtualBodyAcceleration(const mbs::StateLayout& L,
                                                    const mbs::MarkerKinematics& M,
                                                    const Eigen::VectorXd& vdot) {
  if (L.is_ground(M.body)) return Eigen::Matrix<double, 6, 1>::Zero();
  if (!M.flexible()) return vdot.segment<6>(L.velocity(M.body));
  const int ne = L.num_elastic(M.body);
  return M.map.leftCols<6>() * vdot.segment<6>(L.velocity(M.body)) +
         M.map.rightCols(ne) * vdot.segment(L.elastic_v(M.body), ne);
}

}  // namespace

CoordinateTerm JointCoordinateTerm(const mbs::System& system, const std::string& joint,
                                   mbs::JointCoordinate c, double coeff,
                                   const std::string& element) {
  try {
    const int e = system.FindElement(joint);
    const mbs::ConstraintElement& je = system.elements()[static_cast<std::size_t>(e)];
    EMB_THROW_IF(je.kind != mbs::ElementKind::kJoint, "'" << joint << "' is not a joint");
    CoordinateTerm t;
    t.marker_i = je.marker_i;
    t.marker_j = je.marker_j;
    t.kernel = mbs::CoordinateKernel(je.type, c, joint);
    t.coeff = coeff;
    return t;
  } catch (const InputError& e) {
    EMB_THROW(InputError, element << ": " << e.what());
  }
}

int NumAngleTerms(const std::vector<CoordinateTerm>& terms) {
  int n = 0;
  for (const CoordinateTerm& t : terms) n += t.angle() ? 1 : 0;
  return n;
}

CoordinateValue EvalCoordinate(const mbs::ForceContext& ctx,
                               const std::vector<CoordinateTerm>& terms, int first_slot) {
  const int K = static_cast<int>(terms.size());
  EMB_CHECK(2 * K <= mbs::kMaxForceSlots);
  CoordinateValue out;
  out.gradient.setZero(12 * K);
  out.velocity.setZero(12 * K);
  out.num_markers = 2 * K;
  if (ctx.markers == nullptr) out.own.resize(2 * static_cast<std::size_t>(K));  // stays put
  for (int k = 0; k < K; ++k)
    for (int side = 0; side < 2; ++side) {
      const std::size_t s = 2 * static_cast<std::size_t>(k) + side;
      const CoordinateTerm& t = terms[static_cast<std::size_t>(k)];
      const int m = side == 0 ? t.marker_i : t.marker_j;
      out.markers[s] = &ctx.Marker(m, ctx.markers != nullptr ? nullptr : &out.own[s]);
    }
  int slot = first_slot;
  double quadratic = 0.0;
  for (int k = 0; k < K; ++k) {
    const CoordinateTerm& t = terms[static_cast<std::size_t>(k)];
    const mbs::MarkerKinematics& I = out.marker(2 * k);
    const mbs::MarkerKinematics& J = out.marker(2 * k + 1);
    const mbs::KernelEval g = mbs::EvalKernel(t.kernel, I, J);
    double value = g.value;
    if (t.angle()) {
      if (ctx.workspace != nullptr && slot >= 0)
        value = ctx.workspace->Unwrap(slot, g.value, g.value);
      ++slot;
    }
    out.value += t.coeff * value;
    out.gradient.segment<6>(12 * k) = t.coeff * g.d_i;
    out.gradient.segment<6>(12 * k + 6) = t.coeff * g.d_j;
    out.velocity.segment<6>(12 * k) = mbs::VirtualBodyVelocity(I);
    out.velocity.segment<6>(12 * k + 6) = mbs::VirtualBodyVelocity(J);
    const double q = t.coeff * (g.quadratic + g.d_i.dot(I.extra) + g.d_j.dot(J.extra));
    quadratic += q;
    out.accel_scale += std::abs(q);
  }
  out.rate = out.gradient.dot(out.velocity);
  for (int s = 0; s < 2 * K; ++s)
    out.rate_scale += out.gradient.segment<6>(6 * s).norm() * out.velocity.segment<6>(6 * s).norm();
  if (ctx.vdot != nullptr) {
    const mbs::StateLayout& L = ctx.system->layout();
    double a = quadratic;
    for (int s = 0; s < 2 * K; ++s) {
      const Eigen::Matrix<double, 6, 1> acc = VirtualBodyAcceleration(L, out.marker(s), *ctx.vdot);
      a += out.gradient.segment<6>(6 * s).dot(acc);
      out.accel_scale += out.gradient.segment<6>(6 * s).norm() * acc.norm();
    }
    out.accel = a;
  }
  return out;
}

mbs::SlotMatrix CoordinateHessian(const std::vector<CoordinateTerm>& terms,
                                  const CoordinateValue& value) {
  const int K = static_cast<int>(terms.size());
  EMB_CHECK(2 * K <= mbs::kMaxForceSlots);
  mbs::SlotMatrix H = mbs::SlotMatrix::Zero(12 * K, 12 * K);
  for (int k = 0; k < K; ++k)
    H.block<12, 12>(12 * k, 12 * k) =
        terms[static_cast<std::size_t>(k)].coeff *
        mbs::EvalKernelHessian(terms[static_cast<std::size_t>(k)].kernel, value.marker(2 * k),
                               value.marker(2 * k + 1));
  return H;
}

void AddCoordinateForce(const mbs::ForceContext& ctx, const CoordinateValue& value, double force,
                        Eigen::Ref<Eigen::VectorXd> f) {
  const mbs::StateLayout& L = ctx.system->layout();
  for (int s = 0; s < value.num_markers; ++s)
    mbs::AddMarkerForce(L, value.marker(s), -force * value.gradient.segment<6>(6 * s).transpose(), f);
}

void AddCoordinateForceJacobian(const std::vector<CoordinateTerm>& terms,
                                const CoordinateValue& value, double force, double dforce_dx,
                                double dforce_dv, mbs::ForceJacobianSink* sink) {
  mbs::LocalForceJacobian jac(value.markers.data(), value.num_markers);
  const mbs::SlotMatrix H = CoordinateHessian(terms, value);
  const mbs::SlotRows<1> vH = value.velocity * H;
  const mbs::SlotRows<1> g = value.gradient;
  jac.stiffness = -g.transpose() * (dforce_dx * g + dforce_dv * vH) - force * H;
  jac.damping = -dforce_dv * g.transpose() * g;
  for (int s = 0; s < jac.num_slots(); ++s)
    jac.SetSlotForce(s, -force * value.gradient.segment<6>(6 * s).transpose());
  jac.ScatterTo(sink);
}

}  // namespace emb::driveline
