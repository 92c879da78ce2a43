#pragma once
/// @file
/// Parts of a scene that come from a body file (emb reduce): `model: rigid` (mass
/// properties and interface points only) or `model: cms` (a flexible body in the floating
/// frame of reference, mbs/elastic_model.h, seed eqs. 1.27–1.30), with markers placed on the
/// file's interfaces. Internal to emb_scene.

#include <map>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "libemb/mbs/core/body.h"

namespace emb::scene {

/// How a scene uses a body file.
struct BodyFileOptions {
  bool flexible{true};           ///< model: cms (false: model: rigid)
  int max_modes{-1};             ///< keep the lowest N elastic modes (-1: all)
  double fmax_hz{-1.0};          ///< keep modes up to this frequency (-1: no limit)
  /// Kept modes above this frequency are quasi-static (ElasticModel::quasi_static; -1: none).
  double dynamic_band_hz{-1.0};
  int geometric_stiffening{-1};  ///< 1 on, 0 off, -1 on if the file has the data
  std::string expect_mesh_hash;  ///< refuse the file if its mesh hash differs (empty: no check)
};

/// What the markers need of a body-file part.
struct BodyFilePart {
  std::string file;
  bool flexible{false};
  Eigen::Vector3d com_mesh{Eigen::Vector3d::Zero()};  ///< undeformed CM in mesh coordinates
  std::vector<std::string> interface_names;
  std::vector<Eigen::Vector3d> interface_points;      ///< mesh coordinates [m]
  Eigen::MatrixXd interface_shapes;                   ///< 6 nb x ne (kept modes)
  std::string note;                                   ///< what was kept, for the run report
  /// Index of interface `name`. @throws InputError naming the part, the file and the
  /// available interfaces (with a did-you-mean).
  int FindInterface(const std::string& part, const std::string& name) const;
};

/// Reads `path` and fills the mass properties (and, if flexible, the elastic model) of
/// `body` (whose name, pose and velocities the caller sets). `mesh_origin_W` and `R_WM` place
/// the mesh frame in W; the body frame origin goes to the CM.
/// @throws InputError naming the part and the file for a bad or stale file, more modes
/// requested than the file has, or an empty frequency band.
BodyFilePart LoadBodyFilePart(const std::string& path, const BodyFileOptions& options,
                              const Eigen::Vector3d& mesh_origin_W, const Eigen::Matrix3d& R_WM,
                              mbs::RigidBody* body);

}  // namespace emb::scene
