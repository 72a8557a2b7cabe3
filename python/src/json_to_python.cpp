// python/src/json_to_python.cpp — JSON values as Python objects.
#include "json_to_python.h"

#include <string>

namespace relgeo::python {

namespace py = pybind11;

py::object json_to_python(const io::Json& j) {
  switch (j.type()) {
    case io::Json::value_t::null:
      return py::none();
    case io::Json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case io::Json::value_t::number_integer:
      return py::int_(j.get<std::int64_t>());
    case io::Json::value_t::number_unsigned:
      return py::int_(j.get<std::uint64_t>());
    case io::Json::value_t::number_float:
      return py::float_(j.get<double>());
    case io::Json::value_t::string: {
      // A coordinate (io::json_coordinate) is a number written with 17 digits, as in the JSON text.
      const auto& text = j.get_ref<const std::string&>();
      if (text.starts_with(io::internal::coordinate_tag))
        return py::float_(std::stod(text.substr(io::internal::coordinate_tag.size())));
      // An infinite measure (io::json_measure): no other string of a report is "inf".
      if (text == "inf" || text == "-inf") return py::float_(std::stod(text));
      return py::str(text);
    }
    case io::Json::value_t::array: {
      py::list out;
      for (const io::Json& v : j) out.append(json_to_python(v));
      return out;
    }
    case io::Json::value_t::object: {
      py::dict out;
      for (const auto& [key, v] : j.items()) out[py::str(key)] = json_to_python(v);
      return out;
    }
    default:  // binary, discarded: never in relgeo's reports
      return py::none();
  }
}

}  // namespace relgeo::python
