// python/src/json_to_python.h — a JSON value (relgeo/io/json.h) as the Python
// object json.loads would give, so reports the tool prints as JSON reach
// Python by the same code (io::solid_report_json...), never restated.
#pragma once

#include <pybind11/pybind11.h>

#include "relgeo/io/json.h"

namespace relgeo::python {

/// Objects, arrays, numbers, booleans and null as json.loads gives them;
/// coordinates (io::json_coordinate) as the floats the JSON text holds, and
/// infinite measures (io::json_measure's "inf", "-inf") as float infinities.
pybind11::object json_to_python(const io::Json& j);

}  // namespace relgeo::python
