// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "io/cli_output.h"

#include <cmath>
#include <iterator>
#include <type_traits>

#include "core/model/linear_modes.h"
#include "core/orbits/special_orbits.h"
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

namespace {

template <typename S>
std::string number(const S& value) {
  return jsonNumber(value);
}

std::string quoted(const std::string& text) { return jsonQuoted(text); }

// a flat JSON object from (key, already formatted value) pairs
std::string object(std::initializer_list<std::pair<const char*, std::string>> fields) {
  std::string out = "{";
  bool first = true;
  for (const auto& [key, value] : fields) {
    if (!first) out += ", ";
    first = false;
    out += quoted(key) + ": " + value;
  }
  return out + "}";
}

template <typename S>
JsonValue stateValue(const S& t, const core::BasicState<S>& state) {
  return JsonValue::object({{"t", JsonValue::number(t)},
                            {"u1", JsonValue::number(state.u1)},
                            {"u2", JsonValue::number(state.u2)},
                            {"v1", JsonValue::number(state.v1)},
                            {"v2", JsonValue::number(state.v2)}});
}

template <typename S>
JsonValue modelValue(const ModelInput<S>& input, const std::string& precision) {
  const core::BasicModel<S>& model = input.model;
  const core::TwoMassForm<S>& chain = input.chain;
  const S omegaFast = chain.ratio * chain.omegaSlow;
  // M-normalised mode shapes: columns (rho_j, 1) / (sqrt(m1) sqrt(rho_j^2 + beta))
  using std::sqrt;
  S p[2][2];
  const S rho[2] = {chain.rhoFast, chain.rhoSlow};
  for (int j = 0; j < 2; ++j) {
    const S scale = S(1) / (sqrt(model.m1) * sqrt(rho[j] * rho[j] + chain.beta));
    p[0][j] = rho[j] * scale;
    p[1][j] = scale;
  }
  const std::string source =
      model.design ? "1:2 design, " + std::string(core::toString(*model.design)) + " branch"
                   : std::string("given");
  using V = JsonValue;
  return V::object(
      {{"m1", V::number(model.m1)},
       {"m2", V::number(model.m2)},
       {"k1", V::number(model.k1)},
       {"k2", V::number(model.k2)},
       {"gap", V::number(model.gap)},
       {"k2_source", V::of(source)},
       {"mass_ratio", V::number(chain.beta)},
       {"omega1", V::number(omegaFast)},
       {"omega2", V::number(chain.omegaSlow)},
       {"T1", V::number(S(core::twoPi<S>() / omegaFast))},
       {"T2", V::number(S(core::twoPi<S>() / chain.omegaSlow))},
       {"resonant", V::of(chain.resonant)},
       {"detuning", V::number(chain.detuning)},
       {"mode_labelling", V::of("mode 1 is the fast mode, mode 2 the slow one (omega1 = 2 omega2)")},
       {"P", V::array({V::array({V::number(p[0][0]), V::number(p[0][1])}),
                       V::array({V::number(p[1][0]), V::number(p[1][1])})})},
       {"precision", V::of(precision)},
       {"lambda_star", chain.resonant ? V::number(core::lambdaStar(chain)) : V::null()}});
}

// the model as the command line writes it: a field per line
template <typename S>
std::string modelJson(const ModelInput<S>& input, const std::string& precision) {
  return fieldPerLine(modelValue(input, precision), "    ", "  ");
}

template <typename S>
JsonValue initialValue(const RunInput<S>& run) {
  return JsonValue::object({{"description", JsonValue::of(run.initialDescription)},
                            {"state", stateValue(S(0), run.request.initial)}});
}

double contactsPerSecond(const core::Cost& cost) {
  return cost.wallSeconds > 0 ? double(cost.contacts) / cost.wallSeconds : 0;
}

template <typename S>
std::string eventJson(const core::BasicEvent<S>& event) {
  return object({{"t", number(event.t)},
                 {"type", quoted(std::string(core::toString(event.type)))},
                 {"u1", number(event.before.u1)},
                 {"u2", number(event.before.u2)},
                 {"v1_pre", number(event.before.v1)},
                 {"v2_pre", number(event.before.v2)},
                 {"v2_post", number(event.after.v2)}});
}


// `initialUsed`: the start of a run raised to a higher precision, in that precision's digits
// (the head, written before the raise, holds the lower one's); null when not raised
JsonValue precisionValue(const PrecisionReport& precision, JsonValue initialUsed) {
  std::vector<JsonValue> escalations;
  for (const std::string& line : precision.escalations) escalations.push_back(JsonValue::of(line));
  std::vector<JsonValue::Field> fields{{"requested", JsonValue::of(precision.requested)},
                                       {"used", JsonValue::of(precision.used)},
                                       {"escalations", JsonValue::array(std::move(escalations))}};
  if (initialUsed.kind != JsonValue::Kind::Null) fields.emplace_back("initial_state_used", std::move(initialUsed));
  return JsonValue::object(std::move(fields));
}

// the fields the end of a run adds to its document
template <typename S>
std::vector<JsonValue::Field> endValues(const RunInput<S>& run, const core::BasicResult<S>& result,
                                        bool interrupted, const core::Trust& trust,
                                        const PrecisionReport& precision) {
  using V = JsonValue;
  const core::Cost& cost = result.cost;
  // a run raised to this precision started from this precision's reading of the input: the
  // head holds the lower one's, so the start used is said again here
  V initialUsed = precision.escalations.empty() ? V::null() : stateValue(S(0), run.request.initial);
  std::vector<V::Field> fields;
  fields.emplace_back("final", stateValue(result.tFinal, result.final));
  fields.emplace_back("stop_reason", V::of(interrupted ? std::string("interrupted")
                                                       : std::string(core::toString(result.stop))));
  if (!result.message.empty()) fields.emplace_back("message", V::of(result.message));
  fields.emplace_back("contacts", V::object({{"total", V::of(std::int64_t(cost.contacts))},
                                             {"impacts", V::of(std::int64_t(cost.impacts))},
                                             {"grazings", V::of(std::int64_t(cost.grazings))},
                                             {"sticks", V::of(std::int64_t(cost.sticks))},
                                             {"undecided_touches", V::of(std::int64_t(cost.undecidedTouches))}}));
  fields.emplace_back("energy", V::object({{"initial", V::number(result.initialEnergy)},
                                           {"max_rel_drift", V::number(cost.maxRelEnergyDrift)},
                                           {"max_flight_error", V::number(cost.maxFlightEnergyError)}}));
  fields.emplace_back("accuracy", V::object({{"max_contact_residual", V::number(cost.maxContactResidual)}}));
  fields.emplace_back("trust", trustValue(trust));
  fields.emplace_back("precision", precisionValue(precision, std::move(initialUsed)));
  fields.emplace_back("timing", V::object({{"seconds", V::number(cost.wallSeconds)},
                                           {"contacts_per_second", V::number(contactsPerSecond(cost))}}));
  return fields;
}

// the end's fields as the command line writes them: one per line after `indent`
std::string endFields(const std::vector<JsonValue::Field>& fields, const std::string& indent) {
  std::string out;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    out += indent + quoted(std::string(fields[i].first.view())) + ": " + oneLine(fields[i].second);
    if (i + 1 < fields.size()) out += ",\n";
  }
  return out;
}

}  // namespace

