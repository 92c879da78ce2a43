#pragma once
/// @file
/// Notation of the multibody module (after Drake `multibody/multibody_doxygen.h`).
///
/// Frames: W is the world (ground, the seed's GRF); B is a body frame with its origin at the
/// body's centre of mass (the seed's LPRF); M (or I, J for the two markers of a joint) is
/// a marker frame fixed on a body.
///
///   p_AB     position of the origin of B measured from the origin of A, expressed in A [m]
///   R_AB     rotation matrix: columns are B's unit axes expressed in A (v_A = R_AB v_B)
///   e_WB     unit quaternion (Euler parameters) of R_WB, stored (w, x, y, z)
///   v_WB     translational velocity of B's origin in W, expressed in W [m/s]
///   omega_B  angular velocity of B in W, expressed in B [rad/s]
///   omega_W  the same angular velocity expressed in W
///   s_B      a marker's position from its body origin, expressed in B [m]
///
/// Generalised coordinates of one moving body (7): q_b = [p_WB (3), e_WB (4)].
/// Generalised velocities of one moving body (6): v_b = [v_WB (3), omega_B (3)].
/// A constraint Jacobian row is taken with respect to the virtual displacement
/// [delta p_WB (3), delta pi_B (3)] with delta R_WB = R_WB [delta pi_B x], so that the
/// velocity constraint is C(q) v and the Lagrange multipliers are forces (N) or torques (N m).
/// Offsets into q, v and the DAE vector come from StateLayout and GglLayout, never from
/// bare indices.
///
/// Equations of the seed (Rahnejat 2010, ch. 1) referenced in this module:
///   (1.18)/(1.24) constrained Lagrange equations with multipliers lambda;
///   (1.19)/(1.20) the Euler body 3-1-3 transformation T = Rz(psi) Rx(theta) Rz(phi);
///   (1.21)/(1.22) at-point constraint; (1.23) hinge (parallel-axes) constraint;
///   (1.25) the Gruebler-Kutzbach count nDOF = 6 (n - 1) - sum C.
