// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// grazelab._native: the command line's commands run in this process by the command line's own
// code, on a thread of their own with the GIL released. The calling thread wakes every 100 ms:
// Ctrl+C (PyErr_CheckSignals) stops the command through its stop token, and the command's latest
// progress goes to the caller's callback, both on the caller's thread. grazelab/__init__.py turns
// keyword arguments into the options and the outcomes into NumPy. Every command is a typed one
// (commands/simulation.h, periodic_orbit.h, onepp_family.h, modes_atlas_command.h, grazing_set.h,
// chain_info.h, parameter_map.h, stability_matrix.h, work_precision_report.h): its options by name,
// read by the command line's own readers, no command-line text, its outcome handed over as values
// (tables and events as arrays); a chain of N masses is prepared once (prepare_chain:
// grazelab.Chain) for every run of it.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <QCoreApplication>
#include <QFileInfo>
#include <QString>
#include <QStringList>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <initializer_list>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "cli_run.h"
#include "commands/chain_info.h"
#include "commands/family_command.h"
#include "commands/bar_command.h"
#include "commands/glo_set_command.h"
#include "commands/map_command.h"
#include "commands/modes_command.h"
#include "commands/orbit_command.h"
#include "commands/report_command.h"
#include "commands/simulate_command.h"
#include "commands/stability_command.h"
#include "commands/simulation_document.h"
#include "core/experiments/maps.h"
#include "exit_codes.h"
#include "io/cli_io.h"
#include "io/cli_output.h"
#include "io/map_document.h"
#include "io/option_values.h"
#include "io/prepared_chain.h"
#include "value_to_python.h"

namespace py = pybind11;

namespace {

// An in-memory FILE* (open_memstream): what a command writes on its output or its messages.
class MemoryStream {
 public:
  MemoryStream() : m_file(open_memstream(&m_buffer, &m_size)) {
    if (!m_file) throw std::runtime_error("grazelab: cannot open an in-memory stream");
  }
  ~MemoryStream() {
    if (m_file) std::fclose(m_file);
    std::free(m_buffer);
  }
  MemoryStream(const MemoryStream&) = delete;
  MemoryStream& operator=(const MemoryStream&) = delete;
  std::FILE* file() const { return m_file; }
  /// What was written, up to the last flush.
  const char* buffer() const { return m_buffer; }
  /// Everything written (the stream is closed: call once, after the command).
  std::string take() {
    std::fclose(m_file);
    m_file = nullptr;
    return std::string(m_buffer, m_size);
  }

 private:
  char* m_buffer = nullptr;
  std::size_t m_size = 0;
  std::FILE* m_file;
};

// The latest progress of a running command, handed from its threads to the caller's.
struct ProgressMailbox {
  std::mutex mutex;
  bool fresh = false;
  double fraction = -1;
  std::string text;