void emitDocument(const Io& io, JsonValue document) {
  if (io.document) {
    *io.document = std::move(document);
    return;
  }
  const std::string text = fieldPerLine(document, "  ", "") + "\n";
  std::fwrite(text.data(), 1, text.size(), io.out);
}

JsonValue trustValue(const core::Trust& trust) {
  const bool estimated = trust.verdict != core::Verdict::Unchecked;
  auto estimate = [&](double value) { return estimated ? JsonValue::number(value) : JsonValue::null(); };
  return JsonValue::object(
      {{"estimated_state_error", estimate(trust.stateError)},
       {"estimated_time_error", estimate(trust.timeError)},
       {"horizon", estimate(trust.horizon)},
       {"horizon_method", estimated ? JsonValue::of(trust.horizonMethod) : JsonValue::null()},
       {"verdict", JsonValue::of(std::string(core::toString(trust.verdict)))},
       {"reason", JsonValue::of(trust.reason)}});
}

template <typename S>
JsonValue infoValue(const ModelInput<S>& model) {
  return JsonValue::object({{"model", modelValue(model, std::string(core::toString(core::precisionOf<S>())))}});
}

template <typename S>
JsonValue massChainValue(const core::BasicMassChain<S>& chain, const S& period) {
  using V = JsonValue;
  const auto numbers = [](const std::vector<S>& values) {
    std::vector<V> items;
    for (const S& value : values) items.push_back(V::number(value));
    return V::array(std::move(items));
  };
  return V::object({{"masses", numbers(chain.masses)},
                    {"springs", numbers(chain.springs)},
                    {"right_spring", chain.rightSpring > 0 ? V::number(chain.rightSpring) : V::null()},
                    {"stop_mass", V::of(std::int64_t(chain.stopped()))},
                    {"gap", V::number(chain.gap)},
                    {"period", period > 0 ? V::number(period) : V::null()}});
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

template <typename S>
std::string infoJson(const ModelInput<S>& model) {
  return "{\n  \"model\": " + fieldPerLine(infoValue(model).fields[0].second, "    ", "  ") + "\n}\n";
}

template <typename S>
void RunWriter<S>::write(const std::string& text) {
  std::fwrite(text.data(), 1, text.size(), m_out);
}

template <typename S>
void RunWriter<S>::begin(const core::BasicResult<S>&) {
  if (m_document) {
    // the Python module: the document as values, its events in the table
    *m_document = JsonValue::object({{"model", modelValue(m_run.model, m_precision)},
                                     {"initial", initialValue(m_run)},
                                     {"events", JsonValue::array({})}});
    m_document->fields.reserve(16);  // and end()'s, moved in without a reallocation
    return;
  }
  const std::string initial = oneLine(initialValue(m_run));
  switch (m_run.format) {
    case Format::Json:
      write("{\n  \"model\": " + modelJson(m_run.model, m_precision) + ",\n  \"initial\": " + initial +
            ",\n  \"events\": [");
      break;
    case Format::JsonLines: {
      std::string model = modelJson(m_run.model, m_precision);
      std::string flat;
      for (char c : model) {
        if (c != '\n') flat += c;
      }
      write("{\"record\": \"run\", \"model\": " + flat + ", \"initial\": " + initial + "}\n");
      break;
    }
    case Format::Csv:
      write("t,type,u1,u2,v1_pre,v2_pre,v2_post\n");
      break;
    case Format::Summary:
      break;
  }
}

namespace {

// An event into the table; in long double or binary128 also as the decimal text the command line
// writes (the events a run of --precision auto wrote in double before its raise get theirs then).
template <typename S>
void appendEvent(EventTable& table, const core::BasicEvent<S>& event) {
  if (table.discard) return;
  if (table.rows.size() >= table.maxRows) {
    if (!table.full && table.whenFull) table.whenFull();
    table.full = true;
    return;
  }
  if (table.rows.empty()) table.rows.reserve(64);  // (a short run grows it once at most)
  EventRow row{};
  row.t = core::toDouble(event.t);
  const std::string_view type = core::toString(event.type);
  for (std::size_t i = 0; i < type.size() && i < std::size(row.type); ++i) row.type[i] = char32_t(type[i]);
  row.u1 = core::toDouble(event.before.u1);
  row.u2 = core::toDouble(event.before.u2);
  row.v1Pre = core::toDouble(event.before.v1);
  row.v2Pre = core::toDouble(event.before.v2);
  row.v2Post = core::toDouble(event.after.v2);
  if constexpr (!std::is_same_v<S, double>) {
    for (std::size_t i = table.decimals.size() / 6; i < table.rows.size(); ++i) {
      const EventRow& earlier = table.rows[i];
      for (double value : {earlier.t, earlier.u1, earlier.u2, earlier.v1Pre, earlier.v2Pre, earlier.v2Post}) {
        table.decimals.push_back(number(value));
      }
    }
    for (const S* value : {&event.t, &event.before.u1, &event.before.u2, &event.before.v1,
                           &event.before.v2, &event.after.v2}) {
      table.decimals.push_back(number(*value));
    }
  }
  table.rows.push_back(row);
}

}  // namespace

template <typename S>
void RunWriter<S>::event(const core::BasicEvent<S>& event) {
  if (m_table) {
    appendEvent(*m_table, event);
    ++m_events;
    return;
  }
  switch (m_run.format) {
    case Format::Json:
      write((m_events == 0 ? "\n    " : ",\n    ") + eventJson(event));
      break;
    case Format::JsonLines: {
      std::string line = eventJson(event);
      line.insert(1, "\"record\": \"event\", ");
      write(line + "\n");
      break;
    }
    case Format::Csv:
      write(number(event.t) + ',' + std::string(core::toString(event.type)) + ',' +
            number(event.before.u1) + ',' + number(event.before.u2) + ',' +
            number(event.before.v1) + ',' + number(event.before.v2) + ',' +
            number(event.after.v2) + '\n');
      break;
    case Format::Summary:
      break;
  }
  ++m_events;
}

template <typename S>
void RunWriter<S>::end(const core::BasicResult<S>& result, bool interrupted,
                       const core::Trust& trust, const PrecisionReport& precision) {
  std::vector<JsonValue::Field> fields = endValues(m_run, result, interrupted, trust, precision);
  const bool sampled = m_run.request.needs.samples.wanted();
  if (sampled) fields.emplace_back("samples_truncated", JsonValue::of(result.samplesTruncated));
  if (m_document) {
    for (JsonValue::Field& field : fields) m_document->fields.push_back(std::move(field));
    if (sampled && m_samples) *m_samples = result.samples;
    return;
  }
  // the samples as columns, written as they are read (millions of them: no tree)
  const auto samplesField = [&](const std::string& indent) {
    if (!sampled) return std::string();
    std::string out = ",\n" + indent + "\"samples\": {";
    const char* names[] = {"t", "u1", "u2", "v1", "v2"};
    for (int column = 0; column < 5; ++column) {
      out += std::string(column ? ", " : "") + "\"" + names[column] + "\": [";
      for (std::size_t i = 0; i < result.samples.size(); ++i) {
        const core::Sample& sample = result.samples[i];
        const double value = column == 0 ? sample.t : column == 1 ? sample.state.u1
                             : column == 2 ? sample.state.u2 : column == 3 ? sample.state.v1
                                                                             : sample.state.v2;
        if (i > 0) out += ", ";
        out += jsonNumber(value);
      }
      out += "]";
    }
    return out + "}";
  };
  const bool initialUsed = !precision.escalations.empty();
  switch (m_run.format) {
    case Format::Json:
      write((m_events == 0 || m_table ? "],\n" : "\n  ],\n") + endFields(fields, "  ") +
            samplesField("  ") + "\n}\n");
      break;
    case Format::JsonLines: {
      std::string line = endFields(fields, "") + samplesField("");
      std::string flat;
      for (char c : line) flat += c == '\n' ? ' ' : c;
      write("{\"record\": \"end\", " + flat + "}\n");
      break;
    }
    case Format::Csv:
      break;
    case Format::Summary: {
      const core::Cost& cost = result.cost;
      const core::TwoMassForm<S>& chain = m_run.model.chain;
      const core::BasicModel<S>& model = m_run.model.model;
      std::string text;
      text += "start          " + m_run.initialDescription + "\n";
      text += "chain          m1=" + number(model.m1) + " m2=" + number(model.m2) + " k1=" +
              number(model.k1) + " k2=" + number(model.k2) + " gap=" + number(model.gap) + " (" +
              (chain.resonant ? "1:2 resonant" : "detuned by w1/w2 - 2 = " + number(chain.detuning)) +
              "; T2=" + number(S(core::twoPi<S>() / chain.omegaSlow)) + ")\n";
      text += "contacts       " + std::to_string(cost.contacts) + " (impacts " +
              std::to_string(cost.impacts) + ", grazings " + std::to_string(cost.grazings) +
              ", sticks " + std::to_string(cost.sticks) + ")\n";
      text += "stopped        " +
              (interrupted ? std::string("interrupted") : std::string(core::toString(result.stop))) +
              " at t = " + number(result.tFinal) +
              (result.message.empty() ? std::string() : " (" + result.message + ")") + "\n";
      char line[160];
      std::snprintf(line, sizeof line, "wall time      %.4g s (%.4g contacts/s)\n",
                    cost.wallSeconds, contactsPerSecond(cost));
      text += line;
      std::snprintf(line, sizeof line,
                    "energy drift   %.3g (max relative, at contacts; one flight: %.3g)\n",
                    cost.maxRelEnergyDrift, cost.maxFlightEnergyError);
      text += line;
      std::snprintf(line, sizeof line, "|u2 - gap|     %.3g (max at contacts)\n",
                    cost.maxContactResidual);
      text += line;
      text += "precision      " + precision.used +
              (precision.requested == "auto" ? " (auto)" : std::string()) + "\n";
      for (const std::string& line : precision.escalations) {
        text += "               raised: " + line + "\n";
      }
      if (initialUsed) {
        const core::BasicState<S>& x = m_run.request.initial;
        text += "start used     u1=" + number(x.u1) + " u2=" + number(x.u2) + " v1=" + number(x.v1) +
                " v2=" + number(x.v2) + " (in " + precision.used + ")\n";
      }
      text += "trust          " + std::string(core::toString(trust.verdict)) + ": " + trust.reason + "\n";
      if (trust.verdict != core::Verdict::Unchecked) {
        std::snprintf(line, sizeof line,
                      "               state error %.2g, contact time error %.2g T2; holds 1e-6 "
                      "%s t = %.4g (%s)\n",
                      trust.stateError, trust.timeError, trust.horizonObserved ? "until" : "at least until",
                      trust.horizon, trust.horizonObserved ? "observed" : "extrapolated conservatively");
        text += line;
      }
      text += "final          t=" + number(result.tFinal) + " u1=" + number(result.final.u1) +
              " u2=" + number(result.final.u2) + " v1=" + number(result.final.v1) +
              " v2=" + number(result.final.v2) + "\n";
      write(text);
      break;
    }
  }
  std::fflush(m_out);
}

template JsonValue infoValue<double>(const ModelInput<double>&);
template JsonValue infoValue<long double>(const ModelInput<long double>&);
template JsonValue infoValue<core::Quad>(const ModelInput<core::Quad>&);
template std::string infoJson<double>(const ModelInput<double>&);
template std::string infoJson<long double>(const ModelInput<long double>&);
template std::string infoJson<core::Quad>(const ModelInput<core::Quad>&);
template class RunWriter<double>;
template class RunWriter<long double>;
template class RunWriter<core::Quad>;

}  // namespace grazelab::cli
