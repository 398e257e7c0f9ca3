// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <pybind11/pybind11.h>

#include <cstdint>
#include <initializer_list>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/numbers/scalar.h"
#include "io/json_value.h"

namespace grazelab::python {

/// A command's document as Python objects, each object an instance of `objectType` (dict, or a
/// dict subclass that defines neither __new__ nor __init__: grazelab.Result). Numbers are floats and counts ints; with `numbersAsText` both are
/// their decimal text instead, in the run's precision (what `decimal` holds for long and quad).
pybind11::object toPython(const cli::JsonValue& value, const pybind11::handle& objectType,
                          bool numbersAsText = false);

/// A document's value made a Python object as the document is built: the value type V of the
/// documents written once for every face (io/document_values.h, commands/simulation_document.h),
/// with JsonValue's factories. Numbers are floats (a value wider than double rounded: a document
/// in long double or binary128 goes through JsonValue, which keeps their text), counts ints, names
/// strs made once, objects instances of the type ObjectType names. Made with the GIL held.
class PyValue {
 public:
  using Field = std::pair<cli::JsonKey, PyValue>;
  /// {name, value} in a braced list (moved from, like JsonMember)
  struct Member {
    Member(cli::JsonKey name, PyValue&& v) : key(std::move(name)), value(&v) {}
    cli::JsonKey key;
    PyValue* value;
  };
  struct Item {
    Item(PyValue&& v) : value(&v) {}  // NOLINT(google-explicit-constructor)
    PyValue* value;
  };
  /// While it lives, objects are made as instances of `type` (a dict subclass that defines
  /// neither __new__ nor __init__: grazelab.Result), else plain dicts.
  class ObjectType {
   public:
    explicit ObjectType(const pybind11::handle& type);
    ~ObjectType();
    ObjectType(const ObjectType&) = delete;
    ObjectType& operator=(const ObjectType&) = delete;

   private:
    PyTypeObject* m_before;
  };

  /// While it lives, the sections of a run's document that are its chain's own
  /// (cli::values::chainSection: the chain, the note's model) are kept for `chain` (the prepared
  /// chain the run is of, alive while the scope is), on this thread: made once, then copied.
  class ChainScope {
   public:
    explicit ChainScope(std::weak_ptr<const void> chain);
    ~ChainScope();
    ChainScope(const ChainScope&) = delete;
    ChainScope& operator=(const ChainScope&) = delete;

   private:
    std::weak_ptr<const void> m_chain;
    const ChainScope* m_before;
    friend class PyValue;
  };

  /// The section `name` of the scope's chain in its precision `ready`, in `variant`: a copy of the
  /// one kept (its dicts and lists new: a result's sections are its own to change), else `make()`
  /// (kept as a copy when a ChainScope lives).
  template <typename Make>
  static PyValue chainSection(const char* name, const void* ready, const std::string& variant, Make& make) {
    if (PyObject* copy = keptSection(name, ready, variant)) return PyValue(copy);
    PyValue made = make();
    keepSection(name, ready, variant, made.m_object.ptr());
    return made;
  }

  static PyValue null();
  static PyValue of(bool value);
  static PyValue of(std::int64_t value);
  static PyValue of(const std::string& text);
  static PyValue of(const char* text);
  template <typename S>
  static PyValue number(const S& value) {
    if (!core::isFinite(value)) return null();
    return PyValue(PyFloat_FromDouble(core::toDouble(value)));
  }
  static PyValue array(std::vector<PyValue> items);
  static PyValue array(std::initializer_list<Item> items);
  static PyValue object(std::vector<Field> fields);
  static PyValue object(std::initializer_list<Member> members);
  /// Sets an object's field (replaced where it is, else added at the end).
  void set(const cli::JsonKey& key, PyValue value);

  /// The object made.
  pybind11::object take() && { return std::move(m_object); }

 private:
  explicit PyValue(PyObject* made);  // a new reference; the Python error it set when null
  // a new copy of the section kept for the scope's chain, else null
  static PyObject* keptSection(const char* name, const void* ready, const std::string& variant);
  // keeps a copy of `section` for the scope's chain (none without a scope)
  static void keepSection(const char* name, const void* ready, const std::string& variant, PyObject* section);
  PyValue() = default;
  pybind11::object m_object;
};

}  // namespace grazelab::python
