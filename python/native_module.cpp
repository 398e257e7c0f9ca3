// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// grazelab._native: one command line run in this process by the command line's own code
// (runCommandLine), on a thread of its own with the GIL released. The calling thread wakes every
// 100 ms: Ctrl+C (PyErr_CheckSignals) stops the command through its stop token, and the
// command's latest progress goes to the caller's callback, both on the caller's thread.
// grazelab/__init__.py turns keyword arguments into the flags and the output into NumPy.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "cli_run.h"
#include "commands/simulate_command.h"
#include "core/experiments/maps.h"
#include "core/solver/recorder.h"
#include "exit_codes.h"
#include "io/cli_io.h"
#include "io/map_files.h"
#include "io/option_values.h"
#include "value_to_python.h"

namespace py = pybind11;

namespace {

using grazelab::cli::EventRow;
using grazelab::cli::EventTable;

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
};

// The NumPy type of EventRow: the CSV's columns, type as '<U8'.
py::dtype eventDtype() {
  py::list names, formats, offsets;
  auto column = [&](const char* name, const char* format, std::size_t offset) {
    names.append(name);
    formats.append(format);
    offsets.append(offset);
  };
  column("t", "<f8", offsetof(EventRow, t));
  column("type", "<U8", offsetof(EventRow, type));
  column("u1", "<f8", offsetof(EventRow, u1));
  column("u2", "<f8", offsetof(EventRow, u2));
  column("v1_pre", "<f8", offsetof(EventRow, v1Pre));
  column("v2_pre", "<f8", offsetof(EventRow, v2Pre));
  column("v2_post", "<f8", offsetof(EventRow, v2Post));
  py::dict description;
  description["names"] = names;
  description["formats"] = formats;
  description["offsets"] = offsets;
  description["itemsize"] = sizeof(EventRow);
  return py::dtype::from_args(description);
}

// NumPy types made once, when the module is imported (a dtype from a description costs a few
// microseconds: as much as a short run); constants, never changed, kept to the process's end.
struct NumpyTypes {
  py::dtype events;
  py::dtype samples;
};
const NumpyTypes* numpyTypes = nullptr;

// The events as a NumPy array that owns the table's rows (no copy: the vector moves into the
// array's base object).
py::array eventArray(std::unique_ptr<EventTable> table) {
  const py::dtype& dtype = numpyTypes->events;
  const auto count = static_cast<py::ssize_t>(table->rows.size());
  if (count == 0) return py::array(dtype, py::array::ShapeContainer{py::ssize_t(0)}, py::array::StridesContainer{py::ssize_t(sizeof(EventRow))});
  auto* rows = new std::vector<EventRow>(std::move(table->rows));
  py::capsule owner(rows, [](void* p) { delete static_cast<std::vector<EventRow>*>(p); });
  return py::array(dtype, {count}, {py::ssize_t(sizeof(EventRow))}, rows->data(), owner);
}

// Why a run stopped at `maxEvents` events held in memory.
std::string tooManyEvents(std::size_t maxEvents) {
  return "the run made more than " + std::to_string(maxEvents) + " events (" +
         std::to_string(maxEvents * sizeof(EventRow) / 1'000'000) +
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

// A map in memory: (its JSON document, its points as one structured array with a field per
// quantity, row-major), the points owned by the array (no copy).
py::tuple mapInMemory(grazelab::cli::map::StoredMap&& map) {
  using grazelab::core::PointSummary;
  const std::string document = grazelab::cli::indented(grazelab::cli::map::mapDocument(map));
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
  auto* points = new std::vector<PointSummary>(std::move(map.points));
  py::capsule owner(points, [](void* p) { delete static_cast<std::vector<PointSummary>*>(p); });
  const py::array array(dtype, {static_cast<py::ssize_t>(points->size())},
                        {static_cast<py::ssize_t>(sizeof(PointSummary))}, points->data(), owner);
  return py::make_tuple(py::bytes(document), array);
}

// The NumPy type of a two-mass run's samples: t, u1, u2, v1, v2.
py::dtype sampleDtype() {
  using grazelab::core::Sample;
  static_assert(sizeof(Sample) == 5 * sizeof(double));
  py::list names, formats, offsets;
  const std::size_t state = offsetof(Sample, state);
  const std::pair<const char*, std::size_t> columns[] = {
      {"t", offsetof(Sample, t)}, {"u1", state + 0 * sizeof(double)}, {"u2", state + 1 * sizeof(double)},
      {"v1", state + 2 * sizeof(double)}, {"v2", state + 3 * sizeof(double)}};
  for (const auto& [name, offset] : columns) {
    names.append(name);
    formats.append("<f8");
    offsets.append(offset);
  }
  py::dict description;
  description["names"] = names;
  description["formats"] = formats;
  description["offsets"] = offsets;
  description["itemsize"] = sizeof(Sample);
  return py::dtype::from_args(description);
}

// A run's samples as a NumPy array (t, u1, u2, v1, v2) that owns them (no copy).
py::array sampleArray(std::vector<grazelab::core::Sample>&& samples) {
  using grazelab::core::Sample;
  auto* owned = new std::vector<Sample>(std::move(samples));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<Sample>*>(p); });
  return py::array(numpyTypes->samples, {static_cast<py::ssize_t>(owned->size())},
                   {static_cast<py::ssize_t>(sizeof(Sample))}, owned->data(), owner);
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

