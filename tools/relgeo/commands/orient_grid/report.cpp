// tools/relgeo/commands/orient_grid/report.cpp
#include "commands/orient_grid/report.h"

namespace relgeo::tool {

void add_tally_json(io::Json& j, const analysis::Sign_tally& t, const char* cases_key) {
  j.update(io::Json{{cases_key, t.cases},
                    {"wrong", t.wrong()},
                    {"plus_to_zero", t.plus_to_zero},
                    {"minus_to_zero", t.minus_to_zero},
                    {"zero_to_sign", t.zero_to_sign},
                    {"inversions", t.inversions},
                    {"uncertain", t.uncertain},
                    {"correct", t.correct}});
}

std::vector<std::string> tally_header() {
  return {"wrong", "plus_to_zero", "minus_to_zero", "zero_to_sign", "inversions", "uncertain", "correct"};
}

std::vector<std::string> tally_cells(const analysis::Sign_tally& t, bool certified) {
  return {std::to_string(t.wrong()) + (certified && t.wrong() > 0 ? " !" : ""),
          std::to_string(t.plus_to_zero), std::to_string(t.minus_to_zero), std::to_string(t.zero_to_sign),
          std::to_string(t.inversions),   std::to_string(t.uncertain),     std::to_string(t.correct)};
}

}  // namespace relgeo::tool
