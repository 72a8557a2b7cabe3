// tools/relgeo/commands/experiment/html_report.cpp
#include "commands/experiment/html_report.h"

#include <algorithm>
#include <cctype>

#include "relgeo/io/xml_text.h"

namespace relgeo::tool {

namespace {

std::string escape(std::string_view s) { return io::xml_escape(s, io::Control_characters::keep); }

/// A relative link with the characters a URL must not carry raw encoded
/// (file names hold '^', '<', '>' and blanks).
std::string url(std::string_view path) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : path) {
    if (std::isalnum(c) || std::string_view("-_.~/").find(static_cast<char>(c)) != std::string_view::npos) {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out;
}

const char* const style = R"(
body { font-family: system-ui, sans-serif; margin: 2em auto; max-width: 1500px; padding: 0 1.5em; color: #222; }
h1 { margin-bottom: 0.2em; } h2 { border-bottom: 2px solid #ccc; padding-bottom: 0.2em; margin-top: 2em; }
.run { color: #555; } .failures { color: #b00020; font-weight: bold; }
.headlines { background: #f3f6fb; border: 1px solid #c9d6ea; border-radius: 6px; padding: 0.6em 1.2em; }
.headlines h3 { margin: 0.8em 0 0.2em; font-size: 1em; } .headlines li { margin: 0.15em 0; }
.headlines .value { font-weight: 600; font-variant-numeric: tabular-nums; }
nav a { margin-right: 1.2em; }
p.note { white-space: pre-line; line-height: 1.4; }
.scroll { overflow-x: auto; }
table { border-collapse: collapse; font-size: 0.85em; font-variant-numeric: tabular-nums; margin: 0.5em 0 1.5em; }
th, td { padding: 0.2em 0.6em; border-bottom: 1px solid #e3e3e3; text-align: right; white-space: nowrap; }
th { background: #f0f0f0; position: sticky; top: 0; } th.group { text-align: center; background: #e4e9f0; }
td.left, th.left { text-align: left; } tr.rule td { border-top: 2px solid #999; }
td.bad { color: #b00020; font-weight: 600; }
.gallery { display: flex; flex-wrap: wrap; gap: 0.8em; margin: 0.5em 0 1.5em; }
figure { margin: 0; width: 190px; } figure img { width: 190px; border: 1px solid #ddd; background: white; }
figcaption { font-size: 0.75em; color: #444; }
#image-check { color: #555; font-size: 0.85em; margin-top: 3em; }
)";

/// Checks, once everything loaded, that every picture has a size: the
/// result stays in the page (a person sees it; the browser test reads it).
const char* const image_check_script = R"(
window.addEventListener('load', function () {
  var images = Array.prototype.slice.call(document.images);
  var broken = images.filter(function (i) { return !(i.complete && i.naturalWidth > 0); });
  var note = document.getElementById('image-check');
  note.setAttribute('data-total', String(images.length));
  note.setAttribute('data-loaded', String(images.length - broken.length));
  note.textContent = (images.length - broken.length) + ' of ' + images.length + ' pictures loaded' +
      (broken.length ? '; missing: ' + broken.map(function (i) { return i.getAttribute('src'); }).join(', ') : '.');
});
)";

bool flagged(const std::string& cell) {
  return cell.find(" !") != std::string::npos || cell.rfind("FAILED", 0) == 0 || cell == "NO";
}

std::string table_html(const Text_table& t) {
  std::string h = "<div class=\"scroll\"><table>\n";
  const std::size_t left = std::max<std::size_t>(t.left_columns(), 1);
  if (!t.groups().empty()) {
    h += "<tr>";
    for (const auto& [label, span] : t.groups())
      h += "<th class=\"group\" colspan=\"" + std::to_string(span) + "\">" + escape(label) + "</th>";
    h += "</tr>\n";
  }
  h += "<tr>";
  for (std::size_t i = 0; i < t.header().size(); ++i)
    h += std::string(i < left ? "<th class=\"left\">" : "<th>") + escape(t.header()[i]) + "</th>";
  h += "</tr>\n";
  for (std::size_t r = 0; r < t.rows().size(); ++r) {
    const bool rule = r > 0 && std::find(t.rules().begin(), t.rules().end(), r) != t.rules().end();
    h += rule ? "<tr class=\"rule\">" : "<tr>";
    for (std::size_t i = 0; i < t.header().size(); ++i) {
      const std::string cell = i < t.rows()[r].size() ? t.rows()[r][i] : std::string();
      std::string cls = i < left ? "left" : "";
      if (flagged(cell)) cls += cls.empty() ? "bad" : " bad";
      h += (cls.empty() ? std::string("<td>") : "<td class=\"" + cls + "\">") + escape(cell) + "</td>";
    }
    h += "</tr>\n";
  }
  return h + "</table></div>\n";
}

std::string gallery_html(const Report_block& b) {
  std::string h = "<h3>" + escape(b.gallery_title) + "</h3>\n<div class=\"gallery\">\n";
  for (const Picture& p : b.pictures)
    h += "<figure><a href=\"" + url(p.file) + "\"><img src=\"" + url(p.file) + "\" alt=\"" + escape(p.caption) +
         "\"></a><figcaption>" + escape(p.caption) + "</figcaption></figure>\n";
  return h + "</div>\n";
}

std::string section_html(const Html_section& s) {
  std::string h = "<section id=\"" + escape(s.name) + "\">\n<h2>" + escape(s.name) + "</h2>\n<p>" + escape(s.summary) +
                  " <span class=\"run\">(" + format_fixed(s.time_s, 1) + " s; numbers in <a href=\"" + url(s.name) +
                  ".json\">" + escape(s.name) + ".json</a>)</span></p>\n";
  for (const auto& f : s.report.failures) h += "<p class=\"failures\">FAILURE: " + escape(f) + "</p>\n";
  for (const Report_block& b : s.report.blocks) {
    if (!b.note.empty()) h += "<p class=\"note\">" + escape(b.note) + "</p>\n";
    if (b.table) h += table_html(*b.table);
    if (!b.pictures.empty()) h += gallery_html(b);
  }
  return h + "</section>\n";
}

std::string headlines_html(const std::vector<Html_section>& sections) {
  std::string h = "<div class=\"headlines\">\n<h2 style=\"border: none; margin-top: 0.4em\">Headline figures</h2>\n";
  for (const Html_section& s : sections) {
    if (s.report.headlines.empty()) continue;
    h += "<h3><a href=\"#" + escape(s.name) + "\">" + escape(s.name) + "</a></h3>\n<ul>\n";
    for (const Headline& l : s.report.headlines)
      h += "<li>" + escape(l.label) + ": <span class=\"value\">" + escape(l.value) + "</span></li>\n";
    h += "</ul>\n";
  }
  return h + "</div>\n";
}

}  // namespace

std::string html_report(const Html_run& run, const std::vector<Html_section>& sections) {
  std::string h =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>relgeo experiment</title>\n"
      "<style>" + std::string(style) + "</style>\n</head>\n<body>\n<h1>relgeo experiment</h1>\n";
  std::string names;
  for (const auto& s : sections) names += (names.empty() ? "" : ", ") + s.name;
  h += "<p class=\"run\">Kernel comparison (thesis: <i>Reliable computation in geometric modeling</i>). Sections: " +
       escape(names) + "; " + (run.quick ? "quick run (--quick), " : "") + std::to_string(run.workload_size) +
       " cases per predicate workload; " + format_fixed(run.time_s, 1) + " s. The numbers are in experiment.json "
       "and the section files.</p>\n";
  if (run.failures.empty()) h += "<p class=\"run\">No failures.</p>\n";
  for (const auto& f : run.failures) h += "<p class=\"failures\">FAILURE: " + escape(f) + "</p>\n";
  h += headlines_html(sections);
  h += "<nav><p>";
  for (const auto& s : sections) h += "<a href=\"#" + escape(s.name) + "\">" + escape(s.name) + "</a>";
  h += "</p></nav>\n";
  for (const auto& s : sections) h += section_html(s);
  h += "<p id=\"image-check\">pictures not checked (JavaScript off)</p>\n<script>" + std::string(image_check_script) +
       "</script>\n</body>\n</html>\n";
  return h;
}

}  // namespace relgeo::tool
