#include "libemb/sweep/sweep_file.h"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <set>

#include "libemb/common/error.h"
#include "libemb/common/fnv1a.h"
#include "libemb/io/atomic_file.h"
#include "libemb/io/hdf5_file.h"

namespace emb::sweep {
namespace {

using U64 = std::uint64_t;

std::string Text(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

// The digest of what a sweep file holds (every attribute and dataset emb reads back), so
// that a file edited after emb wrote it (another speed, other amplitudes) is refused rather
// than merged or resumed. Numbers in %.17g (they round-trip exactly), strings with their
// length (no two contents spell the same).
std::string ContentDigest(const SweepData& d) {
  Fnv1a h;
  auto str = [&h](const std::string& x) {
    h.Add(std::to_string(x.size()) + ":");
    h.Add(x);
  };
  auto num = [&h](double x) { h.Add(Text(x) + " "); };
  str(d.scene);
  str(d.scene_digest);
  str(d.digest);
  num(d.shard_index);
  num(d.shard_count);
  num(d.settings.samples_per_cycle);
  for (double n : d.sweep_rpm) num(n);
  h.Add("|channels");
  for (const auto& c : d.settings.channels) str(c);
  h.Add("|orders");
  for (double o : d.settings.orders) num(o);
  h.Add("|points");
  for (std::size_t i = 0; i < d.points.size(); ++i) {
    const OperatingPoint& p = d.points[i];
    num(i < d.index.size() ? d.index[i] : -1);
    for (double x : {p.rpm, static_cast<double>(p.cycles), static_cast<double>(p.steps), p.change,
                     p.cpu_seconds})
      num(x);
    str(Name(p.status));
    str(p.message);
    for (double x : p.mean) num(x);
    for (double x : p.amplitude.reshaped()) num(x);
    for (double x : p.phase_deg.reshaped()) num(x);
  }
  return h.Hex();
}

}  // namespace

std::string TextDigest(const std::string& text) {
  Fnv1a h;
  h.Add(text);
  return h.Hex();
}

std::string FileDigest(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EMB_THROW_IF(!in, "file '" << path << "' cannot be read (for the sweep's digest)");
  Fnv1a h;
  std::vector<char> chunk(std::size_t{1} << 20);  // body files are 10-200 MB: stream them
  while (in.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || in.gcount() > 0)
    h.Add(chunk.data(), static_cast<std::size_t>(in.gcount()));
  EMB_THROW_IF(in.bad(), "file '" << path << "': read error (for the sweep's digest)");
  return h.Hex();
}

std::string SweepDigest(const std::string& scene_text, const std::vector<std::string>& inputs,
                        const std::vector<double>& sweep_rpm, const OrderSettings& settings) {
  std::string s = std::string(kSweepFormat) + " " + std::to_string(kSweepFormatVersion) + "\n" +
                  TextDigest(scene_text) + "\ninputs";
  for (const auto& f : inputs) s += " " + FileDigest(f);
  s += "\nrpm";
  for (double n : sweep_rpm) s += " " + Text(n);
  s += "\nchannels";
  for (const auto& c : settings.channels) s += " " + c;
  s += "\norders";
  for (double o : settings.orders) s += " " + Text(o);
  s += "\nsamples_per_cycle " + std::to_string(settings.samples_per_cycle);
  return TextDigest(s);
}

void WriteSweepFile(const std::string& path, const SweepData& d) {
  const U64 n = d.points.size(), nc = d.settings.channels.size(), no = d.settings.orders.size();
  EMB_THROW_IF(d.index.size() != n, "sweep file '" << path << "': " << n << " points but "
                                                   << d.index.size() << " indices");
  std::vector<double> rpm, change, cpu, mean, amplitude, phase;
  std::vector<int> cycles, steps;
  std::vector<std::string> status, message;
  long long counts[4] = {0, 0, 0, 0};
  for (const OperatingPoint& p : d.points) {
    EMB_THROW_IF(static_cast<U64>(p.amplitude.rows()) != nc ||
                     static_cast<U64>(p.amplitude.cols()) != no,
                 "sweep file '" << path << "': the point at " << p.rpm << " rpm holds "
                                << p.amplitude.rows() << " x " << p.amplitude.cols()
                                << " amplitudes, expected " << nc << " x " << no);
    rpm.push_back(p.rpm);
    change.push_back(p.change);
    cpu.push_back(p.cpu_seconds);
    cycles.push_back(p.cycles);
    steps.push_back(static_cast<int>(p.steps));
    status.push_back(Name(p.status));
    message.push_back(p.message);
    ++counts[static_cast<int>(p.status)];
    for (U64 c = 0; c < nc; ++c) {
      mean.push_back(p.mean(static_cast<Eigen::Index>(c)));
      for (U64 k = 0; k < no; ++k) {
        amplitude.push_back(p.amplitude(static_cast<Eigen::Index>(c), static_cast<Eigen::Index>(k)));
        phase.push_back(p.phase_deg(static_cast<Eigen::Index>(c), static_cast<Eigen::Index>(k)));
      }
    }
  }
  AtomicFile out(path);
  {
    std::optional<H5File> file;
    out.Create([&](const std::string& temp) { file.emplace(temp, H5File::Mode::kCreate); });
    H5File& h5 = *file;
    h5.SetAttribute("/", "format", std::string(kSweepFormat));
    h5.SetAttribute("/", "version", static_cast<long long>(kSweepFormatVersion));
    h5.SetAttribute("/", "emb_version", std::string(EMB_VERSION));
    h5.SetAttribute("/", "units", std::string("SI; speeds in rpm, phases in degrees, orders per "
                                              "crank revolution, CPU time in s"));
    h5.SetAttribute("/", "scene", d.scene);
    h5.SetAttribute("/", "scene_digest", d.scene_digest);
    h5.SetAttribute("/", "digest", d.digest);
    h5.SetAttribute("/", "content_digest", ContentDigest(d));
    h5.SetAttribute("/", "shard_index", static_cast<long long>(d.shard_index));
    h5.SetAttribute("/", "shard_count", static_cast<long long>(d.shard_count));
    h5.SetAttribute("/", "samples_per_cycle", static_cast<long long>(d.settings.samples_per_cycle));
    h5.SetAttribute("/", "phase_reference",
                    std::string("crank angle theta = 6 rpm (t - t_start) deg; 0 = the scene's "
                                "start pose"));
    h5.SetAttribute("/", "num_converged", counts[0]);
    h5.SetAttribute("/", "num_not_converged", counts[1]);
    h5.SetAttribute("/", "num_failed", counts[2]);
    h5.SetAttribute("/", "num_run_up_windows", counts[3]);
    h5.Write("/sweep_rpm", d.sweep_rpm.data(), {d.sweep_rpm.size()});
    h5.Write("/index", d.index.data(), {n});
    h5.Write("/rpm", rpm.data(), {n});
    h5.Write("/status", status);
    h5.Write("/message", message);
    h5.Write("/cycles", cycles.data(), {n});
    h5.Write("/steps", steps.data(), {n});
    h5.Write("/change", change.data(), {n});
    h5.Write("/cpu_seconds", cpu.data(), {n});
    h5.Write("/channels", d.settings.channels);
    h5.Write("/orders", d.settings.orders.data(), {no});
    h5.Write("/mean", mean.data(), {n, nc});
    h5.Write("/amplitude", amplitude.data(), {n, nc, no});
    h5.Write("/phase_deg", phase.data(), {n, nc, no});
    h5.Close();
  }
  out.Commit();
}

SweepData ReadSweepFile(const std::string& path) {
  const H5File h5(path, H5File::Mode::kRead);
  EMB_THROW_IF(!h5.HasAttribute("/", "format") ||
                   h5.ReadStringAttribute("/", "format") != kSweepFormat,
               "'" << path << "' is not a sweep file (expected format '" << kSweepFormat
                   << "', from emb sweep)");
  const long long version = h5.ReadIntAttribute("/", "version");
  EMB_THROW_IF(version != kSweepFormatVersion,
               "'" << path << "': sweep format version " << version << ", expected "
                   << kSweepFormatVersion
                   << (version < kSweepFormatVersion
                           ? " (written by an older emb, without a content digest; run the "
                             "sweep again)"
                           : " (written by a newer emb)"));
  SweepData d;
  d.scene = h5.ReadStringAttribute("/", "scene");
  d.scene_digest = h5.ReadStringAttribute("/", "scene_digest");
  d.digest = h5.ReadStringAttribute("/", "digest");
  d.shard_index = static_cast<int>(h5.ReadIntAttribute("/", "shard_index"));
  d.shard_count = static_cast<int>(h5.ReadIntAttribute("/", "shard_count"));
  d.settings.samples_per_cycle = static_cast<int>(h5.ReadIntAttribute("/", "samples_per_cycle"));
  d.sweep_rpm = h5.ReadDoubles("/sweep_rpm");
  d.settings.channels = h5.ReadStrings("/channels");
  d.settings.orders = h5.ReadDoubles("/orders");
  d.index = h5.ReadInts("/index");
  const std::vector<double> rpm = h5.ReadDoubles("/rpm"), change = h5.ReadDoubles("/change"),
                            cpu = h5.ReadDoubles("/cpu_seconds"), mean = h5.ReadDoubles("/mean"),
                            amplitude = h5.ReadDoubles("/amplitude"),
                            phase = h5.ReadDoubles("/phase_deg");
  const std::vector<int> cycles = h5.ReadInts("/cycles"), steps = h5.ReadInts("/steps");
  const std::vector<std::string> status = h5.ReadStrings("/status"),
                                 message = h5.ReadStrings("/message");
  const std::size_t n = d.index.size(), nc = d.settings.channels.size(),
                    no = d.settings.orders.size();
  EMB_THROW_IF(rpm.size() != n || change.size() != n || cpu.size() != n || cycles.size() != n ||
                   steps.size() != n || status.size() != n || message.size() != n ||
                   mean.size() != n * nc || amplitude.size() != n * nc * no ||
                   phase.size() != n * nc * no,
               "'" << path << "': the sweep datasets disagree in size (a damaged file?)");
  for (std::size_t i = 0; i < n; ++i) {
    EMB_THROW_IF(d.index[i] < 0 || static_cast<std::size_t>(d.index[i]) >= d.sweep_rpm.size(),
                 "'" << path << "': point index " << d.index[i] << " outside the sweep's "
                     << d.sweep_rpm.size() << " speeds");
    OperatingPoint p;
    p.rpm = rpm[i];
    p.status = ParsePointStatus(status[i]);
    p.message = message[i];
    p.cycles = cycles[i];
    p.steps = steps[i];
    p.change = change[i];
    p.cpu_seconds = cpu[i];
    p.mean.resize(static_cast<Eigen::Index>(nc));
    p.amplitude.resize(static_cast<Eigen::Index>(nc), static_cast<Eigen::Index>(no));
    p.phase_deg.resizeLike(p.amplitude);
    for (std::size_t c = 0; c < nc; ++c) {
      p.mean(static_cast<Eigen::Index>(c)) = mean[i * nc + c];
      for (std::size_t k = 0; k < no; ++k) {
        p.amplitude(static_cast<Eigen::Index>(c), static_cast<Eigen::Index>(k)) =
            amplitude[(i * nc + c) * no + k];
        p.phase_deg(static_cast<Eigen::Index>(c), static_cast<Eigen::Index>(k)) =
            phase[(i * nc + c) * no + k];
      }
    }
    d.points.push_back(std::move(p));
  }
  const std::string stored = h5.ReadStringAttribute("/", "content_digest");
  const std::string computed = ContentDigest(d);
  EMB_THROW_IF(stored != computed,
               "'" << path << "': its content does not match the digest emb wrote with it "
                   << "(content_digest " << stored << ", computed " << computed
                   << "): the file was changed after emb wrote it; expected an unedited sweep "
                      "file (run the sweep, or this point, again)");
  return d;
}

SweepData MergeSweeps(const std::vector<std::string>& paths, const std::vector<SweepData>& shards) {
  EMB_THROW_IF(shards.empty() || paths.size() != shards.size(),
               "sweep merge: expected at least one shard file");
  const SweepData& first = shards.front();
  std::set<int> shard_seen;
  std::map<int, std::pair<OperatingPoint, std::string>> points;  // index -> point, file
  for (std::size_t s = 0; s < shards.size(); ++s) {
    const SweepData& d = shards[s];
    EMB_THROW_IF(d.digest != first.digest,
                 "sweep merge: '" << paths[s] << "' belongs to another sweep than '" << paths[0]
                                  << "' (digest " << d.digest << " vs " << first.digest
                                  << ": scene text, speeds, channels or orders differ)");
    EMB_THROW_IF(d.shard_count != first.shard_count,
                 "sweep merge: '" << paths[s] << "' is shard " << d.shard_index << " of "
                                  << d.shard_count << ", '" << paths[0] << "' one of "
                                  << first.shard_count << ": expected one shard count");
    EMB_THROW_IF(!shard_seen.insert(d.shard_index).second,
                 "sweep merge: shard " << d.shard_index << " given twice ('" << paths[s] << "')");
    for (std::size_t i = 0; i < d.index.size(); ++i) {
      const auto [it, fresh] = points.emplace(d.index[i], std::pair{d.points[i], paths[s]});
      EMB_THROW_IF(!fresh, "sweep merge: the point at " << d.points[i].rpm << " rpm is in '"
                                                        << it->second.second << "' and in '"
                                                        << paths[s] << "'");
    }
  }
  std::string missing;
  for (std::size_t i = 0; i < first.sweep_rpm.size(); ++i)
    if (!points.count(static_cast<int>(i)))
      missing += (missing.empty() ? "" : ", ") + Text(first.sweep_rpm[i]);
  EMB_THROW_IF(!missing.empty(), "sweep merge: no shard holds the point(s) at " << missing
                                     << " rpm: expected all " << first.shard_count
                                     << " shards of the sweep");
  SweepData out = first;
  out.shard_index = 0;
  out.shard_count = 1;
  out.index.clear();
  out.points.clear();
  for (auto& [i, entry] : points) {
    out.index.push_back(i);
    out.points.push_back(entry.first);
  }
  return out;
}

}  // namespace emb::sweep
