// emb inspect FILE: what is inside a body file (emb reduce): provenance, interfaces, modes,
// invariants and the stored reduction certificate. The file's content digest is verified.

#include <iostream>
#include <memory>

#include "libemb/cms/body_file.h"
#include "libemb/common/error.h"
#include "tools/emb/commands.h"
#include "tools/emb/common_options.h"

namespace emb::cli {
namespace {

struct InspectCommand {
  std::string file;
  OutputOptions out;
  std::string expect_mesh_hash;

  void Run() const {
    BodyFileInfo info;
    const ReducedBody body = ReadBodyFile(file, &info);
    if (!expect_mesh_hash.empty()) CheckBodyProvenance(file, info, expect_mesh_hash);

    Summary s("Body file " + file);
    s.Add("format", "format", std::string(kBodyFormat) + " v" + std::to_string(info.format_version));
    s.Add("content_digest", "content digest (verified)", info.content_digest);
    s.Add("source", "made from", info.provenance.source);
    s.Add("mesh_hash", "mesh hash", info.provenance.mesh_hash);
    s.Add("element_types", "elements", info.element_types);
    s.Add("options", "options", info.provenance.options);
    s.Add("command", "command", info.provenance.command);
    s.Add("material", "material",
          info.material.name + ": E = " + std::to_string(info.material.youngs_modulus) +
              " Pa, nu = " + std::to_string(info.material.poisson_ratio) +
              ", rho = " + std::to_string(info.material.density) + " kg/m^3");
    s.Add("basis", "basis", body.free_free ? std::string("free-free") : std::string("Craig-Bampton"));
    s.Add("selection", "selection", body.selection_note);
    s.Add("fe_dofs", "FE degrees of freedom", static_cast<long long>(body.num_fe_dofs));
    s.Add("reduced_coordinates", "reduced coordinates", static_cast<long long>(body.K.rows()));
    s.Add("elastic_modes", "elastic modes", static_cast<long long>(body.modes.frequencies_hz.size()));
    s.Add("damping", "damping", body.damping.Describe());
    s.Add("geometric_stiffness", "geometric stiffening", body.geometric_stiffness.Describe());
    std::vector<std::string> stress_groups;
    for (const auto& g : body.stress_groups)
      stress_groups.push_back(g.name + " (" + std::to_string(g.num_nodes()) + " nodes)");
    if (stress_groups.empty()) stress_groups.push_back("none");
    s.Add("stress_groups", "modal stresses (stress groups)", stress_groups);
    const ModalStressSurface& surface = body.stress_surface;
    s.Add("stress_surface", "modal stresses on the whole surface",
          surface.empty() ? std::string("none (emb reduce --stress-surface stores them)")
                          : std::to_string(surface.num_nodes()) + " nodes, " +
                                std::to_string(surface.num_faces()) + " faces");
    const InertiaInvariants& inv = body.invariants;
    s.Add("mass_kg", "mass [kg]", inv.mass);
    const Eigen::Vector3d c = inv.CenterOfMass();
    s.Add("center_of_mass", "centre of mass [m]", std::vector<double>{c.x(), c.y(), c.z()});
    const Eigen::Matrix3d I = inv.InertiaAboutCom();
    s.Add("inertia_diagonal", "inertia about CM, diagonal [kg m^2]",
          std::vector<double>{I(0, 0), I(1, 1), I(2, 2)});

    Table itf("Interfaces", {"name", "coupling", "x", "y", "z", "point", "nodes"},
              {"interface", "coupling", "x [m]", "y [m]", "z [m]", "reference point", "nodes"});
    for (const auto& i : body.interfaces)
      itf.AddRow({i.name, std::string(Name(i.coupling)), i.point.x(), i.point.y(), i.point.z(),
                  i.point_source, static_cast<long long>(i.nodes.size())});
    Table modes("Elastic modes", {"mode", "frequency_hz", "damping_ratio"},
                {"mode", "frequency [Hz]", "damping ratio"});
    for (int k = 0; k < body.modes.frequencies_hz.size(); ++k)
      modes.AddRow({static_cast<long long>(k + 1), body.modes.frequencies_hz[k],
                    body.damping_ratios[k]});
    if (out.json) {
      PrintJson({{"summary", s.ToJson()}, {"interfaces", itf.ToJson()}, {"modes", modes.ToJson()}});
    } else {
      s.Print(std::cout);
      std::cout << "\n";
      itf.Print(std::cout);
      std::cout << "\n";
      modes.Print(std::cout);
    }
  }
};

}  // namespace

void RegisterInspectCommand(CLI::App& app) {
  auto st = std::make_shared<InspectCommand>();
  CLI::App* cmd = app.add_subcommand(
      "inspect", "Print what is inside a body file (emb reduce), after verifying its content digest");
  cmd->add_option("file", st->file, "Body file (.h5)")->required();
  cmd->add_option("--expect-mesh-hash", st->expect_mesh_hash,
                  "Refuse the file unless it was reduced from the mesh with this hash");
  st->out.Register(*cmd);
  cmd->callback([st] { st->Run(); });
}

}  // namespace emb::cli
