// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "value_to_python.h"

#include <algorithm>
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

// A new copy of `value` whose dicts (of their own type) and lists are new, their numbers and
// strings shared (they cannot change): a dict is cloned whole by PyDict_Update into an empty one
py::object copied(PyObject* value) {
  if (PyDict_Check(value)) {
    const py::object copy = newObject(Py_TYPE(value));
    if (PyDict_Update(copy.ptr(), value) != 0) throw py::error_already_set();
    Py_ssize_t at = 0;
    PyObject* key = nullptr;
    PyObject* item = nullptr;
    while (PyDict_Next(value, &at, &key, &item)) {
      if (!PyDict_Check(item) && !PyList_Check(item)) continue;
      const py::object inner = copied(item);
      if (PyDict_SetItem(copy.ptr(), key, inner.ptr()) != 0) throw py::error_already_set();  // (in place)
    }
    return copy;
  }
  if (PyList_Check(value)) {
    const Py_ssize_t size = PyList_GET_SIZE(value);
    const py::object copy = owned(PyList_New(size));
    for (Py_ssize_t i = 0; i < size; ++i) PyList_SET_ITEM(copy.ptr(), i, copied(PyList_GET_ITEM(value, i)).release().ptr());
    return copy;
  }
  return py::reinterpret_borrow<py::object>(value);
}

// The sections kept for chains (PyValue::chainSection), the GIL their guard, never freed (as the
// names above). A chain is told by its owner (a weak pointer: an entry of a chain gone is never
// taken for another chain, whose owner differs even at the same address), its precision by the
// address of its ready chain in that owner, a section by the address of its name's literal (the
// same name written twice at two addresses is at worst made again).
struct KeptSection {
  std::weak_ptr<const void> chain;
  const char* name = nullptr;
  const void* ready = nullptr;
  std::string variant;
  PyObject* section = nullptr;  // (a reference of the table's)
};
constexpr std::size_t kKeptSections = 64;
std::vector<KeptSection>& keptSections() {
  static auto* const kept = new std::vector<KeptSection>();
  return *kept;
}
std::size_t nextReplaced = 0;

thread_local const PyValue::ChainScope* chainScopeNow = nullptr;

bool sameOwner(const std::weak_ptr<const void>& a, const std::weak_ptr<const void>& b) {
  return !a.owner_before(b) && !b.owner_before(a);
}

}  // namespace

PyValue::ChainScope::ChainScope(std::weak_ptr<const void> chain) : m_chain(std::move(chain)), m_before(chainScopeNow) {
  chainScopeNow = this;
}
PyValue::ChainScope::~ChainScope() { chainScopeNow = m_before; }

PyObject* PyValue::keptSection(const char* name, const void* ready, const std::string& variant) {
  if (!chainScopeNow) return nullptr;
  for (const KeptSection& kept : keptSections()) {
    // (the objects' type too: a copy is of the type its section was made in)
    if (kept.name == name && kept.ready == ready && sameOwner(kept.chain, chainScopeNow->m_chain) &&
        !kept.chain.expired() && kept.variant == variant && Py_TYPE(kept.section) == objectTypeNow) {
      // (held while copied: the copy's allocations may run a finalizer that changes the table)
      const py::object held = py::reinterpret_borrow<py::object>(kept.section);
      return copied(held.ptr()).release().ptr();
    }
  }
  return nullptr;
}

void PyValue::keepSection(const char* name, const void* ready, const std::string& variant, PyObject* section) {
  if (!chainScopeNow || chainScopeNow->m_chain.expired()) return;
  KeptSection entry{chainScopeNow->m_chain, name, ready, variant, copied(section).release().ptr()};
  // (the table looked at after the copy, whose allocations may run Python code that changes it)
  std::vector<KeptSection>& kept = keptSections();
  // in the place of the same section kept already, or of an entry of a chain gone, else at the
  // end, else in turn
  auto place = std::find_if(kept.begin(), kept.end(), [&](const KeptSection& old) {
    return old.chain.expired() || (old.name == name && old.ready == ready && old.variant == variant &&
                                    sameOwner(old.chain, entry.chain));
  });
  if (place == kept.end() && kept.size() < kKeptSections) {
    kept.push_back(std::move(entry));
    return;
  }
  if (place == kept.end()) place = kept.begin() + std::ptrdiff_t(nextReplaced++ % kKeptSections);
  // (the old section released once the table holds the new one: its finalizers may run)
  std::swap(*place, entry);
  Py_DECREF(entry.section);
}

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