  /// What a command's Io::progress calls (from any thread): the latest replaces the one before.
  std::function<void(double, const std::string&)> post() {
    return [this](double at, const std::string& line) {
      std::lock_guard lock(mutex);
      fresh = true;
      fraction = at;
      text = line;
    };
  }
};

// A typed command's refusal (invalid input: Python's ValueError) and a file it could not write
// (OSError), told apart from any exception a progress callback raised, which goes through as it is.
struct Refused : std::runtime_error {
  using std::runtime_error::runtime_error;
};
struct NotWritten : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Why a run stopped at `maxEvents` events held in memory.
std::string tooManyEvents(std::size_t maxEvents) {
  return "the run made more than " + std::to_string(maxEvents) + " events (at least " +
         std::to_string(maxEvents * 80 / 1'000'000) +
         " MB in memory): ask for fewer contacts or a shorter t_end, or stream the run to a file "
         "with grazelab-cli simulate --format csv";
}

// Where a quantity of a map lives in its point summaries.
std::size_t offsetOf(grazelab::core::Quantity quantity) {
  using grazelab::core::PointSummary;
  using grazelab::core::Quantity;
  switch (quantity) {
    case Quantity::FftFirst: return offsetof(PointSummary, fftFirst);
    case Quantity::FftMin: return offsetof(PointSummary, fftMin);
    case Quantity::FftMax: return offsetof(PointSummary, fftMax);
    case Quantity::FftMean: return offsetof(PointSummary, fftMean);
    case Quantity::Impacts: return offsetof(PointSummary, impacts);
    case Quantity::Grazings: return offsetof(PointSummary, grazings);
    case Quantity::Sticks: return offsetof(PointSummary, sticks);
    case Quantity::FirstImpactTime: return offsetof(PointSummary, firstImpactTime);
    case Quantity::Horizon: return offsetof(PointSummary, horizon);
  }
  return 0;
}

// A map's points as one structured array with a field per quantity, row-major, owned by the
// array (no copy).
py::array mapPoints(std::vector<grazelab::core::PointSummary>&& mapPoints) {
  using grazelab::core::PointSummary;
  py::list names, formats, offsets;
  for (const grazelab::core::QuantityInfo& info : grazelab::core::quantities()) {
    names.append(std::string(info.name));
    formats.append(info.integer ? "<i8" : "<f8");
    offsets.append(offsetOf(info.quantity));
  }
  py::dict description;
  description["names"] = names;
  description["formats"] = formats;
  description["offsets"] = offsets;
  description["itemsize"] = sizeof(PointSummary);
  const py::dtype dtype = py::dtype::from_args(description);
  auto* points = new std::vector<PointSummary>(std::move(mapPoints));
  py::capsule owner(points, [](void* p) { delete static_cast<std::vector<PointSummary>*>(p); });
  return py::array(dtype, {static_cast<py::ssize_t>(points->size())},
                   {static_cast<py::ssize_t>(sizeof(PointSummary))}, points->data(), owner);
}

// Hands the latest progress, if any arrived since the last call, to the caller's callback (with
// the GIL held). False when the callback raised: that exception is kept in `pythonError`.
bool deliverProgress(ProgressMailbox& mailbox, const py::object& progress,
                     std::optional<py::error_already_set>& pythonError) {
  std::optional<std::pair<double, std::string>> latest;
  {
    std::lock_guard lock(mailbox.mutex);
    if (mailbox.fresh) latest.emplace(mailbox.fraction, mailbox.text);
    mailbox.fresh = false;
  }
  if (!latest) return true;
  try {
    progress(latest->first < 0 ? py::object(py::none()) : py::object(py::float_(latest->first)),
             latest->second);
  } catch (py::error_already_set& error) {
    pythonError.emplace(std::move(error));
    return false;
  }
  return true;
}

// Runs `work` on a thread of its own with the GIL released. The calling thread wakes every
// 100 ms: Ctrl+C (PyErr_CheckSignals) requests `stop` and is raised once the work has ended;
// `onWake` (with the GIL held) may stop it too by returning false, its exception kept in
// `pythonError`. Returns the work's code.
int interruptibly(std::stop_source& stop, const std::function<int(std::stop_token)>& work,
                  const std::function<bool()>& onWake, std::optional<py::error_already_set>& pythonError) {
  std::mutex doneMutex;
  std::condition_variable doneSignal;
  bool done = false;
  int code = 0;
  std::exception_ptr failure;
  {
    py::gil_scoped_release released;
    std::thread worker([&] {
      try {
        code = work(stop.get_token());
      } catch (...) {
        failure = std::current_exception();  // out of memory, most likely
      }
      std::lock_guard lock(doneMutex);
      done = true;
      doneSignal.notify_all();
    });
    for (;;) {
      {
        std::unique_lock lock(doneMutex);
        if (doneSignal.wait_for(lock, std::chrono::milliseconds(100), [&] { return done; })) break;
      }
      if (stop.stop_requested()) continue;  // stopping: wait for the work to end
      py::gil_scoped_acquire held;
      // Ctrl+C (or another signal handler that raised): stop the work, raise once it ended
      if (PyErr_CheckSignals() != 0) {
        pythonError.emplace();
        stop.request_stop();
        continue;
      }
      if (onWake && !onWake()) stop.request_stop();
    }
    worker.join();
  }
  if (failure) std::rethrow_exception(failure);
  return code;
}

// The NumPy types of a chain's events (t, type, u1..uN, v1_pre..vN_pre, vS_post: the csv's
// columns) and samples (t, u1..uN, v1..vN), in double, type as '<U8'; made once per (N, S) and
// kept to the process's end (a dtype costs microseconds to describe: as much as a short run).
struct ChainDtypes {
  py::dtype events, samples;
};
const ChainDtypes& chainDtypes(std::size_t n, std::size_t stopped) {
  static auto* const made = new std::map<std::pair<std::size_t, std::size_t>, ChainDtypes>();
  const auto found = made->find({n, stopped});
  if (found != made->end()) return found->second;
  const auto describe = [](const std::vector<std::string>& names, bool withType) {
    py::list fields;
    for (const std::string& name : names) fields.append(py::make_tuple(name, "<f8"));
    if (withType) fields.insert(1, py::make_tuple("type", "<U8"));
    return py::dtype::from_args(fields);
  };
  std::vector<std::string> events{"t"}, samples{"t"};
  for (std::size_t i = 1; i <= n; ++i) events.push_back("u" + std::to_string(i));
  for (std::size_t i = 1; i <= n; ++i) events.push_back("v" + std::to_string(i) + "_pre");
  events.push_back("v" + std::to_string(stopped) + "_post");
  for (std::size_t i = 1; i <= n; ++i) samples.push_back("u" + std::to_string(i));
  for (std::size_t i = 1; i <= n; ++i) samples.push_back("v" + std::to_string(i));
  return made->emplace(std::pair{n, stopped}, ChainDtypes{describe(events, true), describe(samples, false)})
      .first->second;
}

// A chain's events as one structured array that owns the table's rows (no copy: the rows move
// into the array's base object; their layout is the dtype's)
py::array chainEventArray(grazelab::cli::ChainEventTable&& table, const py::dtype& dtype) {
  auto* rows = new std::vector<char>(std::move(table.rows));
  py::capsule owner(rows, [](void* p) { delete static_cast<std::vector<char>*>(p); });
  return py::array(dtype, {static_cast<py::ssize_t>(table.count)}, {static_cast<py::ssize_t>(table.rowBytes())},
                   rows->data(), owner);
}

// A chain's samples (t, u1..uN, v1..vN in double) as one structured array of the dtype's columns
py::array chainSampleArray(const std::vector<std::pair<double, grazelab::core::ChainState>>& samples,
                           const py::dtype& dtype) {
  py::array array(dtype, py::array::ShapeContainer{static_cast<py::ssize_t>(samples.size())});
  auto* data = static_cast<char*>(array.mutable_data());
  const std::size_t itemsize = std::size_t(dtype.itemsize());
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const auto& [t, state] = samples[k];
    char* row = data + k * itemsize;
    std::memcpy(row, &t, sizeof t);
    const Eigen::Index n = state.u.size();
    for (Eigen::Index i = 0; i < n; ++i) {
      std::memcpy(row + std::size_t(1 + i) * sizeof(double), &state.u[i], sizeof(double));
      std::memcpy(row + std::size_t(1 + n + i) * sizeof(double), &state.v[i], sizeof(double));
    }
  }
  return array;
}

