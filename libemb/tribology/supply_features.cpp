#include "libemb/tribology/supply_features.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "libemb/common/error.h"

namespace emb::tribology {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Features are tested against node coordinates; a node exactly on a feature's border (a
// groove of width 2 dz centred on a node row) must count despite round-off in z_j and phi_i,
// which are sums of a few terms: 1e-9 of the spacing is far above that and far below any
// physical tolerance.
constexpr double kBorderSlack = 1e-9;

// (-pi, pi]
double WrapSigned(double a) {
  a = std::fmod(a, kTwoPi);
  if (a > std::numbers::pi) a -= kTwoPi;
  if (a <= -std::numbers::pi) a += kTwoPi;
  return a;
}

// [0, 2 pi)
double WrapPositive(double a) {
  a = std::fmod(a, kTwoPi);
  return a < 0.0 ? a + kTwoPi : a;
}

// The width of a journal hole's taper beyond its own radius, in node spacings
// (supply_features.h: some node within rho at every angle).
constexpr double kTaperSpacings = 1.2;

}  // namespace

namespace {

// The checks every circular hole gets (a shell's or a journal's): finite centre, positive
// diameter, supply pressure >= 0, inside the bearing's length.
template <class Hole>
void CheckHole(const BearingGrid& grid, const Hole& o, const std::string& key,
               const std::string& who) {
  const double half_length = 0.5 * grid.length();
  EMB_THROW_IF(!std::isfinite(o.angle),
               who << ": expected a finite " << key << ".angle, got " << o.angle);
  EMB_THROW_IF(!std::isfinite(o.axial_position),
               who << ": expected a finite " << key << ".axial_position, got " << o.axial_position);
  EMB_THROW_IF(!(std::isfinite(o.diameter) && o.diameter > 0.0),
               who << ": expected a positive " << key << ".diameter, got " << o.diameter << " m");
  EMB_THROW_IF(!(std::isfinite(o.supply_pressure) && o.supply_pressure >= 0.0),
               who << ": expected a supply pressure >= 0 Pa (gauge) for " << key
                   << ".supply_pressure, got " << o.supply_pressure << " Pa");
  EMB_THROW_IF(std::abs(o.axial_position) + 0.5 * o.diameter > half_length * (1 + kBorderSlack),
               who << ": " << key
                   << " reaches outside the bearing: expected |axial_position| "
                      "+ diameter/2 <= L/2 = "
                   << half_length << " m, got " << std::abs(o.axial_position) + 0.5 * o.diameter
                   << " m");
}

}  // namespace

void JournalFeed::clear() {
  unknown.clear();
  conductance.clear();
  conductance_slope.clear();
  supply_psi.clear();
}

void CheckJournalOilHoles(const BearingGrid& grid, const std::vector<JournalOilHole>& holes,
                          const std::string& who) {
  for (size_t h = 0; h < holes.size(); ++h) {
    const std::string key = "journal_oil_holes[" + std::to_string(h) + "]";
    CheckHole(grid, holes[h], key, who);
    // A hole of the journal's radius or larger wraps around it (the weights' angle would
    // flip sign across the bearing).
    EMB_THROW_IF(holes[h].diameter >= grid.radius(),
                 who << ": expected " << key << ".diameter below the journal's radius "
                     << grid.radius() << " m, got " << holes[h].diameter << " m");
  }
}

void CalcJournalFeed(const BearingGrid& grid, const std::vector<JournalOilHole>& holes,
                     double hole_conductance, const std::vector<double>& supply_psi, double psi,
                     JournalFeed* feed) {
  feed->clear();
  const double R = grid.radius(), dphi = grid.dphi();
  const int N = grid.num_circumferential(), m = grid.num_rows();
  const double spacing = std::max(R * dphi, grid.dz());
  for (size_t h = 0; h < holes.size(); ++h) {
    const JournalOilHole& o = holes[h];
    const double radius = 0.5 * o.diameter, band = kTaperSpacings * spacing;
    const double rho = radius + band;
    const double phi_h = WrapPositive(o.angle + psi);
    // Columns within rho of the centre (the window wraps; at most all N).
    const int reach = std::min(N / 2, static_cast<int>(std::ceil(rho / (R * dphi))) + 1);
    const int centre = static_cast<int>(std::lround(phi_h / dphi));
    const int first = feed->size();
    double sum = 0.0, sum_slope = 0.0;
    for (int di = -reach; di <= reach && di < N - reach; ++di) {
      const int i = ((centre + di) % N + N) % N;
      const double a = WrapSigned(grid.angle(i) - phi_h), s = R * a;
      for (int j = 1; j <= m; ++j) {
        const double dz = grid.axial(j) - o.axial_position;
        const double d = std::sqrt(s * s + dz * dz);
        if (d >= rho) continue;
        // w = 1 inside the hole; (1 - t^2)^2 over the band, t = (d - d/2) / band, with
        // dw/dpsi = -4 t (1 - t^2) / band dd/dpsi and dd/dpsi = -R^2 a / d (a = phi_i - phi_h).
        double w = 1.0, w_slope = 0.0;
        if (d > radius) {
          const double t = (d - radius) / band, q = 1.0 - t * t;
          w = q * q;
          w_slope = 4.0 * t * q / band * (R * R * a / d);
        }
        feed->unknown.push_back(grid.Unknown(i, j));
        feed->conductance.push_back(w);
        feed->conductance_slope.push_back(w_slope);
        feed->supply_psi.push_back(supply_psi[h]);
        sum += w;
        sum_slope += w_slope;
      }
    }
    // Normalised: G_k = G w_k / S, dG_k = G (w'_k S - w_k S') / S^2.
    for (int e = first; e < feed->size(); ++e) {
      const double w = feed->conductance[e], w_slope = feed->conductance_slope[e];
      feed->conductance[e] = hole_conductance * w / sum;
      feed->conductance_slope[e] = hole_conductance * (w_slope * sum - w * sum_slope) / (sum * sum);
    }
  }
}

