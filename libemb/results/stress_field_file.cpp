#include "libemb/results/stress_field_file.h"

#include <filesystem>
#include <optional>
#include <sstream>
#include <tuple>

#include "libemb/common/error.h"
#include "libemb/fe/stress_measures.h"
#include "libemb/io/atomic_file.h"
#include "libemb/io/hdf5_file.h"
#include "libemb/io/xdmf_writer.h"

namespace emb::results {
namespace {

// The node attributes of step s of k of a field with m nodes: HyperSlabs of the (k, m[, 6])
// datasets at `base` in `h5`.
void WriteAttributes(std::ostream& x, const std::string& h5, const std::string& base,
                     std::uint64_t s, std::uint64_t k, std::uint64_t m) {
  for (const auto& [field, scalar] :
       {std::tuple{"von_mises", true}, std::tuple{"max_principal", true},
        std::tuple{"signed_von_mises", true}, std::tuple{"stress", false}}) {
    const std::string tail = scalar ? "" : " 6";
    x << "     <Attribute Name=\"" << field << "\" AttributeType=\""
      << (scalar ? "Scalar" : "Tensor6") << "\" Center=\"Node\">\n"
      << "      <DataItem ItemType=\"HyperSlab\" Dimensions=\"" << m << tail << "\">\n"
      << "       <DataItem Dimensions=\"3 " << (scalar ? 2 : 3) << "\" Format=\"XML\">" << s << " 0"
      << (scalar ? "" : " 0") << " 1 1" << (scalar ? "" : " 1") << " 1 " << m << tail
      << "</DataItem>\n       <DataItem Dimensions=\"" << k << " " << m << tail
      << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5 << ":" << base << "/"
      << field << "</DataItem>\n      </DataItem>\n     </Attribute>\n";
  }
}

// One uniform grid of step s: `topology` (XML), the field's geometry and attributes.
void WriteGrid(std::ostream& x, const std::string& name, const std::string& topology,
               const std::string& h5, const std::string& base, std::uint64_t s, std::uint64_t k,
               std::uint64_t m) {
  x << "    <Grid Name=\"" << name << "\" GridType=\"Uniform\">\n"
    << topology << "     <Geometry GeometryType=\"XYZ\">\n      <DataItem Dimensions=\"" << m
    << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5 << ":" << base
    << "/coordinates</DataItem>\n     </Geometry>\n";
  WriteAttributes(x, h5, base, s, k, m);
  x << "    </Grid>\n";
}

void WriteField(H5File& out, std::ostream& x, const std::string& h5, const NodalStressField& f) {
  const std::uint64_t m = f.nodes.size(), k = f.times.size();
  EMB_CHECK(static_cast<std::uint64_t>(f.coordinates.rows()) == m && f.coordinates.cols() == 3 &&
            f.stress.size() == k);
  std::vector<double> xyz, stress, vm, p1, svm;
  for (std::uint64_t i = 0; i < m; ++i)
    for (int c = 0; c < 3; ++c) xyz.push_back(f.coordinates(static_cast<Eigen::Index>(i), c));
  for (const Eigen::MatrixXd& sigma : f.stress) {
    EMB_CHECK(sigma.rows() == 6 && static_cast<std::uint64_t>(sigma.cols()) == m);
    for (Eigen::Index i = 0; i < sigma.cols(); ++i) {
      const Voigt6 v = sigma.col(i);
      for (int c = 0; c < 6; ++c) stress.push_back(v[c]);
      vm.push_back(VonMises(v));
      p1.push_back(PrincipalStresses(v)[0]);
      svm.push_back(SignedVonMises(v));
    }
  }
  const std::string& base = f.path;
  out.Write(base + "/nodes", f.nodes.data(), {m});
  out.Write(base + "/coordinates", xyz.data(), {m, 3});
  out.Write(base + "/times", f.times.data(), {k});
  out.Write(base + "/stress", stress.data(), {k, m, 6});
  out.Write(base + "/von_mises", vm.data(), {k, m});
  out.Write(base + "/max_principal", p1.data(), {k, m});
  out.Write(base + "/signed_von_mises", svm.data(), {k, m});
  // Topology per face block (written once, shared by the steps).
  std::vector<std::string> topologies, names;
  for (const CellBlock& b : f.faces) {
    const std::uint64_t n = b.nodes_per_cell(), c = b.num_cells();
    for (int v : b.connectivity) EMB_CHECK(v >= 0 && static_cast<std::uint64_t>(v) < m);
    const std::string type(Name(b.type));
    out.Write(base + "/faces/" + type, b.connectivity.data(), {c, n});
    std::ostringstream t;
    t << "     <Topology TopologyType=\"" << XdmfTopologyName(b.type) << "\" NumberOfElements=\""
      << c << "\">\n      <DataItem Dimensions=\"" << c << " " << n
      << "\" NumberType=\"Int\" Precision=\"4\" Format=\"HDF\">" << h5 << ":" << base << "/faces/"
      << type << "</DataItem>\n     </Topology>\n";
    topologies.push_back(t.str());
    names.push_back(type);
  }
  if (topologies.empty()) {
    topologies.push_back("     <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" +
                         std::to_string(m) + "\"/>\n");
    names.emplace_back("nodes");
  }
  x << "  <Grid Name=\"" << f.title << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::uint64_t s = 0; s < k; ++s) {
    const bool several = topologies.size() > 1;
    std::ostringstream step;
    step << "t = " << f.times[s] << " s";
    if (several)
      x << "   <Grid Name=\"" << step.str()
        << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
        << "    <Time Value=\"" << f.times[s] << "\"/>\n";
    for (std::size_t b = 0; b < topologies.size(); ++b) {
      std::ostringstream grid;
      if (!several) grid << "     <Time Value=\"" << f.times[s] << "\"/>\n";
      WriteGrid(x, several ? names[b] : step.str(), grid.str() + topologies[b], h5, base, s, k, m);
    }
    if (several) x << "   </Grid>\n";
  }
  x << "  </Grid>\n";
}

}  // namespace

void WriteStressFields(const std::string& h5_path, const std::string& xdmf_path,
                       const std::vector<NodalStressField>& fields) {
  AtomicFile h5_out(h5_path);
  std::ostringstream x;
  x.precision(12);
  x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"2.0\">\n <Domain>\n";
  const std::string h5_name = std::filesystem::path(h5_path).filename().string();
  {
    std::optional<H5File> file;
    h5_out.Create([&](const std::string& temp) { file.emplace(temp, H5File::Mode::kCreate); });
    H5File& h5 = *file;
    h5.SetAttribute("/", "format", std::string("emb.stress_fields"));
    h5.SetAttribute("/", "units",
                    std::string("SI: m, s, Pa; stress in Voigt order xx, yy, zz, "
                                "xy, yz, zx, mesh axes"));
    for (const NodalStressField& f : fields)
      if (!f.times.empty()) WriteField(h5, x, h5_name, f);
    h5.Close();
  }
  x << " </Domain>\n</Xdmf>\n";
  AtomicFile xdmf(xdmf_path);
  xdmf.WriteText(x.str());
  h5_out.Commit();
  xdmf.Commit();
}

}  // namespace emb::results
