#pragma once
/// @file
/// The elastic part of a flexible body in the floating frame of reference (seed eqs.
/// 1.27–1.30): modal coordinates eta, the inertia invariants that couple them with the rigid
/// motion, the modal stiffness and damping and, optionally, geometric (stress) stiffening.
///
/// Frame: the body frame B of a flexible body has its origin at the *undeformed* centre of
/// mass and the axes of the mesh. A material point at xbar (from the CM, in B) is at
///   r = p_WB + R_WB (xbar + Phi(xbar) eta),
/// with Phi the elastic mode shapes (mass-orthonormal, free of rigid motion). The invariants
/// (Shabana's form, cms/inertia_invariants.h, shifted to the CM) are
///   St = ∫ρ Phi (3 x ne),  Ibar_kl = ∫ρ xbar_k Phi_l (1 x ne),  Sbar_kl = ∫ρ Phi_k^T Phi_l
/// (ne x ne) and Jbar = ∫ρ xbar xbar^T. With u = xbar + Phi eta the deformed position,
///   c(eta) = ∫ρ u = St eta,   B_k(eta) = ∫ρ u Phi_k^T (3 x 3, k = mode),
///   A(eta) = ∫ρ u u^T,        J(eta) = tr(A) I - A,
/// the velocities v = [v_WB (W), omega_B (B), eta'] and M(eta) v' = f give
///   M = [ m I        -R [c x]     R St
///         [c x] R^T   J            [∫ρ u x Phi_k]_k
///         St^T R^T    (sym.)       Mee = sum_i Sbar_ii ]
///   f_t = m g - R (w x (w x c) + 2 w x St eta')
///   f_r = c x R^T g - w x J w - 2 sum_l eta'_l (tr(B_l) w - B_l^T w)
///   f_e = St^T R^T g - [w^T B_k w - |w|^2 tr B_k]_k - 2 G(w)^T eta' - K eta - D eta'
///         - K_G(w, a) eta
/// with w = omega_B and G(w) = w_x (S_yz - S_zy) + w_y (S_zx - S_xz) + w_z (S_xy - S_yx).
/// Nothing is dropped: with mean-axis modes c and the rigid-elastic coupling vanish at
/// eta = 0, but the terms are evaluated for every eta.
///
/// Geometric stiffening (optional, from the reduction): K_G(w, a) = sum_p c_p(w) K_p +
/// sum_k a_k K_{a,k} with c = (wx^2, wy^2, wz^2, wx wy, wy wz, wz wx) and a = R^T(v'_WB - g),
/// the acceleration of the frame origin less gravity in B. The centrifugal part derives
/// from a kinetic energy (the second-order foreshortening of a bent body brings its mass
/// closer to the spin axis), T_G = -1/2 eta^T K_G(w, 0) eta = -1/2 w^T Q(eta) w with
/// Q = [s0 s3/2 s5/2; s3/2 s1 s4/2; s5/2 s4/2 s2], s_p = eta^T K_p eta, so its Lagrange
/// equations also act on the rotation: J above is J - Q(eta) (mass and f_r), and f_r gains
/// Q'(eta, eta') w with Q' from s'_p = 2 eta'^T K_p eta. Without them the force on eta did
/// work through a frame rate that follows eta' (a frame held at an elastic interface): a
/// bent, spinning cantilever's torsion mode grew from round-off (issue 12). The kinetic
/// energy includes T_G; the total energy of an undamped, undriven model is conserved.

#include <Eigen/Dense>
#include <array>
#include <string>
#include <vector>

