#pragma once
/// @file
/// Constraint elements: primitive constraints, standard joints assembled from them (seed
/// §1.4.2 and §1.5 counts), prescribed motions on a joint coordinate and gear/couplers.
/// Every element expands to scalar equations named "<element>: <primitive> <component>",
/// which is how the DOF report names a redundant equation.
///
/// Marker convention: marker I is on the first body, marker J on the second; the joint
/// axis is z_J (and z_I once assembled). The joint rotation coordinate is the angle of x_I
/// about z_J measured from x_J; the translation coordinate is (p_I - p_J) . z_J.

#include <string>
#include <vector>

#include "libemb/mbs/core/time_function.h"

namespace emb::mbs {

/// The scalar constraint kernels (their evaluation: constraints/primitive.h).
enum class KernelKind { kPointComponent, kPointOnAxis, kAxisDot, kAngle };

/// Which kernel, and which axes: for kPointComponent axis_i is the world axis (0, 1, 2);
/// for kPointOnAxis axis_j is the axis of marker J; for kAxisDot axis_i of marker I and
/// axis_j of marker J; kAngle uses x_I, x_J, y_J, z_J.
struct KernelSpec {
  KernelKind kind{KernelKind::kPointComponent};
  int axis_i{0};
  int axis_j{0};
};


/// Primitive constraints and standard joints with the number of equations each adds.
enum class JointType {
  kAtPoint,        ///< 3: p_I = p_J                                   (eq. 1.21)
  kInLine,         ///< 2: I on the z-axis of J (d.x_J = d.y_J = 0)
  kInPlane,        ///< 1: I in the xy-plane of J (d.z_J = 0)
  kPerpendicular,  ///< 1: z_I . z_J = 0
  kParallel,       ///< 2: z_I . x_J = z_I . y_J = 0                      (eq. 1.23)
  kFixed,          ///< 6: at-point + parallel + x_I . y_J = 0
  kRevolute,       ///< 5: at-point + parallel
  kTranslational,  ///< 5: in-line + parallel + x_I . y_J = 0
  kCylindrical,    ///< 4: in-line + parallel
  kUniversal,      ///< 4: at-point + perpendicular (the cross axes z_I, z_J)
  kSpherical,      ///< 3: at-point
  kPlanar,         ///< 3: in-plane + parallel
};

/// "revolute", "at-point", ... (the scene-file spelling).
const char* Name(JointType type);
/// Parses a scene-file spelling. @throws InputError with the list of valid names.
JointType ParseJointType(const std::string& name);
/// Number of scalar equations (the seed's C in eq. 1.25).
int ConstraintCount(JointType type);

/// Which joint coordinate a motion, coupler or rotational force acts on.
enum class JointCoordinate { kRotation, kTranslation };
const char* Name(JointCoordinate c);

/// One scalar constraint equation:
///   Phi = sum_k coeff[k] g_k(q) - f(t)   (f only if has_function),
/// g_k a kernel between the markers of term k. Angle kernels are unwrapped continuously
/// through `angle_slot[k]` (see ConstraintWorkspace).
struct ScalarEquation {
  int element{-1};    ///< index of the constraint element that owns it
  std::string label;  ///< "at-point x", "parallel z.x", "motion rotation", ...
  int num_terms{1};
  KernelSpec kernel[2];
  int marker_i[2]{-1, -1};
  int marker_j[2]{-1, -1};
  double coeff[2]{1.0, 0.0};
  int angle_slot[2]{-1, -1};  ///< set by System::Finalize for angle kernels
  bool has_function{false};
  TimeFunction function;
};

/// The kernels of a joint or primitive between markers I and J, labelled.
std::vector<std::pair<KernelSpec, std::string>> JointKernels(JointType type);

/// The kernel measuring a joint coordinate ("rotation" = angle kernel, "translation" =
/// d . z_J). @throws InputError if the joint type has no such free coordinate
/// (e.g. a rotation of a translational joint).
KernelSpec CoordinateKernel(JointType type, JointCoordinate c, const std::string& joint_name);

}  // namespace emb::mbs
