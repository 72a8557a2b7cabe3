// tools/relgeo/commands/boolean/names.cpp — the names of Boolean operations,
// output roundings and retriangulations as `boolean` and `csg` take them
// (no command line here: the Python module uses them too).
#include "cli/text.h"
#include "commands/boolean/facade.h"

namespace relgeo::tool {

Boolean_operation parse_boolean_operation(const std::string& name) {
  for (Boolean_operation op : {Boolean_operation::union_of, Boolean_operation::intersection,
                               Boolean_operation::difference, Boolean_operation::symmetric_difference})
    if (name == to_string(op)) return op;
  throw Usage_error("--op must be union, intersection, difference or xor (got '" + name + "')");
}

Output_rounding parse_output_rounding(const std::string& name) {
  if (name == "repaired") return Output_rounding::repaired;
  if (name == "nearest") return Output_rounding::nearest;
  throw Usage_error("--rounding must be repaired or nearest (got '" + name + "')");
}

bool parse_delaunay_retriangulation(const std::string& name) {
  if (name == "delaunay") return true;
  if (name == "insertion") return false;
  throw Usage_error("--retriangulation must be delaunay or insertion (got '" + name + "')");
}

}  // namespace relgeo::tool