namespace emb::mbs {

struct ElasticModel {
  std::string source;                  ///< e.g. the body file, for messages
  double mass{0.0};                    ///< [kg]
  Eigen::Matrix3d second_moment;       ///< Jbar about the CM [kg m^2]
  Eigen::MatrixXd St;                  ///< 3 x ne
  Eigen::MatrixXd Ibar;                ///< 9 x ne, row 3k+l = Ibar_kl, about the CM
  std::array<Eigen::MatrixXd, 9> Sbar; ///< [3k+l] = Sbar_kl (ne x ne)
  Eigen::MatrixXd K, D;                ///< modal stiffness and damping (ne x ne)
  Eigen::VectorXd frequencies_hz;      ///< of the kept modes (for reports)
  /// Per mode: true if the mode is quasi-static (MakeQuasiStatic). Empty: all dynamic.
  std::vector<bool> quasi_static;
  /// Geometric stiffening (present only if the body file has it and it is switched on).
  bool geometric_stiffening{false};
  std::array<Eigen::MatrixXd, 6> kg_centrifugal;   ///< per product c_p(w)
  std::array<Eigen::MatrixXd, 3> kg_translational; ///< per a_k

  int num_modes() const { return static_cast<int>(K.rows()); }
  /// Inertia tensor about the CM of the undeformed body: tr(Jbar) I - Jbar.
  Eigen::Matrix3d RigidInertia() const;
  /// @throws InputError naming `name` if sizes disagree, K is not symmetric positive
  /// semi-definite or the modal mass is not positive definite.
  void Validate(const std::string& name) const;
  /// The model restricted to modes `keep` (indices into the current modes).
  ElasticModel Subset(const std::vector<int>& keep) const;
  /// The model in new elastic coordinates xi with eta = T xi (T: ne x n', full column
  /// rank, columns in the span of the current modes): every invariant is the same integral
  /// with Phi T for Phi,
  ///   St' = St T,  Ibar' = Ibar T,  Sbar'_kl = T^T Sbar_kl T,  K' = T^T K T,  D' = T^T D T,
  ///   K_G' = T^T K_G T,
  /// so that kinetic, strain and dissipated energies of eta = T xi are those of xi. The
  /// quasi-static flags are dropped (flag the new coordinates with MakeQuasiStatic) and
  /// frequencies_hz becomes sqrt(K'_jj / M'_jj) / 2 pi (M' = sum_i Sbar'_ii), exact for
  /// columns that are M- and K-orthogonal. Cost O(ne^2 n').
  ElasticModel Transformed(const Eigen::MatrixXd& T) const;
  /// Makes the flagged modes quasi-static (residual flexibility, "mode acceleration"): they
  /// keep their stiffness, damping and every load on them (interface forces, the inertial
  /// loads of the frame's motion through Ibar, gravity), so the static response of the full
  /// basis at the interfaces is kept exactly, but they lose their own inertia: the rows and
  /// columns of the flagged modes in every Sbar_kl are zeroed, which removes their modal
  /// mass, their Coriolis and spin-softening terms and their share of J(eta). Their rate
  /// then follows from D eta' = (loads) - K eta at every instant (an algebraic unknown of
  /// the DAE; the relaxation time 2 zeta / omega is far below any step), so they carry no
  /// vibration of their own for the integrator to resolve. Needs a positive modal damping
  /// on each flagged mode. @throws InputError naming `name` otherwise or for a size mismatch.
  void MakeQuasiStatic(const std::vector<bool>& flags, const std::string& name);
  int num_quasi_static() const;
  /// Number of leading coordinates before a trailing run of quasi-static ones (ne if there
  /// is none, or if quasi-static coordinates are not all at the end): the inertia terms
  /// (Sbar) live in the leading block only.
  int num_leading_dynamic() const;
  /// Adds tau K_ss to the damping of the flagged coordinates (the block of K among them),
  /// so that they relax to their static response with the time constant tau [s]. A
  /// quasi-static coordinate has no inertia of its own; what it carries (a rigid body on the
  /// static flexibility at an interface) would otherwise vibrate above the band with the
  /// little damping of the high modes the static shape is made of. Keeps D positive
  /// semi-definite (adds a positive semi-definite block).
  void AddRelaxationDamping(const std::vector<bool>& flags, double tau);
  bool is_quasi_static(int j) const { return !quasi_static.empty() && quasi_static[j]; }
};

/// Inertia terms of one flexible body at one state: the mass matrix and every velocity-,
/// gravity- and deformation-dependent generalised force of the file comment, in the
/// body's velocity coordinates [v_WB, omega_B, eta'] (6 + ne).
struct FlexibleTerms {
  Eigen::MatrixXd mass;   ///< M(eta)
  Eigen::VectorXd force;  ///< f (gravity, quadratic velocity, elastic, damping, K_G)
  /// Derivatives for the iteration matrix: d f / d[v_WB, omega_B, eta'] and
  /// d f / d[delta p, delta pi, eta] (the terms that matter for Newton: velocity products,
  /// the elastic, centrifugal and geometric stiffness, gravity through R; the derivatives
  /// of M(eta) v' are left out).
  Eigen::MatrixXd damping, stiffness;
  /// With a body acceleration a = [v'_WB, omega'_B, eta''] given (else empty):
  /// inertia_stiffness = d(M(eta) a)/d[delta p, delta pi, eta] at fixed a, and
  /// force_accel = d f / d a (the frame acceleration in the translational geometric
  /// stiffness), so that the residual M a - f has d/dx = inertia_stiffness - stiffness and
  /// d/da = mass - force_accel.
  Eigen::MatrixXd inertia_stiffness, force_accel;
  double kinetic_energy{0.0};
  double elastic_energy{0.0};  ///< eta^T K eta / 2
  double gravity_energy{0.0};  ///< -m g.p_WB - g.R c(eta)
  double dissipated_power{0.0};

