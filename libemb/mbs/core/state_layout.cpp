#include "libemb/mbs/core/state_layout.h"

#include "libemb/common/error.h"

namespace emb::mbs {

StateLayout::StateLayout(int num_bodies_with_ground, std::vector<int> num_elastic)
    : num_bodies_(num_bodies_with_ground), ne_(std::move(num_elastic)) {
  EMB_CHECK(ne_.empty() || static_cast<int>(ne_.size()) == num_bodies_);
  offset_.assign(num_bodies_, 0);
  for (int b = 0; b < static_cast<int>(ne_.size()); ++b) {
    EMB_CHECK(ne_[b] >= 0 && (b > 0 || ne_[b] == 0));
    offset_[b] = ne_total_;
    ne_total_ += ne_[b];
  }
}

}  // namespace emb::mbs
