// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "io/prepared_chain.h"

#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace grazelab::cli {

Parsed<std::shared_ptr<const PreparedMassChain>> PreparedMassChain::make(const OptionValues& options,
                                                                         std::stop_token stop) {
  // the note's chain, written with the note's options or as --masses m1,m2 --frequencies 2:1:
  // read in each precision by the note's own reader (its 1:2 design in closed form there, no
  // design search; a ratio beyond double's range left to the precisions that hold it)
  const bool notesOptions = !options.isSet("masses");
  if (notesOptions || writesTheNotesChain(options)) {
    // (a number beyond double's range, --gap 1e-400, is left to the precisions that hold it too)
    const Parsed<ModelInput<double>> model = parseModel<double>(options);
    if (!model.value && !model.precisionBound && !parseModel<core::Quad>(options).value) {
      return {std::nullopt, model.error};
    }
    // (an option not given reads as its default there too)
    std::vector<GivenOption> own;
    for (const char* name : {"masses", "springs", "gap", "frequencies", "design-branch", "m1", "m2", "k1", "k2", "branch"}) {
      if (options.isSet(name)) own.push_back({name, options.value(name), {}, false});
    }
    return {std::shared_ptr<const PreparedMassChain>(new PreparedMassChain(std::move(own), MassChainInput{}, true)), {}};
  }
  Parsed<MassChainInput> input = parseMassChain(options, std::move(stop));
  if (!input.value) return {std::nullopt, input.error};
  // the chain's options kept as text (a command line's options live in its parser, which goes)
  std::vector<GivenOption> own;
  for (const char* name : {"masses", "springs", "right-spring", "stop-mass", "gap", "frequencies", "design-branch"}) {
    if (options.isSet(name)) own.push_back({name, options.value(name), {}, false});
  }
  return {std::shared_ptr<const PreparedMassChain>(new PreparedMassChain(std::move(own), std::move(*input.value), false)),
          {}};
}

PreparedMassChain::PreparedMassChain(std::vector<GivenOption> given, MassChainInput input, bool notesReader)
    : m_given(given),
      m_options(std::move(given)),
      m_input(std::move(input)),
      m_notes(notesReader),
      m_notesReader(notesReader) {}

template <typename S>
PreparedMassChain::InPrecision<S>& PreparedMassChain::in() const {
  if constexpr (std::is_same_v<S, double>) return m_double;
  else if constexpr (std::is_same_v<S, long double>) return m_long;
  else return m_quad;
}

template <typename S>
const Parsed<core::BasicReadyChain<S>>& PreparedMassChain::ready() const {
  InPrecision<S>& slot = in<S>();
  std::call_once(slot.readyOnce, [&] {
    if (m_notesReader) {
      Parsed<ModelInput<S>> model = parseModel<S>(m_options);
      if (model.value) {
        // a design by its closed form; springs given (--k2) as any chain's springs are read
        // (a 1:2 design's to rounding runs as that design), so that both writings are one chain
        const core::BasicModel<S>& m = model.value->model;
        slot.ready.value = m.design ? core::readyChain(m)
                                    : core::readyChain(core::BasicMassChain<S>{{m.m1, m.m2}, {m.k1, m.k2}, S(0), 2, m.gap});
      }
      slot.ready.error = model.error;
      slot.ready.precisionBound = model.precisionBound;
      return;
    }
    Parsed<core::BasicMassChain<S>> numbers = massChainIn<S>(m_options, m_input);
    if (numbers.value) slot.ready.value = core::readyChain(*numbers.value);
    slot.ready.error = numbers.error;
  });
  return slot.ready;
}

template <typename S>
const Parsed<ModelInput<S>>& PreparedMassChain::twoMassForm() const {
  InPrecision<S>& slot = in<S>();
  std::call_once(slot.formOnce, [&] { slot.form = parseModel<S>(m_options); });
  return slot.form;
}

template <typename S>
const core::ChainShadow<S>& PreparedMassChain::shadow() const {
  InPrecision<S>& slot = in<S>();
  std::call_once(slot.shadowOnce, [&] {
    // the chain read one precision up (binary128's own, scaled): the input's rounding counts
    using H = core::ShadowScalar<S>;
    const Parsed<core::BasicReadyChain<H>>& up = ready<H>();
    if (!up.value) {
      slot.shadow.problem = up.error.toStdString();
      return;
    }
    // the numbers as read: those a decimal does not hold exactly are nudged in binary128
    slot.shadow = core::chainShadow<S>(*up.value, m_notesReader ? exactParameters<H>(m_options)
                                                                : chainExactParameters<H>(m_options));
  });
  return slot.shadow;
}

#define GRAZELAB_INSTANTIATE(S)                                                               \
  template const Parsed<core::BasicReadyChain<S>>& PreparedMassChain::ready<S>() const; \
  template const Parsed<ModelInput<S>>& PreparedMassChain::twoMassForm<S>() const;        \
  template const core::ChainShadow<S>& PreparedMassChain::shadow<S>() const;
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(core::Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::cli
