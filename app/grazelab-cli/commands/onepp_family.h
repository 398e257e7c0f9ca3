// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <stop_token>
#include <string>
#include <variant>
#include <vector>

#include "commands/simulation.h"
#include "core/orbits/chain_bifurcations.h"
#include "io/json_value.h"

// `family --onepp` as a typed command (as `simulate` and `orbit` are): the one-impact-per-period
// family of any chain as a table and its description, which the command line writes as files
// (PREFIX.csv, .npy, .json, and a picture) and the Python module hands over as an array and
// values, reading no file back. No Qt.
namespace grazelab::cli {

class PreparedMassChain;

struct FamilyRequest {
  std::int64_t count = 2000;  ///< periods in (0, T_max)
  /// the precision of the note's chain's stability (its rows are computed in binary128 and
  /// rounded once); a chain of N masses is computed in double
  PrecisionChoice precision = PrecisionChoice::Auto;
};

enum class FamilyStatus {
  Computed,
  Refused,      ///< `problem` says why
  Interrupted,  ///< `stop` was requested: nothing computed
};

/// A point of the frequency-energy picture.
struct FamilyPoint {
  double energy = 0;
  double omega = 0;
  bool admissible = false;
};

/// What the note's chain's family is beside its table: its model, lambda*, its grazing end (T,
/// omega, V, u1, energy) and its bifurcations (each in the stability's precision, as written).
struct NotesFamily {
  double m1 = 0, m2 = 0, k1 = 0, k2 = 0, gap = 0, T2 = 0;
  double lambdaStar = 0;
  double endT = 0, endV = 0, endU1 = 0, endEnergy = 0;
  std::string stabilityPrecision;
  JsonValue bifurcations;
};

/// What a chain of N masses's family is beside its table: the chain, T_max and the grazing limit
/// of Theorem 2.1 (its weights, GLO data and energy).
struct ChainFamily {
  JsonValue chain;
  double tMax = 0;
  bool commensurate = false;
  std::vector<double> weights;
  std::optional<std::vector<double>> gloU;  ///< none when the weights give no GLO start
  double gloEnergy = 0;
  /// where its stability changes between its rows, located (core/orbits/chain_bifurcations.h)
  core::ChainBifurcations<double> bifurcations;
};

struct FamilyOutcome {
  FamilyStatus status = FamilyStatus::Refused;
  std::string problem;
  std::int64_t count = 0;
  std::vector<std::string> columns;
  std::vector<double> table;  ///< rows x columns, row-major (the .npy's layout); NaN: no value
  std::int64_t admissible = 0;
  std::variant<NotesFamily, ChainFamily> of;
  /// the frequency-energy picture: the family's points with data, its grazing end, its title
  std::vector<FamilyPoint> points;
  FamilyPoint end;
  std::string title;
  std::size_t rows() const { return columns.empty() ? 0 : table.size() / columns.size(); }
};

/// The most periods a family is computed at: 10 000 000 for the note's chain, 1 000 000 for N masses.
std::int64_t familyMaxCount(bool notesChain);
/// Why a chain of N masses' family is refused in long double or binary128.
inline constexpr const char* kFamilyOfNMassesInDouble =
    "--precision: the family of a chain of N masses is computed in double for now (give double or auto)";

/// Why `request` is refused whatever the chain's numbers (a count out of range, a precision a
/// chain of N masses is not computed in): before the chain is read or designed. `notesChain`: the
/// note's chain, however written.
std::optional<std::string> familyRequestRefusal(const FamilyRequest& request, bool notesChain);
/// Why `chain` has no family to compute for `request` (familyRequestRefusal, or a two-mass chain
/// off the 1:2 design), before any of it is computed; none when it has one.
std::optional<std::string> familyRefusal(const PreparedMassChain& chain, const FamilyRequest& request);

/// The 1IPP family of `chain`: the note's chain (its 1:2 design) by Theorem 2.1's closed form with
/// each admissible orbit's stability and the family's bifurcations in the precision asked for; a
/// chain of N masses by core/orbits/chain_onepp.h with its grazing limit. `progress` hears the
/// fraction done and where it is (from this thread).
FamilyOutcome onePeriodicFamily(const PreparedMassChain& chain, const FamilyRequest& request,
                                const std::function<void(double, const std::string&)>& progress = {},
                                std::stop_token stop = {});

/// The family's JSON document; `files` (the csv and npy names, under "files") when it was
/// written to files.
JsonValue familyDocument(const FamilyOutcome& outcome, const std::optional<std::string>& files);

}  // namespace grazelab::cli