// A command's document as Results; one that holds numbers wider than double (long double,
// binary128) also has `decimal`: its numbers as text.
py::object documentToPython(const grazelab::cli::JsonValue& document, const py::object& resultType,
                            bool withDecimals, std::vector<grazelab::core::Sample>&& samples) {
  py::object result = grazelab::python::toPython(document, resultType);
  // a two-mass run's samples come apart from its document (a chain of N masses lists its own)
  if (result.contains("samples_truncated") && !result.contains("samples")) {
    result["samples"] = sampleArray(std::move(samples));
  }
  if (withDecimals) {
    result["decimal"] = grazelab::python::toPython(document, resultType, true);
  }
  return result;
}

// run(arguments, progress=None, events=False, max_events, discard_events=False, keep_map=False,
//     result_type=None, keep_files=False)
//   -> (code, output, messages, events, decimals, map, document, files)
py::tuple run(const std::vector<std::string>& arguments, const py::object& progress,
              bool eventsAsArrays, std::size_t maxEvents, bool discardEvents, bool keepMap,
              const py::object& resultType, bool keepFiles) {
  QStringList commandLine{QStringLiteral("grazelab")};
  for (const std::string& argument : arguments) commandLine << QString::fromStdString(argument);

  MemoryStream output;
  MemoryStream messages;
  std::stop_source stop;
  auto table = std::make_unique<EventTable>();
  table->maxRows = maxEvents;
  table->whenFull = [&stop] { stop.request_stop(); };
  ProgressMailbox mailbox;
  grazelab::cli::Io io;
  io.out = output.file();
  io.messages = messages.file();
  table->discard = discardEvents;
  if (eventsAsArrays || discardEvents) io.events = table.get();
  grazelab::cli::map::StoredMap map;
  if (keepMap) io.map = &map;
  grazelab::cli::JsonValue document;
  std::vector<grazelab::core::Sample> samples;
  if (!resultType.is_none()) {
    io.document = &document;
    io.samples = &samples;
  }
  std::vector<std::pair<std::string, std::string>> files;
  if (keepFiles) io.files = &files;
  if (!progress.is_none()) {
    io.progress = [&mailbox](double fraction, const std::string& text) {
      std::lock_guard lock(mailbox.mutex);
      mailbox.fresh = true;
      mailbox.fraction = fraction;
      mailbox.text = text;
    };
  }

  std::mutex doneMutex;
  std::condition_variable doneSignal;
  bool done = false;
  int code = 0;
  std::optional<py::error_already_set> pythonError;
  std::exception_ptr failure;
  {
    py::gil_scoped_release released;
    std::thread worker([&] {
      try {
        code = grazelab::cli::runCommandLine(commandLine, io, stop.get_token());
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
      if (stop.stop_requested()) continue;  // stopping: wait for the command to end
      py::gil_scoped_acquire held;
      // Ctrl+C (or another signal handler that raised): stop the command, raise once it ended
      if (PyErr_CheckSignals() != 0) {
        pythonError.emplace();
        stop.request_stop();
        continue;
      }
      if (!deliverProgress(mailbox, progress, pythonError)) stop.request_stop();
    }
    worker.join();
  }
  // the last progress (a command shorter than one wake-up reports its end too)
  if (!pythonError && code == 0) deliverProgress(mailbox, progress, pythonError);
  if (pythonError) throw std::move(*pythonError);
  if (failure) std::rethrow_exception(failure);
  if (table->full) throw py::value_error(tooManyEvents(maxEvents));
  const std::string out = output.take();
  const std::string log = messages.take();
  py::object events = py::none();
  py::object decimals = py::none();
  if (eventsAsArrays && !discardEvents) {
    if (!table->decimals.empty()) decimals = py::cast(table->decimals);
    events = eventArray(std::move(table));
  }
  py::object mapResult = py::none();
  if (keepMap && code == 0) mapResult = mapInMemory(std::move(map));
  py::object documentResult = py::none();
  if (!resultType.is_none() && code == 0) {
    documentResult = documentToPython(document, resultType, document.holdsWideNumbers(), std::move(samples));
  }
  py::object filesResult = py::none();
  if (keepFiles && code == 0) {
    py::dict named;
    for (const auto& [name, bytes] : files) named[py::str(name)] = py::bytes(bytes);
    filesResult = std::move(named);
  }
  return py::make_tuple(code, py::bytes(out), py::str(log), events, decimals, mapResult,
                        documentResult, filesResult);
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

// The notes among a command's messages: each line "grazelab-cli: note: TEXT" as TEXT.
py::list notesOf(const std::string& messages) {
  static constexpr std::string_view kNote = "grazelab-cli: note: ";
  py::list notes;
  std::size_t at = 0;
  while (at < messages.size()) {
    std::size_t end = messages.find('\n', at);
    if (end == std::string::npos) end = messages.size();
    const std::string_view line(messages.data() + at, end - at);
    if (line.substr(0, kNote.size()) == kNote) notes.append(py::str(std::string(line.substr(kNote.size()))));
    at = end + 1;
  }
  return notes;
}

// simulate(options, result_type, events, max_events, discard_events)
//   -> (result with its events and notes, decimals), or None when an option's value is not of a
//      type read directly (then give the options as text)
// `grazelab-cli simulate` on the calling thread, its options given by name as (name, value,
// name, value, ...) with None for an option not given: no command-line text, no parser, no thread (a short
// run, which the caller keeps short: nothing interrupts it), its document handed over as values,
// not as text. The numbers are read as the command line reads their shortest decimal text.
py::object simulateHere(const py::sequence& given, const py::object& resultType, bool eventsAsArrays,
                        std::size_t maxEvents, bool discardEvents) {
  std::vector<grazelab::cli::GivenOption> named;
  const py::object flat = py::reinterpret_steal<py::object>(PySequence_Fast(given.ptr(), "options"));
  if (!flat) throw py::error_already_set();
  const Py_ssize_t count = PySequence_Fast_GET_SIZE(flat.ptr());
  if (count % 2 != 0) throw py::type_error("simulate: options are name, value, name, value, ...");
  named.reserve(std::size_t(count / 2));
  for (Py_ssize_t i = 0; i < count; i += 2) {
    PyObject* key = PySequence_Fast_GET_ITEM(flat.ptr(), i);
    PyObject* value = PySequence_Fast_GET_ITEM(flat.ptr(), i + 1);
    if (!PyUnicode_Check(key)) throw py::type_error("simulate: options are name, value, name, value, ...");
    if (value == Py_None) continue;
    grazelab::cli::GivenOption option;
    Py_ssize_t size = 0;
    const char* name = PyUnicode_AsUTF8AndSize(key, &size);
    if (!name) throw py::error_already_set();
    option.name.assign(name, std::size_t(size));
    // a sequence only where one is expected: elsewhere the text path says what is wrong
    const bool sequence = PyTuple_Check(value) || PyList_Check(value);
    if (sequence && option.name != "state" && option.name != "perturb") return py::none();
    if (!readGiven(value, option)) return py::none();
    named.push_back(std::move(option));
  }
  const grazelab::cli::OptionValues options(std::move(named));
  QString error;
  const auto precision = grazelab::cli::parsePrecisionOption(options, error);
  if (!precision) throw py::value_error(error.simplified().toStdString());
  const auto trust = grazelab::cli::parseTrustOption(options, error);
  if (!trust) throw py::value_error(error.simplified().toStdString());

  MemoryStream messages;
  auto table = std::make_unique<EventTable>();
  table->maxRows = maxEvents;
  table->discard = discardEvents;
  grazelab::cli::Io io;
  io.out = messages.file();  // (a run whose document is taken as values writes no output)
  io.messages = messages.file();
  if (eventsAsArrays || discardEvents) io.events = table.get();
  grazelab::cli::JsonValue document;
  io.document = &document;
  std::vector<grazelab::core::Sample> samples;
  io.samples = &samples;
  int code = 0;
  {
    py::gil_scoped_release released;
    code = grazelab::cli::runSimulate(options, *precision, *trust, io, std::stop_token{}, error);
  }
  if (code == grazelab::cli::kExitInvalidInput) throw py::value_error(error.simplified().toStdString());
  if (table->full) throw py::value_error(tooManyEvents(maxEvents));
  const std::string log = messages.take();
  if (code != 0) {
    PyErr_SetString(PyExc_OSError, error.isEmpty() ? ("simulate failed (exit " + std::to_string(code) + ")").c_str()
                                                   : error.simplified().toStdString().c_str());
    throw py::error_already_set();
  }
  py::object events = py::none();
  py::object decimals = py::none();
  if (eventsAsArrays && !discardEvents) {
    if (!table->decimals.empty()) decimals = py::cast(table->decimals);
    events = eventArray(std::move(table));
  }
  py::object result = documentToPython(document, resultType, document.holdsWideNumbers(), std::move(samples));
  // (names made once: a short run's call is a few microseconds)
  static PyObject* const eventsKey = PyUnicode_InternFromString("events");
  static PyObject* const notesKey = PyUnicode_InternFromString("notes");
  if (PyDict_SetItem(result.ptr(), eventsKey, events.ptr()) != 0 ||
      PyDict_SetItem(result.ptr(), notesKey, notesOf(log).ptr()) != 0) {
    throw py::error_already_set();
  }
  return py::make_tuple(result, decimals);
}

}  // namespace

PYBIND11_MODULE(_native, module) {
  module.doc() = "GrazeLab's command line, run in process (use the grazelab package).";
  // set once here, before any thread reads it (the files' "generator" field)
  QCoreApplication::setApplicationName(QStringLiteral("grazelab-cli"));
  QCoreApplication::setApplicationVersion(QString::fromUtf8(grazelab::cli::kVersion));
  module.attr("version") = grazelab::cli::kVersion;
  // (deliberately never freed: a dtype released after the interpreter's end would crash it)
  numpyTypes = new NumpyTypes{eventDtype(), sampleDtype()};
  module.def("run", &run, py::arg("arguments"), py::arg("progress") = py::none(),
             py::arg("events") = false, py::arg("max_events") = std::size_t(-1),
             py::arg("discard_events") = false, py::arg("keep_map") = false,
             py::arg("result_type") = py::none(), py::arg("keep_files") = false,
             "Runs one grazelab-cli command line (without the program's name) in this process. "
             "Returns (exit code, output bytes, messages, events array or None, the events' "
             "decimal text or None, map or None); raises ValueError when the run makes more "
             "than max_events events. With discard_events a simulate keeps no event anywhere "
             "(statistics only); with keep_map a map or merge hands back (its JSON document, "
             "its points as a structured array) and writes files only where --out says; with "
             "result_type a simulate's document comes back as values of that type, not text; "
             "with keep_files family and modes without --out hand their files back as "
             "{name: bytes} and write none.");
  module.def("simulate", &simulateHere, py::arg("options"), py::arg("result_type"),
             py::arg("events") = true, py::arg("max_events") = std::size_t(-1),
             py::arg("discard_events") = false,
             "grazelab-cli simulate on the calling thread, its options as (name, value, name, "
             "value, ...) (a value str, float, int or a tuple of numbers; None: not given): (result with "
             "its events and notes, the events' decimal text or None), or None when a value is "
             "of another type (give the options as text). A short run only: nothing "
             "interrupts it.");
}
