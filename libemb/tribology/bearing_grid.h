#pragma once
/// @file
/// The finite-volume grid of the unwrapped bearing surface (notation.h).
///
/// Nodes (i, j): phi_i = i dphi, i = 0..N-1 (periodic, dphi = 2 pi / N) and
/// z_j = -L/2 + j dz, j = 0..Nz (dz = L / Nz). The edge rows j = 0 and j = Nz are at ambient
/// pressure; the unknowns are the m = Nz - 1 interior nodes of each column, numbered
/// k = i m + (j - 1) (axial fastest, so the Jacobian is block-cyclic-tridiagonal with m x m
/// blocks: cyclic_block_lu.h). Node (i, j) owns the control volume
/// [phi_i - dphi/2, phi_i + dphi/2] x [z_j - dz/2, z_j + dz/2] of area A = R dphi dz (half
/// of it on the edge rows): the mass balance. Fields over all nodes (the additive film dh)
/// are numbered i (Nz + 1) + j.
///
/// Integrals over the surface (loads, friction) use the periodic trapezoid rule around and
/// Simpson's rule along the axis, R dphi w_j with w_j = dz/3 (1, 4, 2, ..., 4, 1) for even Nz
/// (the 3/8 rule on the last three intervals for odd Nz >= 3; the trapezoid for Nz = 2... is
/// Simpson too). The axial pressure profile is nearly parabolic (p = 0 at the edges): the
/// trapezoid sum of exact nodal values would miss the load by ~1/Nz^2 (1.6 % at Nz = 8),
/// Simpson integrates the parabola exactly.

#include <cmath>
#include <numbers>
#include <vector>

namespace emb::tribology {

/// Grid resolution: nodes around the circumference and intervals along the axis.
struct GridSize {
  int circumferential{48};  ///< N >= 8
  int axial{8};             ///< Nz >= 2 (Nz - 1 interior rows)
};

class BearingGrid {
 public:
  /// @pre radius > 0, length > 0, N >= 8, Nz >= 2 (checked by ReynoldsBearing).
  BearingGrid(double radius, double length, GridSize size)
      : radius_(radius), length_(length), n_(size.circumferential), nz_(size.axial),
        dphi_(2.0 * std::numbers::pi / n_), dz_(length / nz_) {
    cos_node_.resize(n_);
    sin_node_.resize(n_);
    cos_face_.resize(n_);
    sin_face_.resize(n_);
    weight_.assign(nz_ + 1, 0.0);
    const int simpson = nz_ % 2 == 0 ? nz_ : nz_ - 3;  // intervals under Simpson's 1/3 rule
    for (int j = 0; j < simpson; j += 2) {
      weight_[j] += dz_ / 3.0;
      weight_[j + 1] += 4.0 * dz_ / 3.0;
      weight_[j + 2] += dz_ / 3.0;
    }
    if (simpson < nz_) {  // 3/8 rule on the last three intervals
      const int j = simpson;
      weight_[j] += 3.0 * dz_ / 8.0;
      weight_[j + 1] += 9.0 * dz_ / 8.0;
      weight_[j + 2] += 9.0 * dz_ / 8.0;
      weight_[j + 3] += 3.0 * dz_ / 8.0;
    }
    for (int i = 0; i < n_; ++i) {
      cos_node_[i] = std::cos(angle(i));
      sin_node_[i] = std::sin(angle(i));
      cos_face_[i] = std::cos(angle(i) + 0.5 * dphi_);
      sin_face_[i] = std::sin(angle(i) + 0.5 * dphi_);
    }
  }

  double radius() const { return radius_; }
  double length() const { return length_; }
  int num_circumferential() const { return n_; }  ///< N
  int num_axial_intervals() const { return nz_; }  ///< Nz
  int num_rows() const { return nz_ - 1; }         ///< m, interior nodes per column
  int num_unknowns() const { return n_ * (nz_ - 1); }
  int num_nodes() const { return n_ * (nz_ + 1); }  ///< all nodes, edges included
  double dphi() const { return dphi_; }
  double dz() const { return dz_; }
  double node_area() const { return radius_ * dphi_ * dz_; }  ///< A [m^2]
  /// Quadrature area of node row j = 0..Nz for surface integrals: R dphi w_j [m^2].
  double quadrature_area(int j) const { return radius_ * dphi_ * weight_[j]; }

  double angle(int i) const { return i * dphi_; }                 ///< phi_i [rad]
  double axial(int j) const { return -0.5 * length_ + j * dz_; }  ///< z_j [m], j = 0..Nz
  int Unknown(int i, int j) const { return i * (nz_ - 1) + (j - 1); }  ///< j = 1..Nz-1
  int Node(int i, int j) const { return i * (nz_ + 1) + j; }          ///< j = 0..Nz
  int column_of(int k) const { return k / (nz_ - 1); }
  int row_of(int k) const { return k % (nz_ - 1) + 1; }
  int next(int i) const { return i + 1 == n_ ? 0 : i + 1; }
  int previous(int i) const { return i == 0 ? n_ - 1 : i - 1; }

  double cos_node(int i) const { return cos_node_[i]; }
  double sin_node(int i) const { return sin_node_[i]; }
  /// cos, sin of the face phi_{i+1/2} between columns i and i+1.
  double cos_face(int i) const { return cos_face_[i]; }
  double sin_face(int i) const { return sin_face_[i]; }

 private:
  double radius_, length_;
  int n_, nz_;
  double dphi_, dz_;
  std::vector<double> cos_node_, sin_node_, cos_face_, sin_face_, weight_;
};

}  // namespace emb::tribology
