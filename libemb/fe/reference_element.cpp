#include "libemb/fe/reference_element.h"

namespace emb {

// Node coordinates: gmsh's reference elements (verified against gmsh in the tests).
// Quadrature: exact for straight-sided (affine) cells —
//   simplices: total degree 2(p−1) for stiffness, 2p for mass (p = order);
//   Hex8/Hex20: 2/3 Gauss points per direction (per-variable degree 3/5 ≥ 2/4 needed);
//   wedges: triangle degree 2/4 × 2/3 Gauss points in ζ.

const std::array<std::array<double, 3>, 3> ElementTraits<CellType::kTri3>::kNodeCoords{
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
const std::array<std::array<int, 3>, 3> ElementTraits<CellType::kTri3>::kMonomials{
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
QuadratureRule ElementTraits<CellType::kTri3>::StiffnessRule() { return TriRule(0); }
QuadratureRule ElementTraits<CellType::kTri3>::MassRule() { return TriRule(2); }

const std::array<std::array<double, 3>, 6> ElementTraits<CellType::kTri6>::kNodeCoords{
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0, 0}, {0.5, 0.5, 0}, {0, 0.5, 0}}};
const std::array<std::array<int, 3>, 6> ElementTraits<CellType::kTri6>::kMonomials{
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {1, 1, 0}, {0, 2, 0}}};
QuadratureRule ElementTraits<CellType::kTri6>::StiffnessRule() { return TriRule(2); }
QuadratureRule ElementTraits<CellType::kTri6>::MassRule() { return TriRule(4); }

const std::array<std::array<double, 3>, 4> ElementTraits<CellType::kQuad4>::kNodeCoords{
    {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}};
const std::array<std::array<int, 3>, 4> ElementTraits<CellType::kQuad4>::kMonomials{
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}};
QuadratureRule ElementTraits<CellType::kQuad4>::StiffnessRule() { return QuadRule(2); }
QuadratureRule ElementTraits<CellType::kQuad4>::MassRule() { return QuadRule(2); }

const std::array<std::array<double, 3>, 8> ElementTraits<CellType::kQuad8>::kNodeCoords{
    {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}}};
const std::array<std::array<int, 3>, 8> ElementTraits<CellType::kQuad8>::kMonomials{
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {1, 1, 0}, {0, 2, 0}, {2, 1, 0}, {1, 2, 0}}};
QuadratureRule ElementTraits<CellType::kQuad8>::StiffnessRule() { return QuadRule(3); }
QuadratureRule ElementTraits<CellType::kQuad8>::MassRule() { return QuadRule(3); }

const std::array<std::array<double, 3>, 4> ElementTraits<CellType::kTet4>::kNodeCoords{
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
const std::array<std::array<int, 3>, 4> ElementTraits<CellType::kTet4>::kMonomials{
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
QuadratureRule ElementTraits<CellType::kTet4>::StiffnessRule() { return TetRule(0); }
QuadratureRule ElementTraits<CellType::kTet4>::MassRule() { return TetRule(2); }

const std::array<std::array<double, 3>, 10> ElementTraits<CellType::kTet10>::kNodeCoords{
    {{0, 0, 0},
     {1, 0, 0},
     {0, 1, 0},
     {0, 0, 1},
     {0.5, 0, 0},
     {0.5, 0.5, 0},
     {0, 0.5, 0},
     {0, 0, 0.5},
     {0, 0.5, 0.5},
     {0.5, 0, 0.5}}};
const std::array<std::array<int, 3>, 10> ElementTraits<CellType::kTet10>::kMonomials{
    {{0, 0, 0},
     {1, 0, 0},
     {0, 1, 0},
     {0, 0, 1},
     {2, 0, 0},
     {0, 2, 0},
     {0, 0, 2},
     {1, 1, 0},
     {0, 1, 1},
     {1, 0, 1}}};
QuadratureRule ElementTraits<CellType::kTet10>::StiffnessRule() { return TetRule(2); }
QuadratureRule ElementTraits<CellType::kTet10>::MassRule() { return TetRule(4); }

const std::array<std::array<double, 3>, 8> ElementTraits<CellType::kHex8>::kNodeCoords{
    {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
     {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}};
const std::array<std::array<int, 3>, 8> ElementTraits<CellType::kHex8>::kMonomials{
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}, {1, 1, 1}}};
QuadratureRule ElementTraits<CellType::kHex8>::StiffnessRule() { return HexRule(2); }
QuadratureRule ElementTraits<CellType::kHex8>::MassRule() { return HexRule(2); }

const std::array<std::array<double, 3>, 20> ElementTraits<CellType::kHex20>::kNodeCoords{
    {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1},
     {-1, 1, 1},   {0, -1, -1}, {-1, 0, -1}, {-1, -1, 0}, {1, 0, -1}, {1, -1, 0}, {0, 1, -1},
     {1, 1, 0},    {-1, 1, 0},  {0, -1, 1}, {-1, 0, 1},  {1, 0, 1},  {0, 1, 1}}};
const std::array<std::array<int, 3>, 20> ElementTraits<CellType::kHex20>::kMonomials{
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2},
     {1, 1, 0}, {0, 1, 1}, {1, 0, 1}, {2, 1, 0}, {2, 0, 1}, {1, 2, 0}, {0, 2, 1},
     {1, 0, 2}, {0, 1, 2}, {1, 1, 1}, {2, 1, 1}, {1, 2, 1}, {1, 1, 2}}};
QuadratureRule ElementTraits<CellType::kHex20>::StiffnessRule() { return HexRule(3); }
QuadratureRule ElementTraits<CellType::kHex20>::MassRule() { return HexRule(3); }

const std::array<std::array<double, 3>, 6> ElementTraits<CellType::kWedge6>::kNodeCoords{
    {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}}};
const std::array<std::array<int, 3>, 6> ElementTraits<CellType::kWedge6>::kMonomials{
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}}};
QuadratureRule ElementTraits<CellType::kWedge6>::StiffnessRule() { return WedgeRule(2, 2); }
QuadratureRule ElementTraits<CellType::kWedge6>::MassRule() { return WedgeRule(2, 2); }

const std::array<std::array<double, 3>, 15> ElementTraits<CellType::kWedge15>::kNodeCoords{
    {{0, 0, -1},
     {1, 0, -1},
     {0, 1, -1},
     {0, 0, 1},
     {1, 0, 1},
     {0, 1, 1},
     {0.5, 0, -1},
     {0, 0.5, -1},
     {0, 0, 0},
     {0.5, 0.5, -1},
     {1, 0, 0},
     {0, 1, 0},
     {0.5, 0, 1},
     {0, 0.5, 1},
     {0.5, 0.5, 1}}};
const std::array<std::array<int, 3>, 15> ElementTraits<CellType::kWedge15>::kMonomials{
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {1, 1, 0}, {0, 2, 0}, {0, 0, 1}, {1, 0, 1},
     {0, 1, 1}, {2, 0, 1}, {1, 1, 1}, {0, 2, 1}, {0, 0, 2}, {1, 0, 2}, {0, 1, 2}}};
QuadratureRule ElementTraits<CellType::kWedge15>::StiffnessRule() { return WedgeRule(4, 3); }
QuadratureRule ElementTraits<CellType::kWedge15>::MassRule() { return WedgeRule(4, 3); }

}  // namespace emb
