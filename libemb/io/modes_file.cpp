#include "libemb/io/modes_file.h"

#include <filesystem>
#include <optional>

#include "libemb/io/atomic_file.h"
#include "libemb/io/hdf5_file.h"
#include "libemb/io/xdmf_writer.h"
#include "libemb/io/mesh_io.h"

namespace emb {

void WriteModesFile(const std::string& path, const std::string& xdmf_path, const Mesh& mesh,
                    const IsotropicMaterial& material, const ModalResult& modes,
                    const Provenance& provenance) {
  AtomicFile out(path);
  {
    std::optional<H5File> file;
    out.Create([&](const std::string& temp) { file.emplace(temp, H5File::Mode::kCreate); });
    H5File& h5 = *file;
    h5.SetAttribute("/", "format", std::string(kModesFormat));
    h5.SetAttribute("/", "format_version", static_cast<long long>(kModesFormatVersion));
    h5.SetAttribute("/", "emb_version", std::string(EMB_VERSION));
    h5.SetAttribute("/", "units",
                    std::string("SI: m, kg, s; frequencies in Hz; eigenvalues in rad^2/s^2; "
                                "mode shapes mass-normalised (1/sqrt(kg))"));
    WriteProvenance(h5, provenance);
    h5.SetAttribute("/material", "name", material.name);
    h5.SetAttribute("/material", "youngs_modulus", material.youngs_modulus);
    h5.SetAttribute("/material", "poisson_ratio", material.poisson_ratio);
    h5.SetAttribute("/material", "density", material.density);
    WriteMesh(h5, mesh);

    const EigenResult& e = modes.eig;
    const std::uint64_t m = static_cast<std::uint64_t>(e.eigenvalues.size());
    const std::uint64_t n = static_cast<std::uint64_t>(mesh.num_nodes());
    h5.Write("/modes/frequencies_hz", modes.frequencies_hz.data(), {m});
    h5.Write("/modes/eigenvalues", e.eigenvalues.data(), {m});
    h5.Write("/modes/shapes", e.vectors.data(), {m, n, 3});  // column k = mode k, xyz per node
    h5.Write("/modes/backward_errors", e.backward_errors.data(), {m});
    h5.SetAttribute("/modes", "status", std::string(Name(e.status)));
    h5.SetAttribute("/modes", "message", e.message);
    h5.SetAttribute("/modes", "num_rigid_modes", static_cast<long long>(modes.num_rigid_modes));
    h5.SetAttribute("/modes", "rigid_threshold", modes.rigid_threshold);
    h5.SetAttribute("/modes", "shift", e.shift);
    h5.SetAttribute("/modes", "method", e.method);
    h5.SetAttribute("/modes", "iterations", static_cast<long long>(e.iterations));
    h5.SetAttribute("/modes", "num_solves", static_cast<long long>(e.num_solves));
    h5.SetAttribute("/modes", "orthonormality_error", e.orthonormality_error);
    h5.SetAttribute("/modes", "max_backward_error", e.max_backward_error);
    h5.SetAttribute("/modes", "nnz_factor", static_cast<long long>(e.factor.nnz_factor));
    h5.Close();
  }

  // Both files are complete before either takes its name.
  std::optional<AtomicFile> xdmf;
  if (!xdmf_path.empty()) {
    std::vector<double> steps;
    std::vector<std::string> names;
    for (int k = 0; k < modes.frequencies_hz.size(); ++k) {
      steps.push_back(k + 1);
      char buf[64];
      std::snprintf(buf, sizeof buf, "mode %d: %.6g Hz", k + 1, modes.frequencies_hz[k]);
      names.emplace_back(buf);
    }
    const std::string h5_name = std::filesystem::path(path).filename().string();
    xdmf.emplace(xdmf_path);
    xdmf->WriteText(MakeXdmfSteps(h5_name, mesh, "/modes/shapes", "mode_shape", steps, names));
  }
  out.Commit();
  if (xdmf) xdmf->Commit();
}

}  // namespace emb
