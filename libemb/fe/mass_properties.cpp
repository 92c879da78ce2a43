#include "libemb/fe/mass_properties.h"

#include "libemb/common/error.h"
#include "libemb/fe/cell_dispatch.h"
#include "libemb/fe/solid_element.h"

namespace emb {

MassProperties CalcMassProperties(const Mesh& mesh, double density) {
  EMB_THROW_IF(!(density > 0.0), "density: expected > 0 kg/m^3, got " << density);
  EMB_THROW_IF(mesh.num_cells() == 0, "mesh '" << mesh.source << "' has no volume elements");
  double volume = 0.0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (const auto& b : mesh.blocks) {
    DispatchSolid(b.type, [&](auto type) {
      using Element = SolidElement<decltype(type)::value>;
      typename Element::NodeCoords X;
      for (int c = 0; c < b.num_cells(); ++c) {
        for (int a = 0; a < Element::kNodes; ++a) X.col(a) = mesh.nodes.col(b.cell(c)[a]);
        const double min_det = Element::AddGeometricMoments(X, volume, first, second);
        const double size = (X.rowwise().maxCoeff() - X.rowwise().minCoeff()).norm();
        CheckCellJacobian(mesh.source, b.type, b.tags[c], min_det, size);
      }
    });
  }
  MassProperties p;
  p.volume = volume;
  p.mass = density * volume;
  p.center_of_mass = first / volume;
  // Second moment about the centre: ∫ r rᵀ = ∫ x xᵀ − V c cᵀ.
  const Eigen::Matrix3d S = density * (second - volume * p.center_of_mass * p.center_of_mass.transpose());
  p.inertia_about_com = InertiaFromSecondMoment(S);
  return p;
}

}  // namespace emb
