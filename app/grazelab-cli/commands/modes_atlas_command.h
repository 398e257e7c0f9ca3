// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <functional>
#include <optional>
#include <stop_token>
#include <string>
#include <variant>
#include <vector>

#include "commands/periodic_orbit.h"
#include "commands/simulation.h"
#include "core/model/two_mass_form.h"
#include "core/orbits/chain_atlas.h"
#include "core/orbits/modes_atlas.h"
#include "io/json_value.h"

// `modes` as a typed command (as `simulate`, `orbit` and `family` are): the atlas of a chain's
// periodic impacting families, which the command line writes as files (PREFIX.json, one CSV and
// .npy per family, a picture) and the Python module hands over as values and arrays, reading no
// file back. The note's 1:2 chain keeps its two-mass atlas (core/orbits/modes_atlas.h); every
// other chain, of any N, takes the atlas of any chain (core/orbits/chain_atlas.h). No Qt.
namespace grazelab::cli {

class PreparedMassChain;

struct ModesRequest {
  int maxImpacts = core::kDefaultAtlasMaxImpacts;  ///< 1 to 64
  /// the energies followed, "A:B" as decimal text read in the precision that runs; none: the
  /// default range (1/100 to 10000 times the grazing end's energy)
  std::optional<std::string> energyRange;
  PrecisionChoice precision = PrecisionChoice::Auto;  ///< auto: double
};

enum class ModesStatus {
  Computed,
  Refused,      ///< `problem` says why
  Interrupted,  ///< `stop` was requested: nothing computed
};

/// The atlas in precision S with the chain's form it was computed on and the energy range.
template <typename S>
struct AtlasIn {
  core::TwoMassForm<S> chain;
  core::ModesAtlas<S> atlas;
  S low = 0, high = 0;
};

/// The atlas of a chain of N masses in precision S, with the chain and the energy range.
template <typename S>
struct ChainAtlasIn {
  core::BasicMassChain<S> chain;
  S commonPeriod = 0;  ///< 0: the frequencies are not commensurate
  core::ChainAtlas<S> atlas;
  S low = 0, high = 0;
  bool oneFamily = false;  ///< `family --impacts`: one family followed from an orbit, no 1IPP scan
};

struct ModesOutcome {
  ModesStatus status = ModesStatus::Refused;
  std::string problem;
  core::Precision precision = core::Precision::Double;
  int maxImpacts = 0;
  std::variant<std::monostate, AtlasIn<double>, AtlasIn<long double>, AtlasIn<core::Quad>, ChainAtlasIn<double>,
               ChainAtlasIn<long double>, ChainAtlasIn<core::Quad>>
      atlas;
};

/// The atlas `request` asks for on `chain`: the two-mass atlas for a two-mass chain in 1:2
/// resonance stopped on its second mass (the note's form), the atlas of any chain otherwise.
/// `progress` hears each family followed (from this thread).
ModesOutcome modesAtlas(const PreparedMassChain& chain, const ModesRequest& request,
                        const std::function<void(double, const std::string&)>& progress = {},
                        std::stop_token stop = {});

/// `family --impacts K`: the family of the kIPP orbit Newton finds from `start` (its impacts,
/// guess, fixed energy or period, precision) on the return map of any chain, followed both ways in
/// energy to its ends (core::followChainFamily), given as an atlas of that one family (born_at
/// given-orbit, no branch switched at).
struct ImpactsFamilyRequest {
  OrbitRequest start;
  /// "A:B" as for ModesRequest; none: 1e-4 to 1e4 times the energy of the orbit found
  std::optional<std::string> energyRange;
  int maxOrbits = 2000;  ///< the most orbits followed each way
};
ModesOutcome impactsFamily(const PreparedMassChain& chain, const ImpactsFamilyRequest& request,
                           std::stop_token stop = {});

/// The columns of a two-mass atlas's family table: energy, period, omega, trace, stability (0..3),
/// u1, v1, min_impact_speed, min_clearance (NaN: no flight turns back below the stop).
extern const std::vector<std::string> kModesColumns;
/// The columns of `outcome`'s family tables: kModesColumns for the two-mass atlas; for a chain of
/// N masses energy, period, omega, class (0..4), min_impact_speed, u1..uN, v1..vN and, for each
/// of the 2N - 2 nontrivial multipliers, muK_re, muK_im, muK_krein.
std::vector<std::string> modesColumns(const ModesOutcome& outcome);

/// The rows of family `index` (in the atlas's order), row-major over modesColumns, in double.
std::vector<double> modesTable(const ModesOutcome& outcome, std::size_t index);
std::size_t modesFamilyCount(const ModesOutcome& outcome);

/// The atlas's JSON document; with `base` (the files' prefix, its file name) each family names
/// its CSV file (BASE-family-N.csv).
JsonValue modesDocument(const ModesOutcome& outcome, const std::optional<std::string>& base);

}  // namespace grazelab::cli
