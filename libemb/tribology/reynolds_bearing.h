#pragma once
/// @file
/// A finite-width journal bearing solved by the Reynolds equation (notation.h): the immutable
/// model. Its parameters are checked once here; evaluations (film_solver.h for the quasi-
/// static and time-stepped film, film_dae.h for the film as DAE states) only read it.
///
/// Cavitation models, all on the one grid and unknown (notation.h, T5):
///   kMassConserving  JFO (T2, T3): theta is transported by the Couette flow and stored in
///                    the film; rupture and reformation conserve mass. The only model with
///                    history (the fill fraction of the cavitated zone).
///   kReynolds        Swift-Stieber: p >= 0 and the full-film residual >= 0 where p = 0 (a
///                    complementarity problem); no theta transport, not mass-conserving.
///   kHalfSommerfeld  Guembel: the full film solved, sub-ambient pressures dropped from the
///                    loads (not mass-conserving; Ocvirk's closed form uses it).
///   kFullSommerfeld  no cavitation: sub-ambient pressures kept.
/// The complementarity (T3) is solved by semismooth Newton on the Elrod-Adams switch (the
/// default; finite termination when the active set settles) or by Fischer-Burmeister-Newton
/// (Woloszynski et al., Tribol. Lett. 2015); the measurements behind the default (iterations
/// and time, cold and warm, the same forces) are the solvers' table of benchmarks/README.md,
/// "Finite-width Reynolds bearing".

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "libemb/tribology/asperity_contact.h"
#include "libemb/tribology/bearing_grid.h"
#include "libemb/tribology/lubricant.h"
#include "libemb/tribology/supply_features.h"

namespace emb::tribology {

enum class CavitationModel { kMassConserving, kReynolds, kHalfSommerfeld, kFullSommerfeld };
enum class ComplementaritySolver { kElrodAdamsSwitch, kFischerBurmeister };

struct ReynoldsBearingParameters {
  double radius{0.0};     ///< R, journal radius [m]
  double length{0.0};     ///< L, bearing length [m]
  double clearance{0.0};  ///< c, radial clearance [m], < R
  GridSize grid;
  LubricantParameters lubricant;
  std::vector<OilHole> oil_holes;
  std::vector<Groove> grooves;
  /// Oil holes in the journal, turning with it (supply_features.h: they feed through a
  /// conductance).
  std::vector<JournalOilHole> journal_oil_holes;
  /// kappa: a journal hole's feed conductance over pi c^3 / (6 mu_0) (supply_features.h).
  /// 1e4 puts the loads within 0.1 % of the limit kappa -> infinity (JournalFeed.LoadsConvergeAsTheFeedConductanceGrows).
  double journal_feed_ratio{1e4};
  CavitationModel cavitation{CavitationModel::kMassConserving};
  ComplementaritySolver complementarity{ComplementaritySolver::kElrodAdamsSwitch};
  /// Greenwood-Tripp asperity contact; without it a film h <= 0 anywhere is a failed
  /// evaluation (FilmStatus::kJournalTouchesShell).
  std::optional<AsperityContactParameters> asperity_contact;
  /// With contact, the hydrodynamic film is max(h, film_floor * sigma) so that the Reynolds
  /// terms stay finite when the journal goes through its nominal clearance [-].
  double film_floor{0.1};
  /// gamma_b: static tilt of the bore axis in the shell frame (slopes, T1) [rad].
  Eigen::Vector2d bore_tilt{0.0, 0.0};
  /// p_ref: pressure of u = 1 (T5) [Pa]; scales the unknowns (conditioning, DAE error
  /// weights) and, with switch_width > 0, the smoothed band's pressure p_ref w.
  double pressure_scale{1e6};
  /// K: the lubricant's bulk modulus [Pa], for the film as DAE states only (film_dae.h: the
  /// full film's compressibility; 1.5 GPa, a mineral oil near ambient pressure).
  double bulk_modulus{1.5e9};
  /// w: half-width of the smoothed JFO switch in u (T5; mass-conserving only). 0 is the exact
  /// kink: Psi = p_ref max(u, 0), theta = 1 + min(u, 0). With w > 0 the two blend as a
  /// quadratic over |u| < w (C1: the implicit integrator's Newton iteration sees continuous
  /// slopes where film nodes rupture and reform); outside the band both are exact, and
  /// inside the pressure is at most p_ref w and 1 - theta at most w.
  double switch_width{0.0};
  /// Newton iterations allowed per evaluation (each one factorisation).
  int max_iterations{50};
};

class ReynoldsBearing {
 public:
  /// @param name names the bearing in every message.
  /// @throws InputError ("bearing '<name>': expected X, got Y") for R, L, c not positive and
  ///   finite, c >= R, a grid with N < 8 or Nz < 2, lubricant and supply-feature errors
  ///   (lubricant.h, supply_features.h), |gamma_b| L/2 >= c (the bore's own misalignment
  ///   takes up the clearance at an edge), a non-positive pressure scale, film floor or
  ///   iteration limit, and Step/DAE use with a model other than kMassConserving (there).
  ReynoldsBearing(std::string name, const ReynoldsBearingParameters& p);

  const std::string& name() const { return name_; }
  /// "bearing '<name>'", the prefix of every message.
  const std::string& who() const { return who_; }
  const ReynoldsBearingParameters& parameters() const { return p_; }
  const BearingGrid& grid() const { return grid_; }
  const Lubricant& lubricant() const { return lubricant_; }
  const SupplyMap& supply() const { return supply_; }
  const std::optional<AsperityContact>& contact() const { return contact_; }
  /// The message of a film whose reduced pressure reached the pressure-viscosity law's limit
  /// (FilmStatus::kBeyondViscosityLaw): names the bearing and the limit, and says what helps.
  std::string BeyondViscosityLawMessage() const;
  /// Unknown u of a supply node at pressure p: Psi(p) / p_ref (>= 0: flooded).
  double SupplyUnknown(int k) const { return supply_u_[supply_.feature[k]]; }
  bool has_journal_holes() const { return !p_.journal_oil_holes.empty(); }
  /// kappa g_ref [m^3/(Pa s)] and the journal holes' reduced supply pressures [Pa].
  double journal_hole_conductance() const { return journal_conductance_; }
  const std::vector<double>& journal_supply_psi() const { return journal_psi_; }
  bool is_supply(int k) const { return supply_.feature[k] >= 0; }
  int num_unknowns() const { return grid_.num_unknowns(); }

 private:
  std::string name_, who_;
  ReynoldsBearingParameters p_;
  BearingGrid grid_;
  Lubricant lubricant_;
  SupplyMap supply_;
  std::vector<double> supply_u_;
  double journal_conductance_{0.0};
  std::vector<double> journal_psi_;
  std::optional<AsperityContact> contact_;
};

}  // namespace emb::tribology
