#pragma once
/// @file
/// Notation and equations of the tribology module: the finite-width Reynolds journal bearing.
///
/// Frames and coordinates. S is the shell (bearing) frame: x_S, y_S span the bearing plane,
/// z_S is the bearing axis. The bearing surface is unwrapped into
///   phi   the circumferential angle from x_S towards y_S [rad], n(phi) = (cos phi, sin phi),
///         t(phi) = z_S x n = (-sin phi, cos phi);
///   z     the axial coordinate from the bearing mid-plane, z in [-L/2, L/2] [m].
/// Journal position (shell axes): e = (e_x, e_y), the journal centre at the mid-plane [m];
/// tilt gamma = (gamma_x, gamma_y) = de/dz [rad], so the journal axis runs along
/// (gamma_x, gamma_y, 1): a rotation of the journal by gamma_x about y_S and by -gamma_y
/// about x_S. Rates e_dot, gamma_dot are time derivatives seen in S. omega_j and omega_s
/// are the angular speeds about z_S of the journal and shell surfaces relative to S (a shell
/// fixed in S has omega_s = 0; a frame that does not turn with the shell gives both speeds).
///
/// Film thickness (rigid surfaces plus an optional additive field dh, e.g. elastic shells):
///   h(phi, z) = c - (e + z (gamma - gamma_b)) . n(phi) + dh(phi, z),                    (T1)
/// c the radial clearance, gamma_b a static bore tilt. Reynolds equation for an isothermal,
/// incompressible lubricant with Jakobsson-Floberg-Olsson (JFO) cavitation: the seed's
/// (1.2) with rho = theta rho_0 (theta the fill fraction, 1 in the full film), x = R phi,
/// the mean surface speed U = R (omega_j + omega_s) / 2 and no axial surface speed:
///   (1/R^2) d/dphi(h^3/(12 mu) dp/dphi) + d/dz(h^3/(12 mu) dp/dz)
///       = (U/R) d(theta h)/dphi + d(theta h)/dt,                                         (T2)
///   p >= 0,  1 - theta >= 0,  p (1 - theta) = 0                                          (T3)
/// (pressures gauge, the cavitation pressure equal to ambient). Edges z = +-L/2 are at
/// ambient pressure; oil holes and grooves hold their supply pressure (supply_features.h).
/// With a pressure-dependent viscosity mu(p) the reduced pressure
///   Psi(p) = int_0^p mu_0 / mu(s) ds                                                      (T4)
/// turns the Poiseuille terms of (T2) into h^3/(12 mu_0) grad Psi: the discrete equations
/// stay piecewise linear in (Psi, theta), and p = P(Psi) only enters the loads.
///
/// Discretisation (bearing_grid.h, film_assembly.h): finite volumes on an N x Nz grid,
/// periodic in phi; film thickness evaluated exactly at faces (T1); Poiseuille fluxes by
/// central differences (second order); Couette flux U h_face theta_upwind (Elrod's type
/// differencing: theta upwinded, exact h; second order in the full film where theta = 1).
/// Per node one unknown u (Elrod-Adams universal variable, scaled):
///   Psi = p_ref max(u, 0),   theta = 1 + min(u, 0),                                     (T5)
/// so (T3) holds by construction; the cavitation models (reynolds_bearing.h) differ in how
/// theta enters. The residual of node k is its volume balance [m^3/s]
///   r_k = A_k d(theta_k h_k)/dt + (net Couette + Poiseuille outflow of k),                (T6)
/// A_k = R dphi dz; the time derivative is theta_k dh_k/dt (quasi-static), backward Euler
/// on the content theta h (film_solver.h) or A_k (h theta'(u) u_dot + theta h_dot)
/// (film_dae.h: the film's DAE states).
///
/// Loads on the journal (shell axes; pressure p_k at the nodes, A_k the node areas):
///   F = -sum_k A_k p_k n_k                                               force [N]
///   M = sum_k A_k p_k z_k (sin phi_k, -cos phi_k)                        moment about x_S,
///                                                    y_S at the mid-plane centre [N m]
///   T_j = T_p + T_c,  T_s = T_p - T_c                                    torques about z_S
///   T_p = 1/2 sum_k A_k p_k dh/dphi_k     (the pressure-gradient shear, by parts)
///   T_c = R sum_k A_k theta_k mu(p_k) (omega_s - omega_j) R / h_k   (Couette shear)
/// with dh/dphi = (e + z (gamma - gamma_b)) x n (z component) for a rigid film, so that the
/// film is in moment balance about z_S:
///   T_j + T_s + (e x F)_z - (gamma - gamma_b) . M = 0                                     (T7)
/// exactly for the discrete sums (asperity contact aside). A force element applies F, M and
/// T_j to the journal at its mid-plane centre and -F, -M, -T_j to the shell at the same
/// point; T_s is the shell's friction torque about its own axis (a report).
///
/// Units: SI throughout (m, s, Pa, Pa s, N, N m, m^3/s, W).