// A command's document as Results; one that holds numbers wider than double (long double,
// binary128) also has `decimal`: its numbers as text.
py::object documentToPython(const grazelab::cli::JsonValue& document, const py::object& resultType,
                            bool withDecimals) {
  py::object result = grazelab::python::toPython(document, resultType);
  if (withDecimals) {
    result["decimal"] = grazelab::python::toPython(document, resultType, true);
  }
  return result;
}

// A simulate's outcome as its Python result, the same for every chain however it was written:
// its document's values (commands/simulation_document.h) made Python objects as they are made in
// double; in a wider precision the document as JsonValue, whose numbers keep their text, under
// `decimal` too; its events, from `table`, as one structured array (None when discarded), its
// samples as another, and `notes`. Returns (the result, the events' decimal text in long double or
// binary128, 2N + 2 a row, else None).
py::tuple simulationResult(const grazelab::cli::SimulateOutcome& outcome, const grazelab::cli::SimulateRequest& request,
                           grazelab::cli::ChainEventTable&& table, const py::object& resultType,
                           std::weak_ptr<const void> chain) {
  // (the samples apart: an array, not a document's columns)
  grazelab::cli::SimulateRequest unsampled = request;
  unsampled.sampled = false;
  py::object result;
  const ChainDtypes& dtypes = chainDtypes(table.masses, std::size_t(table.stopped));
  if (outcome.precision == grazelab::core::Precision::Double) {
    const grazelab::python::PyValue::ObjectType objects(resultType);
    // (the chain's own sections made once for it: they are the same in every run of it)
    const grazelab::python::PyValue::ChainScope sections(std::move(chain));
    result = grazelab::cli::simulationDocument<grazelab::python::PyValue>(outcome, unsampled).take();
    if (request.sampled) {
      result["samples"] = chainSampleArray(outcome.samples, dtypes.samples);
      result["samples_truncated"] = py::bool_(outcome.samplesTruncated);
    }
  } else {
    grazelab::cli::JsonValue document = grazelab::cli::simulationDocument<grazelab::cli::JsonValue>(outcome, request);
    if (request.sampled) document.set("samples", grazelab::cli::JsonValue::null());  // (an array, below)
    result = grazelab::python::toPython(document, resultType);  // (its events, None, in their place)
    if (request.sampled) result["samples"] = chainSampleArray(outcome.samples, dtypes.samples);
    document.remove("events");  // (the result's are an array; `decimal` has neither)
    document.remove("samples");
    result["decimal"] = grazelab::python::toPython(document, resultType, true);
  }
  const py::object events =
      table.discard ? py::object(py::none()) : py::object(chainEventArray(std::move(table), dtypes.events));
  // (names made once: a short run's call is a few microseconds)
  static PyObject* const eventsKey = PyUnicode_InternFromString("events");
  static PyObject* const notesKey = PyUnicode_InternFromString("notes");
  if (PyDict_SetItem(result.ptr(), eventsKey, events.ptr()) != 0 ||
      PyDict_SetItem(result.ptr(), notesKey, py::cast(outcome.notes).ptr()) != 0) {
    throw py::error_already_set();
  }
  return py::make_tuple(result, table.decimals.empty() ? py::object(py::none()) : py::cast(table.decimals));
}

// Options given by name as (flag, text) pairs, text None for a bare flag (--onepp).
grazelab::cli::OptionValues textOptions(const std::vector<std::pair<std::string, std::optional<std::string>>>& given) {
  std::vector<grazelab::cli::GivenOption> named;
  for (const auto& [flag, text] : given) {
    named.push_back({flag, text ? QString::fromStdString(*text) : QString(), {}, false});
  }
  return grazelab::cli::OptionValues(std::move(named));
}

// An option's value as the direct call takes it: a str is its text; a float, an int exact in
// double or a tuple/list of them are numbers. False for any other type (the caller then writes
// the options as text: NumPy scalars, Fractions, ...).
bool readGiven(PyObject* value, grazelab::cli::GivenOption& option) {
  auto number = [](PyObject* item, double& out) {
    if (PyFloat_CheckExact(item)) {
      out = PyFloat_AS_DOUBLE(item);
      return true;
    }
    if (!PyLong_CheckExact(item)) return false;  // (a bool is an int subclass: refused here)
    int overflow = 0;
    const long long whole = PyLong_AsLongLongAndOverflow(item, &overflow);
    if (overflow != 0 || whole > (1LL << 53) || whole < -(1LL << 53)) return false;
    out = double(whole);
    return true;
  };
  if (PyUnicode_CheckExact(value)) {
    Py_ssize_t size = 0;
    const char* utf8 = PyUnicode_AsUTF8AndSize(value, &size);
    if (!utf8) throw py::error_already_set();
    option.text = QString::fromUtf8(utf8, size);
    return true;
  }
  double single = 0;
  if (number(value, single)) {
    option.numeric = true;
    option.numbers.assign(1, single);
    return true;
  }
  if (!PyTuple_CheckExact(value) && !PyList_CheckExact(value)) return false;
  const Py_ssize_t size = PySequence_Fast_GET_SIZE(value);
  option.numeric = true;
  option.numbers.resize(std::size_t(size));
  for (Py_ssize_t i = 0; i < size; ++i) {
    if (!number(PySequence_Fast_GET_ITEM(value, i), option.numbers[std::size_t(i)])) return false;
  }
  return true;
}

