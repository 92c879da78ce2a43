// emb mesh PART: mesh a geometry (or read a mesh), check every cell, report what is in it.

#include <iostream>
#include <memory>

#include "libemb/common/timer.h"
#include "libemb/fe/assembly.h"
#include "libemb/fe/mass_properties.h"
#include "libemb/mesh/gmsh_reader.h"
#include "tools/emb/commands.h"
#include "tools/emb/common_options.h"
#include "tools/emb/progress_display.h"

namespace emb::cli {
namespace {

struct MeshCommand {
  PartOptions part;
  OutputOptions out;

  void Run() const {
    const PreparedOutputs outputs({{part.save_mesh, "--save-mesh"}}, {part.file});
    Stopwatch sw;
    const Mesh mesh = ReadMesh(part.file, part.Meshing(), MakeProgressDisplay(out.quiet));
    const double t_mesh = sw.seconds();
    part.material.Validate();
    const MassProperties mp = CalcMassProperties(mesh, part.material.density);
    FinishProgressLine();

    Summary s("Mesh " + mesh.source);
    s.Add("nodes", "nodes", mesh.num_nodes());
    s.Add("dofs", "degrees of freedom", 3 * mesh.num_nodes());
    for (const auto& b : mesh.blocks)
      s.Add("cells_" + std::string(Name(b.type)), std::string(Name(b.type)) + " cells",
            b.num_cells());
    const Eigen::Vector3d lo = mesh.nodes.rowwise().minCoeff(), hi = mesh.nodes.rowwise().maxCoeff();
    s.Add("bounding_box_min_m", "bounding box min [m]", {lo.x(), lo.y(), lo.z()});
    s.Add("bounding_box_max_m", "bounding box max [m]", {hi.x(), hi.y(), hi.z()});
    s.Add("volume_m3", "volume [m^3]", mp.volume);
    s.Add("mass_kg", "mass [kg]", mp.mass);
    const Eigen::Vector3d& c = mp.center_of_mass;
    s.Add("center_of_mass_m", "centre of mass [m]", {c.x(), c.y(), c.z()});
    const Eigen::Matrix3d& I = mp.inertia_about_com;
    s.Add("inertia_kgm2", "inertia about CoM [kg m^2]",
          {{I(0, 0), I(0, 1), I(0, 2)}, {I(1, 0), I(1, 1), I(1, 2)}, {I(2, 0), I(2, 1), I(2, 2)}});
    s.Add("mesh_hash", "mesh hash", MeshHash(mesh));
    s.Add("seconds", "time to mesh/read [s]", t_mesh);

    Table groups("Physical groups", {"name", "dim", "nodes", "faces"},
                 {"name", "dim", "nodes", "faces"});
    for (const auto& g : mesh.groups) {
      long long faces = 0;
      for (const auto& f : g.faces) faces += f.num_cells();
      groups.AddRow({g.name, static_cast<long long>(g.dim), static_cast<long long>(g.nodes.size()),
                     faces});
    }
    if (out.json) {
      PrintJson({{"mesh", s.ToJson()}, {"groups", groups.ToJson()}});
    } else if (!out.quiet || part.save_mesh.empty()) {  // without a file the table is the result
      s.Print(std::cout);
      std::cout << "\n";
      groups.Print(std::cout);
    }
  }
};

}  // namespace

void RegisterMeshCommand(CLI::App& app) {
  auto cmd_state = std::make_shared<MeshCommand>();
  CLI::App* cmd = app.add_subcommand(
      "mesh", "Mesh a geometry (or read a mesh), check every cell and report nodes, cells, "
              "physical groups and mass properties");
  cmd_state->part.Register(*cmd);
  cmd_state->out.Register(*cmd);
  cmd->callback([cmd_state] { cmd_state->Run(); });
}

}  // namespace emb::cli
