#pragma once
/// @file
/// Suggestions for misspelt names in error messages ("unknown body 'crnk'; did you mean
/// 'crank'?"), by Levenshtein edit distance.

#include <string>
#include <vector>

namespace emb {

/// Levenshtein distance between a and b (insertions, deletions, substitutions).
/// Cost O(|a| |b|).
int EditDistance(const std::string& a, const std::string& b);

/// "; did you mean 'crank'?" for the nearest of `candidates` to `name`, or "" when none is
/// a near miss (more than max(2, |name|/3) edits away).
std::string DidYouMean(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace emb