// Options given by name as (name, value, name, value, ...), None for an option not given; a
// sequence only for the options in `sequences`. Nothing when a value is not of a type read
// directly (then give the options as text).
std::optional<std::vector<grazelab::cli::GivenOption>> givenOptions(const py::sequence& given,
                                                                    std::initializer_list<std::string_view> sequences) {
  std::vector<grazelab::cli::GivenOption> named;
  const py::object flat = py::reinterpret_steal<py::object>(PySequence_Fast(given.ptr(), "options"));
  if (!flat) throw py::error_already_set();
  const Py_ssize_t count = PySequence_Fast_GET_SIZE(flat.ptr());
  if (count % 2 != 0) throw py::type_error("options are name, value, name, value, ...");
  named.reserve(std::size_t(count / 2));
  for (Py_ssize_t i = 0; i < count; i += 2) {
    PyObject* key = PySequence_Fast_GET_ITEM(flat.ptr(), i);
    PyObject* value = PySequence_Fast_GET_ITEM(flat.ptr(), i + 1);
    if (!PyUnicode_Check(key)) throw py::type_error("options are name, value, name, value, ...");
    if (value == Py_None) continue;
    grazelab::cli::GivenOption option;
    Py_ssize_t size = 0;
    const char* name = PyUnicode_AsUTF8AndSize(key, &size);
    if (!name) throw py::error_already_set();
    option.name.assign(name, std::size_t(size));
    // a sequence only where one is expected: elsewhere the text path says what is wrong
    const bool sequence = PyTuple_Check(value) || PyList_Check(value);
    if (sequence && std::find(sequences.begin(), sequences.end(), option.name) == sequences.end()) return std::nullopt;
    if (!readGiven(value, option)) return std::nullopt;
    named.push_back(std::move(option));
  }
  return named;
}

// A typed command that writes its files where --out says (family, modes, map, stability: `work`
// is its ...WithFiles), run on a thread of its own that Ctrl+C stops, its progress heard on the
// calling thread, its messages put in `log` when given; Refused (invalid input) or NotWritten (a
// file not written) with its line.
template <typename Work>
auto filesCommand(const grazelab::cli::OptionValues& options, const py::object& progress, Work work,
                  std::string* log = nullptr) {
  using Run = decltype(work(options, grazelab::cli::Io{}, std::stop_token{}, std::declval<QString&>(), false));
  MemoryStream messages;
  ProgressMailbox mailbox;
  grazelab::cli::Io io;
  io.messages = messages.file();
  if (!progress.is_none()) io.progress = mailbox.post();
  QString error;
  Run run;
  std::stop_source stop;
  std::optional<py::error_already_set> pythonError;
  interruptibly(
      stop,
      [&](std::stop_token token) {
        run = work(options, io, std::move(token), error, false);
        return run.code;
      },
      [&] { return progress.is_none() || deliverProgress(mailbox, progress, pythonError); }, pythonError);
  if (!pythonError && run.code == 0 && !progress.is_none()) deliverProgress(mailbox, progress, pythonError);
  if (pythonError) throw std::move(*pythonError);
  if (run.code == grazelab::cli::kExitInvalidInput) throw Refused(error.simplified().toStdString());
  if (run.code != 0) throw NotWritten(error.simplified().toStdString());
  if (log) *log = messages.take();
  return run;
}

// The file name of --out (the files' base), when given.
std::optional<std::string> outBase(const grazelab::cli::OptionValues& options) {
  if (!options.isSet("out")) return std::nullopt;
  return QFileInfo(options.value("out")).fileName().toStdString();
}

