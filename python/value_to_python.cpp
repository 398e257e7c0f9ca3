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

// A new instance of `type` (the C API directly: a document is ~70 objects, and a short run costs
// a few microseconds): the type's tp_new, as calling the type would, without the call's own work
py::object newObject(PyTypeObject* type) {
  static PyObject* const noArguments = PyTuple_New(0);  // (kept to the process's end)
  return owned(type->tp_new(type, noArguments, nullptr));
}

// the type PyValue makes objects of (PyValue::ObjectType), per thread: a finalizer run while a
// document is built may hand the GIL to another thread's call
thread_local PyTypeObject* objectTypeNow = &PyDict_Type;

}  // namespace

PyValue::PyValue(PyObject* made) : m_object(owned(made)) {}

PyValue::ObjectType::ObjectType(const py::handle& type) : m_before(objectTypeNow) {
  objectTypeNow = reinterpret_cast<PyTypeObject*>(type.ptr());
}
PyValue::ObjectType::~ObjectType() { objectTypeNow = m_before; }

PyValue PyValue::null() {
  PyValue value;
  value.m_object = py::none();
  return value;
}
PyValue PyValue::of(bool value) { return PyValue(PyBool_FromLong(value ? 1 : 0)); }
PyValue PyValue::of(std::int64_t value) { return PyValue(PyLong_FromLongLong(value)); }
PyValue PyValue::of(const std::string& text) {
  return PyValue(PyUnicode_FromStringAndSize(text.data(), static_cast<Py_ssize_t>(text.size())));
}
PyValue PyValue::of(const char* text) { return PyValue(PyUnicode_FromString(text)); }

PyValue PyValue::array(std::vector<PyValue> items) {
  PyValue list(PyList_New(static_cast<Py_ssize_t>(items.size())));
  for (std::size_t i = 0; i < items.size(); ++i) {
    PyList_SET_ITEM(list.m_object.ptr(), static_cast<Py_ssize_t>(i), items[i].m_object.release().ptr());
  }
  return list;
}
PyValue PyValue::array(std::initializer_list<Item> items) {
  PyValue list(PyList_New(static_cast<Py_ssize_t>(items.size())));
  Py_ssize_t i = 0;
  for (const Item& item : items) PyList_SET_ITEM(list.m_object.ptr(), i++, item.value->m_object.release().ptr());
  return list;
}

PyValue PyValue::object(std::vector<Field> fields) {
  PyValue object;
  object.m_object = newObject(objectTypeNow);
  for (Field& field : fields) object.set(field.first, std::move(field.second));
  return object;
}
PyValue PyValue::object(std::initializer_list<Member> members) {
  PyValue object;
  object.m_object = newObject(objectTypeNow);
  for (const Member& member : members) object.set(member.key, std::move(*member.value));
  return object;
}

void PyValue::set(const cli::JsonKey& key, PyValue value) {
  const py::object name = owned(keyObject(key));
  if (PyDict_SetItem(m_object.ptr(), name.ptr(), value.m_object.ptr()) != 0) throw py::error_already_set();
}

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
      // (objectType is a dict subclass that defines neither __new__ nor __init__)
      const py::object object = newObject(reinterpret_cast<PyTypeObject*>(objectType.ptr()));
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
