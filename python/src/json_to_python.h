// python/src/json_to_python.h — a JSON value (relgeo/io/json.h) as the Python
// object json.loads would give, so reports the tool prints as JSON reach
// Python by the same code (io::solid_report_json...), never restated.
#pragma once

#include <pybind11/pybind11.h>

#include "relgeo/io/json.h"

namespace relgeo::python {

pybind11::object json_to_python(const io::Json& j);

}  // namespace relgeo::python
