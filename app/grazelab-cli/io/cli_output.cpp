// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "io/cli_output.h"

#include <cmath>
#include <iterator>
#include <type_traits>

#include "core/model/linear_modes.h"
#include "core/orbits/special_orbits.h"
#include "io/document_values.h"
#include "io/json_value.h"

namespace grazelab::cli {

std::string jsonQuoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

template <typename S>
JsonValue modelValue(const ModelInput<S>& input, const std::string& precision) {
  return values::model<JsonValue>(input, precision);
}

void emitDocument(const Io& io, JsonValue document) {
  const std::string text = fieldPerLine(document, "  ", "") + "\n";
  std::fwrite(text.data(), 1, text.size(), io.out);
}

JsonValue trustValue(const core::Trust& trust) { return values::trust<JsonValue>(trust); }

template <typename S>
JsonValue infoValue(const ModelInput<S>& model) {
  return JsonValue::object({{"model", modelValue(model, std::string(core::toString(core::precisionOf<S>())))}});
}

template <typename S>
JsonValue massChainValue(const core::BasicMassChain<S>& chain, const S& period) {
  return values::massChain<JsonValue>(chain, period);
}
template JsonValue massChainValue<double>(const core::BasicMassChain<double>&, const double&);
template JsonValue massChainValue<long double>(const core::BasicMassChain<long double>&, const long double&);
template JsonValue massChainValue<core::Quad>(const core::BasicMassChain<core::Quad>&, const core::Quad&);

JsonValue massChainInfoValue(const core::MassChain& chain, const std::optional<core::DesignChoice>& design) {
  using V = JsonValue;
  const core::ChainModes modes = core::chainModes(chain);
  const core::SpectrumRatios ratios = core::detectRatios(modes.omega);
  const auto numbers = [](const auto& values) {
    std::vector<V> items;
    for (double value : values) items.push_back(V::number(value));
    return V::array(std::move(items));
  };
  std::vector<V> modeList;
  for (int j = 0; j < chain.size(); ++j) {
    std::vector<double> shape(modes.P.col(j).data(), modes.P.col(j).data() + chain.size());
    modeList.push_back(V::object(
        {{"mode", V::of(std::int64_t(j + 1))},
         {"omega", V::number(modes.omega(j))},
         {"period", V::number(2 * M_PI / modes.omega(j))},
         {"shape", numbers(shape)},
         {"node_at_stop", V::of(bool(modes.nodeAtStop[std::size_t(j)]))},
         {"harmonic", ratios.commensurate ? V::of(std::int64_t(ratios.harmonics[std::size_t(j)])) : V::null()}}));
  }
  std::vector<V> harmonics;
  for (int h : ratios.harmonics) harmonics.push_back(V::of(std::int64_t(h)));
  V designValue = V::null();
  if (design) {
    std::vector<V> asked;
    for (int h : design->harmonics) asked.push_back(V::of(std::int64_t(h)));
    std::vector<V> found;
    for (const core::ChainDesign& each : design->designs.designs) {
      found.push_back(V::object({{"springs", numbers(each.springs)},
                                 {"omega0", V::number(each.omega0)},
                                 {"T", V::number(2 * M_PI / each.omega0)},
                                 {"ratio_error", V::number(each.ratioError)}}));
    }
    designValue = V::object(
        {{"frequencies", V::array(std::move(asked))},
         {"branch", V::of(std::int64_t(design->number))},
         {"designs", V::array(std::move(found))},
         {"solutions", V::of(std::int64_t(design->designs.paths))},
         {"complex_or_not_positive", V::of(std::int64_t(design->designs.complexEnds))},
         {"at_infinity", V::of(std::int64_t(design->designs.infiniteEnds))},
         {"method", V::of(std::string("every solution of the design equations followed from a start system with ")
                              .append(chain.rightSpring > 0 ? "2 N! roots (a right wall: quadratic in 1/k1)" : "N! roots")
                              .append(" (homotopy); the positive ones polished in binary128 and checked "
                                      "against the designed chain's own spectrum; ordered by k2, largest first"))}});
  }
  return V::object(
      {{"chain", V::object({{"masses", numbers(chain.masses)},
                            {"springs", numbers(chain.springs)},
                            {"right_spring", chain.rightSpring > 0 ? V::number(chain.rightSpring) : V::null()},
                            {"stop_mass", V::of(std::int64_t(chain.stopped()))},
                            {"gap", V::number(chain.gap)}})},
       {"modes", V::array(std::move(modeList))},
       {"ratios", V::object({{"commensurate", V::of(ratios.commensurate)},
                             {"harmonics", V::array(std::move(harmonics))},
                             {"omega0", V::number(ratios.omega0)},
                             {"T", V::number(2 * M_PI / ratios.omega0)},
                             {"detuning", V::number(ratios.detuning)}})},
       {"mode_labelling", V::of("mode 1 is the fastest; shapes are M-orthonormal, the stopped "
                                "mass's entry > 0; harmonics n_j with omega_j = n_j omega0, "
                                "T = 2 pi / omega0 (when not commensurate: the nearest small "
                                "ratios and how far)")},
       {"design", std::move(designValue)},
       {"precision", V::of("double")}});
}

template JsonValue infoValue<double>(const ModelInput<double>&);
template JsonValue infoValue<long double>(const ModelInput<long double>&);
template JsonValue infoValue<core::Quad>(const ModelInput<core::Quad>&);
template JsonValue modelValue<double>(const ModelInput<double>&, const std::string&);
template JsonValue modelValue<long double>(const ModelInput<long double>&, const std::string&);
template JsonValue modelValue<core::Quad>(const ModelInput<core::Quad>&, const std::string&);

}  // namespace grazelab::cli
