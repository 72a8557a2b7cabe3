// tools/relgeo/commands/experiment/html_report.h — DIR/index.html, the page a
// person opens after `relgeo experiment`: run facts, the headline figures of
// every section first, then each section's notes, tables and pictures.
// Self-contained: inline style, pictures by relative links (readable from
// the file system, without a server). A script at the end records in the
// page whether every picture loaded (#image-check: data-total, data-loaded),
// which the browser test reads.
#pragma once

#include <string>
#include <vector>

#include "experiment/section.h"

namespace relgeo::tool {

struct Html_run {
  bool quick = false;
  std::size_t workload_size = 0;
  double time_s = 0;
  std::vector<std::string> failures;
};

struct Html_section {
  std::string name, summary;
  double time_s = 0;
  Section_report report;
};

/// The whole page.
std::string html_report(const Html_run& run, const std::vector<Html_section>& sections);

}  // namespace relgeo::tool