// A table of double columns, row-major, as a structured array that owns it (no copy).
py::array tableArray(std::vector<double>&& rows, const std::vector<std::string>& columns) {
  py::list fields;
  for (const std::string& column : columns) fields.append(py::make_tuple(column, "<f8"));
  const py::dtype dtype = py::dtype::from_args(fields);
  auto* table = new std::vector<double>(std::move(rows));
  py::capsule owner(table, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  const auto count = static_cast<py::ssize_t>(columns.empty() ? 0 : table->size() / columns.size());
  return py::array(dtype, {count}, {static_cast<py::ssize_t>(dtype.itemsize())}, table->data(), owner);
}

// The document of a typed command (orbit, info, glo-set) as values of `resultType`: `work` reads
// its chain and runs it on a thread of its own that Ctrl+C stops, and gives its document, or
// nothing with `refusal` (the command line's line). What Python raised goes through; a refusal is
// Refused (a ValueError).
using TypedWork = std::function<std::optional<grazelab::cli::JsonValue>(std::stop_token, std::string& refusal)>;
py::object typedDocument(const TypedWork& work, const py::object& resultType) {
  std::optional<grazelab::cli::JsonValue> document;
  std::string refusal;
  std::stop_source stop;
  std::optional<py::error_already_set> pythonError;
  interruptibly(
      stop,
      [&](std::stop_token token) {
        document = work(std::move(token), refusal);
        return 0;
      },
      {}, pythonError);
  if (pythonError) throw std::move(*pythonError);
  if (!document) throw Refused(QString::fromStdString(refusal).simplified().toStdString());
  return documentToPython(*document, resultType, document->holdsWideNumbers());
}

// orbit(options, result_type) -> its document as values: the typed orbit (commands/periodic_orbit.h)
// of the options given by name as (flag, text) pairs (text None for the bare --onepp).
py::object orbitCommand(const std::vector<std::pair<std::string, std::optional<std::string>>>& given,
                        const py::object& resultType) {
  const grazelab::cli::OptionValues options = textOptions(given);
  QString error;
  const std::optional<grazelab::cli::OrbitRequest> request = grazelab::cli::readOrbitRequest(options, error);
  if (!request) throw Refused(error.simplified().toStdString());
  return typedDocument(
      [&](std::stop_token token, std::string& refusal) -> std::optional<grazelab::cli::JsonValue> {
        const auto chain = grazelab::cli::orbitChainOf(options, token);
        if (!chain.value) {
          refusal = chain.error.toStdString();
          return std::nullopt;
        }
        const grazelab::cli::OrbitOutcome outcome = grazelab::cli::solveOrbit(**chain.value, *request, std::move(token));
        if (outcome.status != grazelab::cli::OrbitStatus::Found) {
          refusal = outcome.problem;
          return std::nullopt;
        }
        return grazelab::cli::orbitDocument(outcome);
      },
      resultType);
}

// info(options, result_type) -> its document as values: the typed info (commands/chain_info.h)
// of the options given by name as (flag, text) pairs (a design of the springs may take a while).
py::object infoCommand(const std::vector<std::pair<std::string, std::optional<std::string>>>& given,
                       const py::object& resultType) {
  const grazelab::cli::OptionValues options = textOptions(given);
  QString error;
  const std::optional<grazelab::cli::InfoRequest> request = grazelab::cli::readInfoRequest(options, error);
  if (!request) throw Refused(error.simplified().toStdString());
  return typedDocument(
      [&](std::stop_token token, std::string& refusal) -> std::optional<grazelab::cli::JsonValue> {
        grazelab::cli::InfoOutcome outcome = grazelab::cli::describeChain(options, *request, std::move(token));
        if (outcome.status != grazelab::cli::InfoStatus::Described) {
          refusal = outcome.problem;
          return std::nullopt;
        }
        return std::move(outcome.document);
      },
      resultType);
}

// glo_set(options, result_type) -> its document as values: the typed glo-set
// (commands/grazing_set.h) of the options given by name as (flag, text) pairs.
py::object gloSetCommand(const std::vector<std::pair<std::string, std::optional<std::string>>>& given,
                         const py::object& resultType) {
  const grazelab::cli::OptionValues options = textOptions(given);
  QString error;
  const std::optional<grazelab::cli::GloSetRequest> request = grazelab::cli::readGloSetRequest(options, error);
  if (!request) throw Refused(error.simplified().toStdString());
  return typedDocument(
      [&](std::stop_token token, std::string& refusal) -> std::optional<grazelab::cli::JsonValue> {
        const auto chain = grazelab::cli::gloSetChainOf(options, token);
        if (!chain.value) {
          refusal = chain.error.toStdString();
          return std::nullopt;
        }
        const grazelab::cli::GloSetOutcome outcome = grazelab::cli::grazingSet(*chain.value, *request, std::move(token));
        if (outcome.status != grazelab::cli::GloSetStatus::Computed) {
          refusal = outcome.problem;
          return std::nullopt;
        }
        return grazelab::cli::gloSetDocument(outcome);
      },
      resultType);
}

// bar(options, result_type) -> its document as values: the typed bar (commands/bar_command.h)
py::object barCommand(const std::vector<std::pair<std::string, std::optional<std::string>>>& given,
                      const py::object& resultType) {
  const grazelab::cli::OptionValues options = textOptions(given);
  QString error;
  const std::optional<grazelab::cli::BarRequest> request = grazelab::cli::readBarRequest(options, error);
  if (!request) throw Refused(error.simplified().toStdString());
  return typedDocument(
      [&](std::stop_token token, std::string&) -> std::optional<grazelab::cli::JsonValue> {
        const grazelab::cli::BarOutcome outcome = grazelab::cli::throwBars(*request, std::move(token));
        if (outcome.status != grazelab::cli::BarOutcomeStatus::Computed) return std::nullopt;
        return grazelab::cli::barDocument(outcome);
      },
      resultType);
}

// family(options, result_type, progress) -> (its document as values, its table as a structured
// array): the typed family (commands/onepp_family.h) of the options given by name as (flag, text)
// pairs (text None for the bare --onepp), on a thread of its own that Ctrl+C stops, `progress`
// hearing it on the calling thread; its files written only where --out names them (no picture).
// The table's rows move into the array (no copy). Refused (a ValueError) with the command line's
// line when there is no family, NotWritten (an OSError) when a file could not be written.
py::tuple familyCommand(const std::vector<std::pair<std::string, std::optional<std::string>>>& given,
                        const py::object& resultType, const py::object& progress) {
  const grazelab::cli::OptionValues options = textOptions(given);
  grazelab::cli::FamilyRun run = filesCommand(options, progress, &grazelab::cli::familyWithFiles);
  const grazelab::cli::JsonValue document = grazelab::cli::familyDocument(run.outcome, outBase(options));
  return py::make_tuple(documentToPython(document, resultType, document.holdsWideNumbers()),
                        tableArray(std::move(run.outcome.table), run.outcome.columns));
}

// An atlas computed (`modes`, `family --impacts`): (its document as values of `resultType`, each
// family's table as a structured array, in the document's order).
py::tuple atlasTuple(const grazelab::cli::ModesRun& run, const grazelab::cli::OptionValues& options,
                     const py::object& resultType) {
  const grazelab::cli::JsonValue document = grazelab::cli::modesDocument(run.outcome, outBase(options));
  py::list tables;
  for (std::size_t i = 0; i < grazelab::cli::modesFamilyCount(run.outcome); ++i) {
    tables.append(tableArray(grazelab::cli::modesTable(run.outcome, i), grazelab::cli::modesColumns(run.outcome)));
  }
  return py::make_tuple(documentToPython(document, resultType, document.holdsWideNumbers()), tables);
}

// modes(options, result_type, progress) -> (its document as values, each family's table as a
// structured array, in the document's order): the typed atlas (commands/modes_atlas_command.h)
// of the options given by name as (flag, text) pairs, on a thread of its own that Ctrl+C stops;
// its files written only where --out names them (no picture). Refused (a ValueError) with the
// command line's line when there is none, NotWritten (an OSError) when a file could not be written.
py::tuple modesCommand(const std::vector<std::pair<std::string, std::optional<std::string>>>& given,
                       const py::object& resultType, const py::object& progress) {
  const grazelab::cli::OptionValues options = textOptions(given);
  return atlasTuple(filesCommand(options, progress, &grazelab::cli::modesWithFiles), options, resultType);
}

// family(options with --impacts, result_type, progress): the family of a kIPP orbit followed both
// ways, as an atlas of one family (commands/modes_atlas_command.h impactsFamily): as `modes`.
py::tuple impactsFamilyCommand(const std::vector<std::pair<std::string, std::optional<std::string>>>& given,
                               const py::object& resultType, const py::object& progress) {
  const grazelab::cli::OptionValues options = textOptions(given);
  return atlasTuple(filesCommand(options, progress, &grazelab::cli::impactsFamilyWithFiles), options, resultType);
}

// A map or merge computed: (its document as values of `resultType`, with `files` when written,
// its points as one structured array).
py::tuple mapResult(grazelab::cli::MapRun&& run, const py::object& resultType) {
  grazelab::cli::map::StoredMap& map = run.outcome.map;
  const grazelab::cli::JsonValue document =
      grazelab::cli::map::mapDocument(map, run.files ? std::move(*run.files) : grazelab::cli::JsonValue::null());
  return py::make_tuple(grazelab::python::toPython(document, resultType), mapPoints(std::move(map.points)));
}

// map(options, result_type, progress) -> (its document as values, its points as a structured
// array): the typed map (commands/parameter_map.h) of the options given by name as (flag, text)
// pairs, on threads that Ctrl+C stops; its files written only where --out names them (no picture).
py::tuple mapCommand(const std::vector<std::pair<std::string, std::optional<std::string>>>& given,
                     const py::object& resultType, const py::object& progress) {
  const grazelab::cli::OptionValues options = textOptions(given);
  return mapResult(filesCommand(options, progress, &grazelab::cli::mapWithFiles), resultType);
}

// merge(parts, out, result_type) -> as map: the stripes of one map (their prefixes) joined, written
// under `out` when given.
py::tuple mergeCommand(const std::vector<std::string>& partTexts, const std::optional<std::string>& out,
                       const py::object& resultType) {
  QStringList parts;
  for (const std::string& part : partTexts) parts << QString::fromStdString(part);
  std::vector<std::pair<std::string, std::optional<std::string>>> given;
  if (out) given.emplace_back("out", *out);
  const grazelab::cli::OptionValues options = textOptions(given);
  const auto merge = [&parts](const grazelab::cli::OptionValues& values, const grazelab::cli::Io& io,
                              std::stop_token stop, QString& error, bool filesRequired) {
    return grazelab::cli::mergeWithFiles(values, parts, io, std::move(stop), error, filesRequired);
  };
  return mapResult(filesCommand(options, py::none(), merge), resultType);
}

// report(options, progress) -> (results.csv's text, report.md's text, the messages): the typed
// work-precision report (commands/work_precision_report.h) of the options given by name as
// (flag, text) pairs (text None for the bare --quick), on a thread of its own that Ctrl+C stops;
// its files written only where --out names them (no picture).
py::tuple reportCommand(const std::vector<std::pair<std::string, std::optional<std::string>>>& given,
                        const py::object& progress) {
  const grazelab::cli::OptionValues options = textOptions(given);
  std::string log;
  const grazelab::cli::ReportRun run = filesCommand(options, progress, &grazelab::cli::reportWithFiles, &log);
  return py::make_tuple(py::bytes(run.csv.toStdString()), run.markdown.toStdString(), log);
}

// stability(options, progress) -> (matrix.csv's text, matrix.md's text, the messages): the typed
// stability matrix (commands/stability_matrix.h) of the options given by name as (flag, text)
// pairs (text None for the bare --quick), on a thread of its own that Ctrl+C stops; its files
// written only where --out names them.
py::tuple stabilityCommand(const std::vector<std::pair<std::string, std::optional<std::string>>>& given,
                           const py::object& progress) {
  const grazelab::cli::OptionValues options = textOptions(given);
  std::string log;
  const grazelab::cli::StabilityRun run = filesCommand(options, progress, &grazelab::cli::stabilityWithFiles, &log);
  return py::make_tuple(py::bytes(grazelab::cli::stabilityCsv(run.outcome).toStdString()),
                        grazelab::cli::stabilityMarkdown(run.request, run.outcome).toStdString(), log);
}

// grazelab.Chain's native half: a chain of N masses read, checked and designed once, shared by
// every run of it (cli::PreparedMassChain).
struct ChainHandle {
  std::shared_ptr<const grazelab::cli::PreparedMassChain> chain;
};

// The typed simulate (cli::simulate) of `chain` with the run options `options`: (its result, the
// events' decimal text in long double or binary128, else None). `direct`: on the calling thread
// (a short run, which the caller keeps short: nothing interrupts it), else on a thread of its own
// that Ctrl+C stops. ValueError for a request refused or a run past max_events events.
py::tuple simulateTyped(const std::shared_ptr<const grazelab::cli::PreparedMassChain>& chain,
                        const grazelab::cli::OptionValues& options,
                        bool notesStarts, const py::object& resultType, bool discardEvents, bool direct,
                        std::size_t maxEvents) {
  QString error;
  std::optional<grazelab::cli::SimulateRequest> request =
      grazelab::cli::readSimulateRequest(options, grazelab::cli::Format::Json, error);
  if (!request) throw py::value_error(error.simplified().toStdString());
  request->notesStarts = notesStarts;
  std::stop_source stop;
  grazelab::cli::ChainEventTable table;
  table.discard = discardEvents;
  table.maxRows = maxEvents;
  table.whenFull = [&stop] { stop.request_stop(); };
  grazelab::cli::EventTableSink sink(table);
  grazelab::cli::SimulateOutcome outcome;
  const auto work = [&](std::stop_token token) {
    outcome = grazelab::cli::simulate(*chain, *request, sink, std::move(token));
    return 0;
  };
  if (direct) {
    py::gil_scoped_release released;
    work(stop.get_token());
  } else {
    std::optional<py::error_already_set> pythonError;
    interruptibly(stop, work, {}, pythonError);
    if (pythonError) throw std::move(*pythonError);
  }
  if (table.full) throw py::value_error(tooManyEvents(maxEvents));
  if (outcome.status == grazelab::cli::SimulateStatus::Refused) {
    throw py::value_error(QString::fromStdString(outcome.problem).simplified().toStdString());
  }
  return simulationResult(outcome, *request, std::move(table), resultType, chain);
}

// simulate(options, result_type, events, max_events, discard_events, direct) -> (result with its
// events and notes, decimals), or None when an option's value is not of a type read directly
// (then give the options as text). A chain of the note's options or of --masses (read once for
// the last 16 asked for) run with the options given by name as (name, value, name, value, ...),
// None for an option not given: no command-line text, no parser, its outcome handed over as
// values. The numbers are read as the command line reads their shortest decimal text.
py::object simulateOptions(const py::sequence& given, const py::object& resultType, bool eventsAsArrays,
                           std::size_t maxEvents, bool discardEvents, bool direct) {
  auto named = givenOptions(given, {"state", "perturb", "sample-times"});
  if (!named) return py::none();
  const grazelab::cli::OptionValues options(std::move(*named));
  // the chain read (a design may take seconds: on the run's thread unless the run is direct)
  grazelab::cli::Parsed<std::shared_ptr<const grazelab::cli::PreparedMassChain>> chain;
  const auto read = [&](std::stop_token stop) {
    chain = grazelab::cli::recentChain(options, std::move(stop));
    return 0;
  };
  if (direct) {
    py::gil_scoped_release released;
    read({});
  } else {
    std::stop_source stop;
    std::optional<py::error_already_set> pythonError;
    interruptibly(stop, read, {}, pythonError);
    if (pythonError) throw std::move(*pythonError);
  }
  if (!chain.value) throw py::value_error(chain.error.simplified().toStdString());
  return simulateTyped(*chain.value, options, !options.isSet("masses"), resultType,
                       discardEvents || !eventsAsArrays, direct, maxEvents);
}

// prepare_chain(options) -> ChainHandle: the chain of `options` ((name, text, ...): masses,
// springs, right-spring, stop-mass, gap, frequencies, design-branch), designed on a thread of
// its own (a seven-mass design takes seconds: Ctrl+C stops it); ValueError with the command
// line's line when there is none.
ChainHandle prepareChain(const py::sequence& given) {
  auto named = givenOptions(given, {});
  if (!named) throw py::type_error("Chain: its options are given as text");
  const grazelab::cli::OptionValues options(std::move(*named));
  std::stop_source stop;
  std::optional<py::error_already_set> pythonError;
  grazelab::cli::Parsed<std::shared_ptr<const grazelab::cli::PreparedMassChain>> made;
  interruptibly(
      stop,
      [&](std::stop_token token) {
        made = grazelab::cli::PreparedMassChain::make(options, token);
        return 0;
      },
      {}, pythonError);
  if (pythonError) throw std::move(*pythonError);
  if (!made.value) throw py::value_error(made.error.simplified().toStdString());
  return {std::move(*made.value)};
}

// simulate_chain(chain, options, result_type, discard_events, direct) -> (result, the events'
// decimal text in long double or binary128, else None), or None when an option's value is not
// of a type read directly (then give the options as text). The run of `grazelab-cli simulate
// --masses ...` on the prepared chain (simulateTyped); the note's chain is run by the note's
// kernel (the result of simulate with the two-mass keywords). `direct`: on the calling thread (a short run of a commensurate chain, whose every
// flight is decided within a period), else on a thread of its own that Ctrl+C stops.
py::object simulateChain(const ChainHandle& chain, const py::sequence& given, const py::object& resultType,
                         bool discardEvents, bool direct, std::size_t maxEvents) {
  auto named = givenOptions(given, {"state", "perturb", "glo-weights", "sample-times"});
  if (!named) return py::none();
  const grazelab::cli::OptionValues options(std::move(*named));
  return simulateTyped(chain.chain, options, false, resultType, discardEvents, direct, maxEvents);
}

// The chain as the documents write it (masses, springs designed, right spring, stop, gap, the
// common period of a commensurate chain), in double.
py::object chainDescription(const ChainHandle& chain, const py::object& resultType) {
  const grazelab::core::BasicReadyChain<double>& ready = *chain.chain->ready<double>().value;
  return grazelab::python::toPython(grazelab::cli::massChainValue(ready.numbers, ready.dynamics.period), resultType);
}

}  // namespace

