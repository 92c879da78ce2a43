#pragma once
/// @file
/// Pairing the modes of an approximate model with those of a reference by their shapes
/// (modal assurance criterion), degenerate pairs kept together.
///
/// MAC(a, b) = (aᵀb)² / ((aᵀa)(bᵀb)) ∈ [0, 1] for sampled shapes a, b. A round part has exact
/// degenerate pairs (bending in two planes) whose shapes are any rotation of each other, so a
/// single candidate's MAC can be anything in [0, 1]; the score of candidate i for reference
/// mode a is therefore the subspace MAC
///   S(a, G_i) = aᵀ P a / aᵀa,   P the orthogonal projector onto span{b_k : k ∈ G_i},
/// G_i the candidates whose frequency is within `degenerate_tolerance` (relative) of i's.
/// Greedy, in ascending reference order: each reference mode takes the unused candidate with
/// the highest score (the lower index on ties) if that score is ≥ `min_mac`, else stays
/// unpaired (e.g. a shell mode of a tube against a beam).

#include <Eigen/Core>
#include <vector>

namespace emb {

/// MAC matrix (reference modes × candidate modes) of sampled shapes (columns).
/// @throws InputError if the row counts differ.
Eigen::MatrixXd CalcMac(const Eigen::MatrixXd& reference, const Eigen::MatrixXd& candidates);

struct ModePairing {
  std::vector<int> match;  ///< per reference mode: candidate column, or −1 (unpaired)
  Eigen::VectorXd score;   ///< subspace MAC of the match (of the best candidate if unpaired)
};

/// See the file comment. `candidate_hz` gives the candidates' frequencies [Hz].
/// @throws InputError for mismatched sizes or tolerances outside (0, 1).
ModePairing PairModesByShape(const Eigen::MatrixXd& reference, const Eigen::MatrixXd& candidates,
                             const Eigen::VectorXd& candidate_hz, double degenerate_tolerance = 1e-6,
                             double min_mac = 0.5);

}  // namespace emb