  /// Scratch of the in-place evaluation (flexible_terms.cpp), kept between calls.
  struct Scratch {
    Eigen::MatrixXd Bm, Mre, Mee, G, KG, W, Kc, P, Kcd, Kae, WaT, dMre;
    Eigen::VectorXd trB, fe, Kg_eta, tmp;
  } scratch;
};

/// What CalcFlexibleTerms evaluates (bit flags).
enum FlexibleTermsParts : unsigned {
  kFlexibleMass = 1u,         ///< mass
  kFlexibleForce = 2u,        ///< force
  kFlexibleEnergies = 4u,     ///< kinetic, elastic, gravity energy, dissipated power
  kFlexibleDerivatives = 8u,  ///< damping, stiffness (and with accel: inertia_stiffness,
                              ///< force_accel); implies mass and force
  kFlexibleAll = 15u,
};

/// Evaluates the `parts` of FlexibleTerms into `out`, reusing its storage (no allocation
/// once sized). `a_B` is the frame origin's acceleration less gravity in B for the
/// translational geometric stiffness (zero if unknown). `accel` (derivatives only; may be
/// null) is the body acceleration [v'_WB, omega'_B, eta''] for inertia_stiffness and
/// force_accel. Cost O(ne^2) (the Sbar terms only over the leading dynamic coordinates when
/// the quasi-static ones are the trailing ones: they have no inertia).
void CalcFlexibleTerms(const ElasticModel& model, const Eigen::Vector3d& p_WB,
                       const Eigen::Matrix3d& R_WB, const Eigen::Vector3d& v_WB,
                       const Eigen::Vector3d& omega_B, const Eigen::Ref<const Eigen::VectorXd>& eta,
                       const Eigen::Ref<const Eigen::VectorXd>& eta_dot,
                       const Eigen::Vector3d& g_W, const Eigen::Vector3d& a_B, unsigned parts,
                       const Eigen::Ref<const Eigen::VectorXd>* accel, FlexibleTerms* out);

/// Evaluates FlexibleTerms (all parts; the derivatives if `with_derivatives`).
FlexibleTerms CalcFlexibleTerms(const ElasticModel& model, const Eigen::Vector3d& p_WB,
                                const Eigen::Matrix3d& R_WB, const Eigen::Vector3d& v_WB,
                                const Eigen::Vector3d& omega_B, const Eigen::VectorXd& eta,
                                const Eigen::VectorXd& eta_dot, const Eigen::Vector3d& g_W,
                                const Eigen::Vector3d& a_B, bool with_derivatives,
                                const Eigen::VectorXd* accel = nullptr);

}  // namespace emb::mbs