PYBIND11_MODULE(_native, module) {
  module.doc() = "GrazeLab's command line, run in process (use the grazelab package).";
  // set once here, before any thread reads it (the files' "generator" field)
  QCoreApplication::setApplicationName(QStringLiteral("grazelab-cli"));
  QCoreApplication::setApplicationVersion(QString::fromUtf8(grazelab::cli::kVersion));
  module.attr("version") = grazelab::cli::kVersion;
  py::register_exception<Refused>(module, "Refused", PyExc_ValueError);
  py::register_exception<NotWritten>(module, "NotWritten", PyExc_OSError);
  py::class_<ChainHandle>(module, "PreparedChain",
                          "A chain of N masses read, checked and designed once (use grazelab.Chain).")
      .def("describe", &chainDescription, py::arg("result_type"),
           "The chain as the documents write it (designed springs, the common period), in double.")
      .def_property_readonly("period", [](const ChainHandle& chain) {
        return chain.chain->ready<double>().value->dynamics.period;
      }, "The common period of a commensurate chain, 0 otherwise.");
  module.def("orbit", &orbitCommand, py::arg("options"), py::arg("result_type"),
             "grazelab-cli orbit's typed command, its options as (flag, text) pairs (text None for the bare "
             "--onepp): its document as values of result_type (in long double or binary128 also as text, "
             "under 'decimal'). Raises ValueError with the command line's line when there is no orbit.");
  module.def("info", &infoCommand, py::arg("options"), py::arg("result_type"),
             "grazelab-cli info's typed command, its options as (flag, text) pairs: its document as values of "
             "result_type (in long double or binary128 also as text, under 'decimal'). Raises ValueError with "
             "the command line's line when there is no chain.");
  module.def("glo_set", &gloSetCommand, py::arg("options"), py::arg("result_type"),
             "grazelab-cli glo-set's typed command, its options as (flag, text) pairs: its document as values "
             "of result_type. Raises ValueError with the command line's line when the chain has none.");
  module.def("bar", &barCommand, py::arg("options"), py::arg("result_type"),
             "grazelab-cli bar's typed command, its options as (flag, text) pairs: its document as values of "
             "result_type.");
  module.def("family", &familyCommand, py::arg("options"), py::arg("result_type"), py::arg("progress") = py::none(),
             "grazelab-cli family --onepp's typed command, its options as (flag, text) pairs (text None for the bare "
             "--onepp): (its document as values of result_type, its table as a structured array); its files "
             "written only where --out names them, without pictures. ValueError when there is no family.");
  module.def("modes", &modesCommand, py::arg("options"), py::arg("result_type"), py::arg("progress") = py::none(),
             "grazelab-cli modes's typed command, its options as (flag, text) pairs: (its document as values of "
             "result_type, each family's table as a structured array); its files written only where --out names "
             "them, without pictures. ValueError when there is no atlas.");
  module.def("impacts_family", &impactsFamilyCommand, py::arg("options"), py::arg("result_type"),
             py::arg("progress") = py::none(),
             "grazelab-cli family --impacts's typed command, its options as (flag, text) pairs: (its document as "
             "values of result_type, as modes's with one family, and that family's table). ValueError when no "
             "orbit is found from the guess.");
  module.def("map", &mapCommand, py::arg("options"), py::arg("result_type"), py::arg("progress") = py::none(),
             "grazelab-cli map's typed command, its options as (flag, text) pairs: (its document as values of "
             "result_type, its points as a structured array, a field per quantity, row-major); its files "
             "written only where --out names them, without a picture. ValueError when there is no map.");
  module.def("merge", &mergeCommand, py::arg("parts"), py::arg("out"), py::arg("result_type"),
             "grazelab-cli merge in process: the stripes of one map (their prefixes) joined, as map returns a "
             "map; written under out when it is not None. ValueError when the parts are not one map's stripes.");
  module.def("report", &reportCommand, py::arg("options"), py::arg("progress") = py::none(),
             "grazelab-cli report's typed command, its options as (flag, text) pairs (text None for the bare "
             "--quick): (results.csv's bytes, report.md's text, the messages); its files written only where --out "
             "names them, without pictures. ValueError when there is no report.");
  module.def("stability", &stabilityCommand, py::arg("options"), py::arg("progress") = py::none(),
             "grazelab-cli stability's typed command, its options as (flag, text) pairs (text None for the bare "
             "--quick): (matrix.csv's bytes, matrix.md's text, the messages); its files written only where --out "
             "names them. ValueError when there is no matrix.");
  module.def("prepare_chain", &prepareChain, py::arg("options"),
             "A chain of N masses from its options as (name, text, ...): masses, springs, right-spring, "
             "stop-mass, gap, frequencies, design-branch. Raises ValueError when there is none.");
  module.def("simulate_chain", &simulateChain, py::arg("chain"), py::arg("options"), py::arg("result_type"),
             py::arg("discard_events") = false, py::arg("direct") = false, py::arg("max_events") = std::size_t(-1),
             "grazelab-cli simulate --masses ... on a prepared chain, its run options as (name, value, ...): "
             "(the result: its document as values, with events and notes; the note's chain's events' decimal "
             "text or None), or None when a value is of a type not read directly (give the options as text).");
  module.def("simulate", &simulateOptions, py::arg("options"), py::arg("result_type"),
             py::arg("events") = true, py::arg("max_events") = std::size_t(-1),
             py::arg("discard_events") = false, py::arg("direct") = false,
             "grazelab-cli simulate's run, its options as (name, value, name, value, ...) (a value str, "
             "float, int or a tuple of numbers; None: not given): (result with its events and notes, "
             "the events' decimal text or None), or None when a value is of another type (give the "
             "options as text). direct: on the calling thread (a short run: nothing interrupts it), "
             "else on a thread of its own that Ctrl+C stops.");
}
