// tools/relgeo/commands/orient_grid/report.h — sign tallies as the tool
// reports them (orient-grid and the experiment's kernels section).
#pragma once

#include <string>
#include <vector>

#include "cli/text.h"
#include "relgeo/analysis/sign_tally.h"
#include "relgeo/io/json.h"

namespace relgeo::tool {

/// Adds the counts of a tally to a JSON record: `cases_key` ("cases" or
/// "cells"), wrong, plus_to_zero, minus_to_zero, zero_to_sign, inversions,
/// uncertain, correct.
void add_tally_json(io::Json& j, const analysis::Sign_tally& t, const char* cases_key);

/// The columns wrong .. correct of a tally table, the wrong count flagged
/// with " !" when a certified kernel has any.
std::vector<std::string> tally_cells(const analysis::Sign_tally& t, bool certified);
/// Their header: wrong, plus_to_zero, minus_to_zero, zero_to_sign, inversions, uncertain, correct.
std::vector<std::string> tally_header();

}  // namespace relgeo::tool
