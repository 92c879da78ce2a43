#pragma once
// The command prefix that starts N MPI ranks in tests, for a CI container with 2 cores: root
// allowed, more ranks than cores allowed, no remote launcher needed, shared-memory transport
// without the ptrace-based single copy (often forbidden in containers). Open MPI's names.

#include <string>

namespace emb::test {

inline std::string MpirunPrefix(const std::string& mpiexec, int ranks) {
  return "env OMPI_MCA_plm=isolated OMPI_MCA_btl_vader_single_copy_mechanism=none "
         "OMPI_MCA_rmaps_base_oversubscribe=1 '" +
         mpiexec + "' --allow-run-as-root -n " + std::to_string(ranks) + " ";
}

}  // namespace emb::test
