// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "value_to_python.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace grazelab::python {

namespace py = pybind11;

namespace {

// A field's name as a Python str. A name of the code (a literal) is made once and kept, by its
// address: a str made once keeps its hash, so a dict insert costs a pointer comparison (a short
// run's document has ~50 names: made afresh they took ~3 of its ~20 µs). The GIL, held here,
// guards the table; never freed (strs released after the interpreter's end would crash it).
PyObject* keyObject(const cli::JsonKey& key) {
  const std::string_view name = key.view();
  const auto make = [&] { return PyUnicode_FromStringAndSize(name.data(), static_cast<Py_ssize_t>(name.size())); };
  if (!key.literal()) return make();
  // open addressing on the literal's address: the code has a few hundred names
  struct Slot {
    const char* literal;
    PyObject* name;
  };
  constexpr std::size_t kSlots = 4096;
  static auto* slots = new Slot[kSlots]();
  const auto address = reinterpret_cast<std::uintptr_t>(key.literal());
  std::size_t at = static_cast<std::size_t>((address >> 3) * 0x9E3779B97F4A7C15ULL >> 52);  // 12 bits
  for (std::size_t probe = 0; probe < 64; ++probe, at = (at + 1) % kSlots) {
    Slot& slot = slots[at];
    if (slot.literal == key.literal()) {
      Py_INCREF(slot.name);
      return slot.name;
    }
    if (slot.literal) continue;
    PyObject* made = make();
    if (!made) return nullptr;
    Py_INCREF(made);  // the table's reference
    slot = {key.literal(), made};
    return made;
  }
  return make();  // a crowded neighbourhood: made afresh
}

// A new reference from the C API as an object; the Python error it set when there is none.
py::object owned(PyObject* made) {
  if (!made) throw py::error_already_set();
  return py::reinterpret_steal<py::object>(made);
}

}  // namespace

py::object toPython(const cli::JsonValue& value, const py::handle& objectType, bool numbersAsText) {
  using Kind = cli::JsonValue::Kind;
  switch (value.kind) {
    case Kind::Null: return py::none();
    case Kind::Bool: return py::reinterpret_borrow<py::object>(value.boolean ? Py_True : Py_False);
    case Kind::Integer:
      if (numbersAsText) return py::str(std::to_string(value.integer));
      return owned(PyLong_FromLongLong(value.integer));
    case Kind::Number:
      if (numbersAsText) return py::str(value.numberText());
      return owned(PyFloat_FromDouble(value.value));
    case Kind::String: return py::str(value.text);
    case Kind::Array: {
      py::list items(value.items.size());
      for (std::size_t i = 0; i < value.items.size(); ++i) {
        items[i] = toPython(value.items[i], objectType, numbersAsText);
      }
      return items;
    }
    case Kind::Object: {
      // the C API directly (a document is ~70 objects, and a short run costs a few microseconds):
      // the type's tp_new, as calling the type would, without the call's own work (objectType
      // is a dict subclass that defines neither __new__ nor __init__)
      auto* type = reinterpret_cast<PyTypeObject*>(objectType.ptr());
      static PyObject* const noArguments = PyTuple_New(0);  // (kept to the process's end)
      const py::object object = owned(type->tp_new(type, noArguments, nullptr));
      for (const auto& [key, field] : value.fields) {
        const py::object item = toPython(field, objectType, numbersAsText);
        const py::object name = owned(keyObject(key));
        if (PyDict_SetItem(object.ptr(), name.ptr(), item.ptr()) != 0) throw py::error_already_set();
      }
      return object;
    }
  }
  return py::none();
}

}  // namespace grazelab::python