SupplyMap MarkSupplyNodes(const BearingGrid& grid, const std::vector<OilHole>& holes,
                          const std::vector<Groove>& grooves, const std::string& who) {
  SupplyMap map;
  map.feature.assign(grid.num_unknowns(), -1);
  const double half_length = 0.5 * grid.length();
  const double R = grid.radius();
  auto finite = [&](double v, const std::string& key) {
    EMB_THROW_IF(!std::isfinite(v), who << ": expected a finite " << key << ", got " << v);
  };
  auto positive = [&](double v, const std::string& key, const char* unit) {
    EMB_THROW_IF(!(std::isfinite(v) && v > 0.0),
                 who << ": expected a positive " << key << ", got " << v << " " << unit);
  };
  auto pressure = [&](double v, const std::string& key) {
    EMB_THROW_IF(!(std::isfinite(v) && v >= 0.0),
                 who << ": expected a supply pressure >= 0 Pa (gauge) for " << key << ", got " << v
                     << " Pa");
  };
  // Marks the interior nodes for which `inside(i, j)` holds; returns how many.
  auto mark = [&](int feature, const std::string& key, auto inside) {
    int count = 0;
    for (int i = 0; i < grid.num_circumferential(); ++i)
      for (int j = 1; j < grid.num_axial_intervals(); ++j) {
        if (!inside(i, j)) continue;
        const int k = grid.Unknown(i, j);
        const int other = map.feature[k];
        EMB_THROW_IF(other >= 0 && map.pressure[other] != map.pressure[feature],
                     who << ": " << key
                         << " overlaps another supply feature at a different "
                            "pressure (expected one supply pressure per node, got "
                         << map.pressure[other] << " Pa and " << map.pressure[feature]
                         << " Pa at phi = " << grid.angle(i) << " rad, z = " << grid.axial(j)
                         << " m)");
        map.feature[k] = feature;
        ++count;
      }
    return count;
  };

  for (size_t h = 0; h < holes.size(); ++h) {
    const OilHole& o = holes[h];
    const std::string key = "oil_holes[" + std::to_string(h) + "]";
    CheckHole(grid, o, key, who);
    map.pressure.push_back(o.supply_pressure);
    const double r2 = 0.25 * o.diameter * o.diameter * (1.0 + kBorderSlack);
    const int count = mark(static_cast<int>(h), key, [&](int i, int j) {
      const double s = R * WrapSigned(grid.angle(i) - o.angle);
      const double dz = grid.axial(j) - o.axial_position;
      return s * s + dz * dz <= r2;
    });
    EMB_THROW_IF(count == 0,
                 who << ": the grid is too coarse for " << key << " (diameter " << o.diameter
                     << " m): expected at least one interior node inside it, got none (node "
                        "spacing R dphi = "
                     << R * grid.dphi() << " m, dz = " << grid.dz() << " m)");
  }
  for (size_t g = 0; g < grooves.size(); ++g) {
    const Groove& o = grooves[g];
    const std::string key = "grooves[" + std::to_string(g) + "]";
    finite(o.axial_position, key + ".axial_position");
    finite(o.start_angle, key + ".start_angle");
    positive(o.width, key + ".width", "m");
    EMB_THROW_IF(!(std::isfinite(o.angular_extent) && o.angular_extent > 0.0 &&
                   o.angular_extent <= kTwoPi * (1 + kBorderSlack)),
                 who << ": expected " << key << ".angular_extent in (0, 2 pi] rad, got "
                     << o.angular_extent);
    pressure(o.supply_pressure, key + ".supply_pressure");
    EMB_THROW_IF(std::abs(o.axial_position) + 0.5 * o.width > half_length * (1 + kBorderSlack),
                 who << ": " << key
                     << " reaches outside the bearing: expected |axial_position| "
                        "+ width/2 <= L/2 = "
                     << half_length << " m, got " << std::abs(o.axial_position) + 0.5 * o.width
                     << " m");
    const int feature = static_cast<int>(holes.size() + g);
    map.pressure.push_back(o.supply_pressure);
    const double half_width = 0.5 * o.width + kBorderSlack * grid.dz();
    const bool full = o.angular_extent >= kTwoPi * (1 - kBorderSlack);
    const double extent = o.angular_extent + kBorderSlack * grid.dphi();
    const int count = mark(feature, key, [&](int i, int j) {
      if (std::abs(grid.axial(j) - o.axial_position) > half_width) return false;
      return full || WrapPositive(grid.angle(i) - o.start_angle) <= extent ||
             WrapPositive(grid.angle(i) - o.start_angle) >= kTwoPi - kBorderSlack * grid.dphi();
    });
    EMB_THROW_IF(count == 0,
                 who << ": the grid is too coarse for " << key << " (width " << o.width
                     << " m, extent " << o.angular_extent
                     << " rad): expected at least one interior node inside it, got none (node "
                        "spacing dz = "
                     << grid.dz() << " m, R dphi = " << R * grid.dphi() << " m)");
  }
  for (int k = 0; k < grid.num_unknowns(); ++k)
    if (map.feature[k] >= 0) map.nodes.push_back(k);
  return map;
}

}  // namespace emb::tribology
