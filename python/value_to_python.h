// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <pybind11/pybind11.h>

#include "io/json_value.h"

namespace grazelab::python {

/// A command's document as Python objects, each object an instance of `objectType` (dict, or a
/// dict subclass that defines neither __new__ nor __init__: grazelab.Result). Numbers are floats and counts ints; with `numbersAsText` both are
/// their decimal text instead, in the run's precision (what `decimal` holds for long and quad).
pybind11::object toPython(const cli::JsonValue& value, const pybind11::handle& objectType,
                          bool numbersAsText = false);

}  // namespace grazelab::python
