#include "libemb/mbs/core/joint.h"

#include "libemb/common/error.h"

namespace emb::mbs {
namespace {

struct TypeInfo {
  JointType type;
  const char* name;
  int count;
};
constexpr TypeInfo kTypes[] = {
    {JointType::kAtPoint, "at-point", 3},        {JointType::kInLine, "in-line", 2},
    {JointType::kInPlane, "in-plane", 1},        {JointType::kPerpendicular, "perpendicular", 1},
    {JointType::kParallel, "parallel", 2},       {JointType::kFixed, "fixed", 6},
    {JointType::kRevolute, "revolute", 5},       {JointType::kTranslational, "translational", 5},
    {JointType::kCylindrical, "cylindrical", 4}, {JointType::kUniversal, "universal", 4},
    {JointType::kSpherical, "spherical", 3},     {JointType::kPlanar, "planar", 3},
};

constexpr int kX = 0, kY = 1, kZ = 2;

void AddAtPoint(std::vector<std::pair<KernelSpec, std::string>>& k) {
  k.push_back({{KernelKind::kPointComponent, kX, 0}, "at-point x"});
  k.push_back({{KernelKind::kPointComponent, kY, 0}, "at-point y"});
  k.push_back({{KernelKind::kPointComponent, kZ, 0}, "at-point z"});
}
void AddInLine(std::vector<std::pair<KernelSpec, std::string>>& k) {
  k.push_back({{KernelKind::kPointOnAxis, 0, kX}, "in-line d.x_J"});
  k.push_back({{KernelKind::kPointOnAxis, 0, kY}, "in-line d.y_J"});
}
void AddParallel(std::vector<std::pair<KernelSpec, std::string>>& k) {
  k.push_back({{KernelKind::kAxisDot, kZ, kX}, "parallel z_I.x_J"});
  k.push_back({{KernelKind::kAxisDot, kZ, kY}, "parallel z_I.y_J"});
}
void AddNoSpin(std::vector<std::pair<KernelSpec, std::string>>& k) {
  k.push_back({{KernelKind::kAxisDot, kX, kY}, "perpendicular x_I.y_J"});
}

}  // namespace

const char* Name(JointType type) {
  for (const auto& t : kTypes)
    if (t.type == type) return t.name;
  return "unknown";
}

JointType ParseJointType(const std::string& name) {
  std::string valid;
  for (const auto& t : kTypes) {
    if (name == t.name) return t.type;
    valid += std::string(valid.empty() ? "" : ", ") + t.name;
  }
  EMB_THROW(InputError, "unknown joint type '" << name << "': expected one of " << valid);
}

int ConstraintCount(JointType type) {
  for (const auto& t : kTypes)
    if (t.type == type) return t.count;
  return 0;
}

const char* Name(JointCoordinate c) {
  return c == JointCoordinate::kRotation ? "rotation" : "translation";
}

std::vector<std::pair<KernelSpec, std::string>> JointKernels(JointType type) {
  std::vector<std::pair<KernelSpec, std::string>> k;
  switch (type) {
    case JointType::kAtPoint:
    case JointType::kSpherical:
      AddAtPoint(k);
      break;
    case JointType::kInLine:
      AddInLine(k);
      break;
    case JointType::kInPlane:
      k.push_back({{KernelKind::kPointOnAxis, 0, kZ}, "in-plane d.z_J"});
      break;
    case JointType::kPerpendicular:
      k.push_back({{KernelKind::kAxisDot, kZ, kZ}, "perpendicular z_I.z_J"});
      break;
    case JointType::kParallel:
      AddParallel(k);
      break;
    case JointType::kFixed:
      AddAtPoint(k);
      AddParallel(k);
      AddNoSpin(k);
      break;
    case JointType::kRevolute:
      AddAtPoint(k);
      AddParallel(k);
      break;
    case JointType::kTranslational:
      AddInLine(k);
      AddParallel(k);
      AddNoSpin(k);
      break;
    case JointType::kCylindrical:
      AddInLine(k);
      AddParallel(k);
      break;
    case JointType::kUniversal:
      AddAtPoint(k);
      k.push_back({{KernelKind::kAxisDot, kZ, kZ}, "perpendicular z_I.z_J"});
      break;
    case JointType::kPlanar:
      k.push_back({{KernelKind::kPointOnAxis, 0, kZ}, "in-plane d.z_J"});
      AddParallel(k);
      break;
  }
  EMB_CHECK(static_cast<int>(k.size()) == ConstraintCount(type));
  return k;
}

KernelSpec CoordinateKernel(JointType type, JointCoordinate c, const std::string& joint_name) {
  const bool rotates = type == JointType::kRevolute || type == JointType::kCylindrical;
  const bool slides = type == JointType::kTranslational || type == JointType::kCylindrical;
  if (c == JointCoordinate::kRotation) {
    EMB_THROW_IF(!rotates, "joint '" << joint_name << "' (" << Name(type)
                                     << "): expected a revolute or cylindrical joint for a "
                                        "rotation coordinate");
    return {KernelKind::kAngle, 0, 0};
  }
  EMB_THROW_IF(!slides, "joint '" << joint_name << "' (" << Name(type)
                                  << "): expected a translational or cylindrical joint for a "
                                     "translation coordinate");
  return {KernelKind::kPointOnAxis, 0, kZ};
}

}  // namespace emb::mbs
