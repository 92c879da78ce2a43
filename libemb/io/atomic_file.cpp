#include "libemb/io/atomic_file.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "libemb/common/error.h"

namespace emb {

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  namespace fs = std::filesystem;
  const fs::path p(path_);
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  std::error_code ec;
  EMB_THROW_IF(!fs::is_directory(dir, ec),
               "output '" << path_ << "': directory '" << dir.string() << "' does not exist");
  EMB_THROW_IF(fs::is_directory(p, ec), "output '" << path_ << "' is a directory; expected a file name");
  temp_ = (dir / ("." + p.filename().string() + ".tmp." + std::to_string(::getpid()))).string();
}

AtomicFile::~AtomicFile() {
  if (!committed_) std::remove(temp_.c_str());
}

void AtomicFile::Commit() {
  if (std::rename(temp_.c_str(), path_.c_str()) != 0)
    EMB_THROW(InputError, "output '" << path_ << "': could not move the finished file into place");
  committed_ = true;
}

void WriteTextFileAtomic(const std::string& path, const std::string& text) {
  AtomicFile file(path);
  {
    std::ofstream out(file.temp_path(), std::ios::binary);
    out << text;
    out.flush();
    EMB_THROW_IF(!out, "output '" << path << "': write failed (disk full or no permission?)");
  }
  file.Commit();
}

}  // namespace emb
