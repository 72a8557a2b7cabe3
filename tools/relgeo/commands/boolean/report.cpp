// tools/relgeo/commands/boolean/report.cpp
#include "commands/boolean/report.h"

#include <cstdio>
#include <sstream>

#include "relgeo/io/solid_report_json.h"

namespace relgeo::tool {

io::Json operand_json(const std::string& file, const Mesh_double& m) {
  double v = 0;
  for (const auto& f : m.faces) {
    const auto &p = m.vertices[f[0]], &q = m.vertices[f[1]], &r = m.vertices[f[2]];
    v += p.x * (q.y * r.z - q.z * r.y) - p.y * (q.x * r.z - q.z * r.x) + p.z * (q.x * r.y - q.y * r.x);
  }
  return {{"file", file}, {"vertices", m.vertices.size()}, {"faces", m.faces.size()}, {"volume", io::json_measure(v / 6)}};
}

io::Json rounding_repair_json(const Rounding_repair_report& r, const std::string& method) {
  return {{"method", method},
          {"rounds", r.rounds},
          {"defects_before", r.defects_before},
          {"moved_vertices", r.moved_vertices},
          {"flips", r.flips},
          {"collapses", r.collapses},
          {"largest_change", io::json_measure(r.largest_change)},
          {"remaining_pairs", r.remaining_pairs.size()},
          {"remaining_degenerate_faces", r.remaining_degenerate_faces.size()}};
}

io::Json boolean_timing_json(const Boolean_timing& t) {
  return {{"check", t.check},
          {"broad_phase", t.broad_phase},
          {"narrow_phase", t.narrow_phase},
          {"retriangulation", t.retriangulation},
          {"labelling", t.labelling},
          {"assembly", t.assembly},
          {"rounding", t.rounding}};
}

io::Json boolean_report_json(const Boolean_report_input& in) {
  const Boolean_run& r = *in.run;
  const double volume = r.validation.volume.value;
  io::Json j;
  put_run_header(j, in.operation, r);
  io::Json pairs = io::Json::array();
  for (std::size_t i = 0; i < r.undecided_pairs.size() && i < 100; ++i)
    pairs.push_back({r.undecided_pairs[i].first, r.undecided_pairs[i].second});
  io::Json time_s = boolean_timing_json(r.time);
  time_s.update(io::Json{{"total", r.time.total()}, {"validation", r.time.validation}});
  j.update(io::Json{{"undecided_pairs", pairs},
                    {"operands", {{"a", operand_json(in.input_a, *in.a)}, {"b", operand_json(in.input_b, *in.b)}}},
                    {"output",
                     {{"vertices", r.mesh.vertices.size()},
                      {"faces", r.mesh.faces.size()},
                      {"creases", r.mesh.tags.creases().size()}}},
                    {"validation", r.ok() ? io::solid_report_json(r.validation) : io::Json(nullptr)},
                    {"exact_self_intersecting_pairs",
                     r.exact_self_intersecting_pairs ? io::Json(*r.exact_self_intersecting_pairs) : io::Json(nullptr)},
                    {"rounding_error", io::json_measure(r.rounding_error)},
                    {"rounding", rounding_repair_json(r.rounding, r.rounding_method)},
                    {"counts",
                     {{"candidate_pairs", r.counts.candidate_pairs},
                      {"intersecting_pairs", r.counts.intersecting_pairs},
                      {"coplanar_pairs", r.counts.coplanar_pairs},
                      {"new_vertices", r.counts.new_vertices},
                      {"split_faces", r.counts.split_faces},
                      {"patches", r.counts.patches},
                      {"unchanged_certified_faces", r.counts.unchanged_certified_faces}}},
                    {"time_s", time_s}});
  if (in.oracle) {
    const Oracle_comparison& o = *in.oracle;
    j["oracle"] = {{"cgal_ok", o.cgal_ok},
                   {"cgal_volume", io::json_measure(o.cgal_volume)},
                   {"cgal_faces", o.cgal_faces},
                   {"volume_difference", io::json_measure(volume - o.cgal_volume)},
                   {"symmetric_difference_volume",
                    o.symmetric_difference_volume ? io::json_measure(*o.symmetric_difference_volume) : io::Json(nullptr)},
                   {"hausdorff", io::json_measure(o.hausdorff)}};
  }
  return j;
}

std::string boolean_report_text(const Boolean_report_input& in) {
  const Boolean_run& r = *in.run;
  std::ostringstream s;
  char buf[256];
  s << "operation        " << in.operation << " of " << in.input_a << " (" << in.a->faces.size() << " faces) and "
    << in.input_b << " (" << in.b->faces.size() << " faces)\n";
  s << "kernel           " << r.kernel << (r.certified ? " (certified)" : " (naive: answers may be wrong)") << "\n";
  s << "status           " << (r.ok() ? "ok" : "failed: " + r.failure) << "\n";
  if (!r.undecided_pairs.empty()) s << "undecided pairs  " << r.undecided_pairs.size() << "\n";
  s << "output           " << r.mesh.vertices.size() << " vertices, " << r.mesh.faces.size() << " faces, "
    << r.mesh.tags.creases().size() << " crease edges (the intersection curves)\n";
  const Solid_report& v = r.validation;
  if (r.ok()) {
    std::snprintf(buf, sizeof buf, "%.17g", v.volume.value);
    s << "volume           " << buf << "\n";
    s << "validation       " << v.summary() << "\n";
    if (!v.self_intersection_free.passed() && r.exact_self_intersecting_pairs)
      s << "                 before rounding: " << *r.exact_self_intersecting_pairs << " self-intersecting pairs\n";
    if (v.euler_characteristic)
      s << "euler, components " << *v.euler_characteristic << ", " << v.components << "\n";
  }
  std::snprintf(buf, sizeof buf, "%.3g", r.rounding_error);
  s << "rounding error   " << buf << " (largest move of a new vertex to doubles)\n";
  if (r.rounding.rounds > 0) {
    std::snprintf(buf, sizeof buf, "%.3g", r.rounding.largest_change);
    s << "rounding repair  " << r.rounding.defects_before << " defects after nearest rounding; " << r.rounding.moved_vertices
      << " vertices moved, " << r.rounding.flips << " flips, " << r.rounding.collapses << " collapses in "
      << r.rounding.rounds << " rounds (largest change " << buf << "); " << r.rounding.remaining_pairs.size()
      << " crossing pairs left\n";
  }
  s << "pairs            " << r.counts.candidate_pairs << " candidates, " << r.counts.intersecting_pairs << " intersecting ("
    << r.counts.coplanar_pairs << " coplanar); " << r.counts.new_vertices << " new vertices, " << r.counts.split_faces
    << " faces split, " << r.counts.patches << " patches; " << r.counts.unchanged_certified_faces
    << " output faces kept whole from a certified operand\n";
  std::snprintf(buf, sizeof buf,
                "%.4f s (check %.4f, broad %.4f, narrow %.4f, retriangulation %.4f, labelling %.4f, assembly %.4f, "
                "rounding %.4f)",
                r.time.total(), r.time.check, r.time.broad_phase, r.time.narrow_phase, r.time.retriangulation,
                r.time.labelling, r.time.assembly, r.time.rounding);
  s << "time             " << buf << "\n";
  if (in.oracle) {
    const Oracle_comparison& o = *in.oracle;
    if (!o.cgal_ok) s << "oracle           CGAL's corefinement failed\n";
    else {
      std::snprintf(buf, sizeof buf, "CGAL Epeck volume %.17g, |difference| %.3g, symmetric difference %s, Hausdorff %.3g",
                    o.cgal_volume, std::abs(r.validation.volume.value - o.cgal_volume),
                    o.symmetric_difference_volume ? std::to_string(*o.symmetric_difference_volume).c_str() : "n/a", o.hausdorff);
      s << "oracle           " << buf << "\n";
    }
  }
  return s.str();
}

}  // namespace relgeo::tool
