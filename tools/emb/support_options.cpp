#include "tools/emb/support_options.h"

namespace emb::cli {

void SupportOptions::Register(CLI::App& cmd) {
  const struct {
    const char* name;
    std::vector<std::string>* into;
    const char* help;
  } kOptions[] = {
      {"--fixed", &fixed,
       "GROUP[:COMPS]: hold components COMPS (x,y,z comma separated, global axes; all three if "
       "omitted) of every node of a physical group; GROUP may be A&B (the nodes common to groups "
       "A and B, e.g. an edge). Repeatable; default free-free"},
      {"--symmetry", &symmetry,
       "GROUP[:x|y|z]: symmetry plane, the displacement normal to the planar group is held at "
       "its nodes (u.n = 0; n its own normal, may be oblique, or the axis given, which must be "
       "its normal). Repeatable"},
      {"--rbe2", &rbe2,
       "GROUP[@X,Y,Z]:COMPS: the surface group slaved rigidly to a reference node (at the point, "
       "default plane centroid or cylinder axis) whose components COMPS (x,y,z,rx,ry,rz) are "
       "held. Repeatable"},
      {"--rbe3", &rbe3,
       "GROUP[@X,Y,Z]:COMPS: as --rbe2 but the reference node is the area-weighted average of "
       "the surface motion (does not stiffen it). Repeatable"},
      {"--equation", &equations,
       "'A1 N1 C1 A2 N2 C2 ...': the linear constraint sum A_i u(N_i, C_i) = 0 between node "
       "displacements (N: the mesh's node tag, C: x, y or z). Repeatable"},
  };
  for (const auto& o : kOptions) cmd.add_option(o.name, *o.into, o.help);
  cmd.add_option("--equations", equation_file, "File of such equations, one per line ('#' comments)")
      ->check(CLI::ExistingFile);
}

SupportSpecs SupportOptions::Specs() const {
  SupportSpecs specs;
  for (const auto& t : fixed) specs.fixed.push_back(ComponentSupport::Parse(t));
  for (const auto& t : symmetry) specs.symmetry.push_back(SymmetrySupport::Parse(t));
  for (const auto& t : rbe2) specs.reference.push_back(ReferenceSupport::Parse(t, Coupling::kRbe2));
  for (const auto& t : rbe3) specs.reference.push_back(ReferenceSupport::Parse(t, Coupling::kRbe3));
  for (size_t k = 0; k < equations.size(); ++k)
    specs.equations.push_back(NodeEquation::Parse(equations[k], "--equation " + std::to_string(k + 1)));
  if (!equation_file.empty())
    for (auto& e : ReadEquationFile(equation_file)) specs.equations.push_back(std::move(e));
  return specs;
}

}  // namespace emb::cli
