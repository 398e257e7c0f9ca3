// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "value_to_python.h"

#include <string>

namespace grazelab::python {

namespace py = pybind11;

py::object toPython(const cli::JsonValue& value, const py::handle& objectType, bool numbersAsText) {
  using Kind = cli::JsonValue::Kind;
  switch (value.kind) {
    case Kind::Null: return py::none();
    case Kind::Bool: return py::bool_(value.boolean);
    case Kind::Integer:
      if (numbersAsText) return py::str(std::to_string(value.integer));
      return py::int_(value.integer);
    case Kind::Number:
      if (numbersAsText) return py::str(value.numberText());
      return py::float_(value.value);
    case Kind::String: return py::str(value.text);
    case Kind::Array: {
      py::list items(value.items.size());
      for (std::size_t i = 0; i < value.items.size(); ++i) {
        items[i] = toPython(value.items[i], objectType, numbersAsText);
      }
      return items;
    }
    case Kind::Object: {
      py::object object = objectType();
      for (const auto& [key, field] : value.fields) {
        const py::object item = toPython(field, objectType, numbersAsText);
        // (not PyDict_SetItemString: it interns every key, a dict lookup of its own)
        const py::str name(key);
        if (PyDict_SetItem(object.ptr(), name.ptr(), item.ptr()) != 0) throw py::error_already_set();
      }
      return object;
    }
  }
  return py::none();
}

}  // namespace grazelab::python
