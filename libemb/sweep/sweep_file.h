#pragma once
/// @file
/// The results of a speed sweep (HDF5, format "emb-sweep", version 2, SI units; n points,
/// nc channels, no orders; row-major as h5py shows it), written atomically (temp + rename):
///   /                 attrs format, version, emb_version, scene (path), scene_digest (FNV-1a
///                     of the scene text), digest (SweepDigest: scene text, the files it
///                     reads, all speeds, channels, orders, samples per cycle),
///                     content_digest (FNV-1a of everything below and above as read back:
///                     a file edited after emb wrote it is refused), shard_index,
///                     shard_count,
///                     samples_per_cycle, phase_reference, num_converged,
///                     num_not_converged, num_failed, num_run_up_windows
///   /sweep_rpm        [N] every speed of the whole sweep (all shards) [rpm]
///   /index            [n] each point's position in /sweep_rpm
///   /rpm              [n] [rpm]
///   /status           [n] "converged", "not-converged", "failed" or, for the windows of a
///                     run-up (emb runup, order_tracking.h), "run-up" (operating_point.h)
///   /message          [n] why a point failed or did not converge ("" otherwise)
///   /cycles           [n] whole cycles run;  /change [n] last cycle-to-cycle change
///   /cpu_seconds      [n] CPU time of the point [s];  /steps [n] integrator steps
///   /channels [nc], /orders [no] (per crank revolution)
///   /mean             [n, nc]      channel means over the analysed cycle
///   /amplitude        [n, nc, no]  in the channel's unit (NaN for a failed point)
///   /phase_deg        [n, nc, no]  of cos(o theta + phase), theta = 0 at the scene's start
/// A point file of a sweep (for resuming) is the same format with one point.

#include <string>
#include <vector>

#include "libemb/sweep/operating_point.h"

namespace emb::sweep {

inline constexpr const char* kSweepFormat = "emb-sweep";
inline constexpr int kSweepFormatVersion = 2;  ///< 2: with content_digest

/// A sweep, or the part of it one shard (or one point file) holds.
struct SweepData {
  std::string scene;         ///< the scene file as given
  std::string scene_digest;  ///< TextDigest of its text
  std::string digest;        ///< SweepDigest: what makes two sweeps the same
  int shard_index{0}, shard_count{1};
  std::vector<double> sweep_rpm;  ///< every speed of the sweep [rpm]
  OrderSettings settings;
  std::vector<int> index;                ///< per point held: position in sweep_rpm
  std::vector<OperatingPoint> points;    ///< in the order of `index`
};

/// FNV-1a 64-bit digest of `text` as 16 hex digits.
std::string TextDigest(const std::string& text);
/// FNV-1a digest of a file's bytes. @throws InputError if it cannot be read.
std::string FileDigest(const std::string& path);
/// The digest of a sweep definition: the scene text, the bytes of every other file the scene
/// reads (`inputs`: body files, geometries; a re-reduced body file makes another sweep), every
/// speed, the channels, the orders and the samples per cycle.
std::string SweepDigest(const std::string& scene_text, const std::vector<std::string>& inputs,
                        const std::vector<double>& sweep_rpm, const OrderSettings& settings);

/// Writes `data` to `path` atomically. @throws InputError if it cannot be written.
void WriteSweepFile(const std::string& path, const SweepData& data);
/// @throws InputError for a file that is not an emb-sweep file of this version, whose
/// datasets disagree in size, or whose content does not match its content_digest.
SweepData ReadSweepFile(const std::string& path);

/// Merges shard files of one sweep into the whole sweep (shard 0 of 1, points in sweep order).
/// @throws InputError naming the file if the shards belong to different sweeps (digest),
/// disagree on the shard count, repeat a shard or a point, or leave points out (named by rpm).
SweepData MergeSweeps(const std::vector<std::string>& paths, const std::vector<SweepData>& shards);

}  // namespace emb::sweep
