// tools/relgeo/experiment/extrusion.cpp — the "extrusion" section of `relgeo
// experiment` (thesis Sec. 3.4.1):
//  (1) a gallery of contours (circle-like cubic chains, the three classic
//      failures, a pinch below the uncertainty, a 3D contour) under
//      failsafe / graham-fortune: verdict and margins, with a picture each;
//  (2) every kernel and hull algorithm on a good and on bad contours:
//      verdict, uncertain answers, hull certificates, time;
//  (3) scaling: circle chains of M = 100 .. 10^5 curves, time and the pairs
//      the prune leaves, against the full quadratic check for small M.
// The section fails (exit 1) when a contour known to violate a condition is
// certified, or a well-formed circle chain is refused (by any kernel: the
// hull certificate is exact, so even naive kernels must never certify wrongly).
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "commands/extrusion/facade.h"
#include "commands/extrusion/report.h"
#include "commands/hull/facade.h"
#include "experiment/section.h"
#include "kernels/registry.h"
#include "relgeo_fixtures/curves/test_contours.h"

namespace relgeo::tool {

namespace {

using io::Json;

std::string extrusion_measure_text(double v) { return measure_text(v, 4); }

struct Case {
  std::string name;
  Bezier_contour contour;
  double uncertainty;     ///< relative
  double rotation_error;  ///< 3D input
  int expect;             ///< 1 must be certified, -1 must not be certified, 0 no expectation
};

std::string margin_text(const Extrusion_condition_summary& s) {
  if (s.problems == 0 && s.pruned == 0) return "-";
  return extrusion_measure_text(s.min_margin) + (s.min_margin_is_prune_bound ? " (>=)" : "");
}

/// The circle chain of M = 12 cubics placed on the plane d.x = 2 for d = (1, 2, 2)/3,
/// projected back with relgeo::project_along.
Case three_d_case() {
  const Bezier_contour planar = circle_contour(12, 5.0);
  const Point_3<double> d{1.0 / 3, 2.0 / 3, 2.0 / 3}, e1{2.0 / 3, -2.0 / 3, 1.0 / 3}, e2{2.0 / 3, 1.0 / 3, -2.0 / 3};
  std::vector<Point_3<double>> pts;
  for (std::size_t m = 0; m < planar.size(); ++m)
    for (std::size_t i = 0; i < 3; ++i) {
      const auto p = planar[m][i];
      pts.push_back({2 * d.x + p.x * e1.x + p.y * e2.x, 2 * d.y + p.x * e1.y + p.y * e2.y, 2 * d.z + p.x * e1.z + p.y * e2.z});
    }
  const Plane_projection proj = project_along(pts, {1, 2, 2});
  Bezier_contour c = Bezier_contour::from_chain(proj.points, 3);
  std::vector<std::vector<double>> scales(c.size());
  for (std::size_t m = 0; m < c.size(); ++m)
    for (std::size_t i = 0; i <= 3; ++i) scales[m].push_back(proj.norms[(3 * m + i) % proj.norms.size()]);
  c.set_scales(scales);
  return {"3d circle M=12, d=(1,2,2)/3", c, 1e-3, proj.rotation_error, 1};
}

/// The gallery: circle chains, the three classic failures, a pinch below the
/// uncertainty, a 3D contour.
std::vector<Case> gallery_cases() {
  std::vector<Case> gallery;
  for (std::size_t M : {4, 8, 16, 32, 64}) gallery.push_back({"circle M=" + std::to_string(M), circle_contour(M), 1e-3, 0, 1});
  gallery.push_back({"looped curve (M=8)", looped_circle_contour(8), 1e-3, 0, -1});
  gallery.push_back({"folded adjacent curves", folded_contour(), 1e-3, 0, -1});
  gallery.push_back({"bow tie (crossing curves)", bow_tie_contour(), 1e-3, 0, -1});
  gallery.push_back({"thin rectangle h=1e-4", thin_rectangle_contour(1e-4), 1e-3, 0, -1});
  gallery.push_back({"thin rectangle h=1e-4, delta=1e-6", thin_rectangle_contour(1e-4), 1e-6, 0, 1});
  gallery.push_back({"circle M=64, delta=0.1", circle_contour(64), 0.1, 0, -1});
  gallery.push_back(three_d_case());
  return gallery;
}

Extrusion_options options_of(const Case& c) {
  Extrusion_options o;
  o.relative_uncertainty = c.uncertainty;
  o.rotation_error = c.rotation_error;
  o.max_listed = 20;
  return o;
}

/// A failure when `who` refuses a well-formed contour or certifies a bad one.
void check_expectation(Section_report& rep, const Case& c, const std::string& who, const Extrusion_report& r) {
  if (c.expect > 0 && r.verdict == Extrusion_verdict::refused)
    rep.failures.push_back(c.name + ": a well-formed contour refused by " + who);
  if (c.expect < 0 && r.verdict == Extrusion_verdict::certified)
    rep.failures.push_back(c.name + ": certified by " + who + " although a condition fails or is not robust");
}

/// The first offending pair of a report, in a few words ("-" for none).
std::string worst_pair_text(const Extrusion_report& r) {
  if (r.offending.empty()) return "-";
  const auto& p = r.offending.front();
  return "cond " + std::to_string(static_cast<int>(p.condition)) + " " + std::string(p.set) + " (" +
         std::to_string(p.curve_a) + "," + std::to_string(p.curve_b) + ") " + std::string(to_string(p.verdict));
}

/// (1) The gallery under failsafe / graham-fortune: verdict and margins, a
/// picture each.
void gallery_part(const Experiment_context& ctx, const std::vector<Case>& gallery, Section_report& rep) {
  ctx.progress("gallery under failsafe / graham-fortune");
  const std::filesystem::path dir = ctx.section_dir();
  Text_table t({"contour", "M", "delta", "verdict", "margin 1", "margin 2", "margin 3", "not certified", "worst", "picture"});
  t.set_left_columns(1);
  Json rows = Json::array();
  int index = 0;
  std::vector<Picture> pictures;
  std::map<std::string, int> verdicts;
  for (const Case& c : gallery) {
    const Extrusion_options o = options_of(c);
    double time_s = 0;
    const Extrusion_report r = run_extrusion("graham-fortune", "failsafe", c.contour, o, &time_s);
    check_expectation(rep, c, "failsafe/graham-fortune", r);
    const std::string file = "contour_" + std::to_string(index++) + ".svg";
    write_extrusion_svg((dir / file).string(), c.contour, r, c.name + " (failsafe, graham-fortune)");
    pictures.push_back({ctx.relative(dir / file), c.name + ": " + std::string(to_string(r.verdict))});
    ++verdicts[std::string(to_string(r.verdict))];
    t.add_row({c.name, std::to_string(c.contour.size()), format_g(c.uncertainty, 2), std::string(to_string(r.verdict)),
               margin_text(r.conditions[0]), margin_text(r.conditions[1]), margin_text(r.conditions[2]),
               std::to_string(r.offending_total), worst_pair_text(r), file});
    io::Contour_input in;
    in.source = c.name;
    in.contour = c.contour;
    Json j = extrusion_report_json(in, "failsafe", "graham-fortune", o, r, time_s);
    j["picture"] = ctx.relative(dir / file);
    rows.push_back(j);
  }
  rep.add_note("Extruded objects (thesis Sec. 3.4.1): the three sufficient conditions as planar hull problems, "
               "kernel failsafe,\nalgorithm graham-fortune. Margins: exact, rounded down, signed (<= 0: the "
               "condition fails); (>=): condition 3's\nprune radius bounds the pairs not computed. delta: relative "
               "input uncertainty.\n\n");
  rep.add_table(t);
  rep.add_gallery("The gallery's contours (failsafe, graham-fortune): curves blue, control hulls grey, offending "
                  "curves red (condition 1), orange (2), magenta (3)",
                  std::move(pictures));
  std::string counts;
  for (const auto& [v, n] : verdicts) counts += (counts.empty() ? "" : ", ") + std::to_string(n) + " " + v;
  rep.add_headline("Contour gallery (" + std::to_string(gallery.size()) + " contours, failsafe)", counts);
  rep.json["gallery"] = rows;
}

Json kernel_run_json(const Case& c, const std::string& kernel, const std::string& algorithm, const Extrusion_report& r,
                     double time_s) {
  return Json{{"contour", c.name},
              {"kernel", kernel},
              {"algorithm", algorithm},
              {"verdict", to_string(r.verdict)},
              {"min_margins",
               Json::array({io::json_measure(r.conditions[0].min_margin), io::json_measure(r.conditions[1].min_margin),
                            io::json_measure(r.conditions[2].min_margin)})},
              {"offending_total", r.offending_total},
              {"uncertain_answers", r.uncertain_answers},
              {"non_convex_hulls", r.non_convex_hulls},
              {"hull_failures", r.hull_failures},
              {"max_hull_backward_error", io::json_measure(r.max_hull_backward_error)},
              {"time_s", time_s}};
}

/// (2) Every kernel and hull algorithm on a good and on bad contours.
void kernels_part(const Experiment_context& ctx, const std::vector<Case>& gallery, Section_report& rep) {
  std::vector<Case> cases = {gallery[4], gallery[5], gallery[7]};  // circle 64, looped, bow tie
  Text_table t({"contour", "kernel", "algorithm", "verdict", "margin 1", "margin 2", "margin 3", "uncertain answers",
                "non-convex hulls", "max hull backward error", "time"});
  t.set_left_columns(3);
  Json rows = Json::array();
  for (const Case& c : cases) {
    ctx.progress("kernels x algorithms: " + c.name);
    for (const auto& a : hull_algorithm_names())
      for (const auto& k : kernel_registry()) {
        if (a == "cgal" && !k.cgal) continue;
        const Extrusion_options o = options_of(c);
        double time_s = 0;
        const Extrusion_report r = run_extrusion(a, k.name, c.contour, o, &time_s, ctx.min_timing_seconds / 10);
        check_expectation(rep, c, k.label() + "/" + a, r);
        t.add_row({c.name, k.label(), a, std::string(to_string(r.verdict)), margin_text(r.conditions[0]),
                   margin_text(r.conditions[1]), margin_text(r.conditions[2]), std::to_string(r.uncertain_answers),
                   std::to_string(r.non_convex_hulls), extrusion_measure_text(r.max_hull_backward_error),
                   format_g(time_s * 1e3, 3) + " ms"});
        rows.push_back(kernel_run_json(c, k.label(), a, r, time_s));
      }
    t.add_rule();
  }
  rep.add_part("Every kernel and hull algorithm. A naive kernel may return a hull that is not the exact one; "
               "its exact backward-error\ncertificate then enters the computation error, so the verdict degrades to "
               "'uncertain' but never certifies wrongly.\n\n",
               t, "kernels", rows);
}

/// (3) Scaling: circle chains of M = 100 .. 10^5 curves, with and without the
/// prune.
void scaling_part(const Experiment_context& ctx, Section_report& rep) {
  std::vector<std::size_t> sizes = {100, 1000, 10000};
  if (!ctx.quick) sizes.push_back(100000);
  Text_table t({"M", "kernel", "algorithm", "prune", "verdict", "pairs computed", "non-adjacent pairs", "time", "time / M"});
  t.set_left_columns(0);
  Json rows = Json::array();
  for (std::size_t M : sizes) {
    const Bezier_contour c = circle_contour(M);
    for (const auto& [k, a] : {std::pair<std::string, std::string>{"failsafe", "graham-fortune"}, {"filtered", "monotone-chain"}}) {
      for (bool prune : {true, false}) {
        // the quadratic check: M = 100 (and 1000 for failsafe in the full run)
        if (!prune && (M > 1000 || (M == 1000 && (ctx.quick || k != "failsafe")))) continue;
        ctx.progress("scaling M = " + std::to_string(M) + " " + k + (prune ? "" : " (no prune)"));
        Extrusion_options o;
        o.relative_uncertainty = 1e-9;  // the curves are ~2 pi / M long: 1e-3 would not be covered
        o.prune = prune;
        double time_s = 0;
        const Extrusion_report r = run_extrusion(a, k, c, o, &time_s);
        if (prune && k == "failsafe" && M == sizes.back())
          rep.add_headline("Largest circle chain checked (M = " + std::to_string(M) + ", failsafe, pruned)",
                           std::string(to_string(r.verdict)) + " in " + format_g(time_s, 3) + " s");
        if (r.verdict != Extrusion_verdict::certified)
          rep.failures.push_back("circle M=" + std::to_string(M) + " not certified by " + k + "/" + a);
        t.add_row({std::to_string(M), k, a, prune ? "yes" : "no", std::string(to_string(r.verdict)),
                   std::to_string(r.pairs_computed), std::to_string(r.non_adjacent_pairs),
                   format_g(time_s, 3) + " s", format_g(time_s / static_cast<double>(M) * 1e6, 3) + " us"});
        rows.push_back({{"M", M}, {"kernel", k}, {"algorithm", a}, {"prune", prune}, {"verdict", to_string(r.verdict)},
                        {"pairs_computed", r.pairs_computed}, {"non_adjacent_pairs", r.non_adjacent_pairs},
                        {"prune_radius", r.prune_radius}, {"time_s", time_s}});
      }
    }
  }
  rep.add_part("Scaling: circle chains of M cubics, relative uncertainty 1e-9. With the prune, condition 3 computes "
               "O(M) pairs;\nwithout it M(M-3)/2.\n\n",
               t, "scaling", rows);
}

}  // namespace

Section_report extrusion_section(const Experiment_context& ctx) {
  Section_report rep;
  const std::vector<Case> gallery = gallery_cases();
  gallery_part(ctx, gallery, rep);
  kernels_part(ctx, gallery, rep);
  scaling_part(ctx, rep);
  return rep;
}

}  // namespace relgeo::tool
