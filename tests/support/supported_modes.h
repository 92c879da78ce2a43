#pragma once
/// @file
/// Modes of a meshed part under supports, checked as every test wants them checked: a
/// successful eigen-solve and a constraint residual at round-off.

#include <gtest/gtest.h>

#include "libemb/cms/supports.h"
#include "libemb/fe/assembly.h"
#include "libemb/fe/modal_analysis.h"

namespace emb::test {

/// The lowest `num_modes` modes of `mesh` in `material` held by `specs`; the resolved supports
/// in `*resolved` if given.
inline ModalResult SupportedModes(const Mesh& mesh, const SupportSpecs& specs,
                                  const IsotropicMaterial& material, int num_modes,
                                  Supports* resolved = nullptr) {
  const Supports supports = BuildSupports(mesh, specs);
  ModalOptions mo;
  mo.num_modes = num_modes;
  const ModalResult r = ComputeModes(AssembleSystem(mesh, material), supports.Apply(mo));
  EXPECT_TRUE(r.eig.ok()) << r.eig.message;
  EXPECT_LT(ConstraintResidual(supports, r), kConstraintResidualLimit);
  if (resolved) *resolved = supports;
  return r;
}

}  // namespace emb::test
