// tools/relgeo/experiment/linear.cpp — the "linear" section of `relgeo
// experiment` (thesis Sec. 3.2):
//  (1) the thesis' 2x2 example under every method, and without pivoting
//      under every scalar;
//  (2) Hilbert matrices n = 2..14 stored in double: small backward error,
//      large forward error for the stable methods, against kappa;
//  (3) the exact Hilbert systems: the MPFR precision each n needs for a
//      forward error <= 1e-3, 1e-6, 1e-12 (partial pivoting);
//  (4) random systems in double: every method's backward errors and time,
//      relgeo's elimination against Eigen's LU.
// The section fails (exit 1) only on a library regression: the thesis'
// numbers not reproduced, or a pivoting method in double with a backward
// error above 10 n u.
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "commands/linsolve/facade.h"
#include "experiment/section.h"
#include "relgeo_fixtures/linear/test_problems.h"

namespace relgeo::tool {

namespace {

using io::Json;

Json measure(double v) { return io::json_measure(v); }
std::string text(double v, int digits = 3) { return measure_text(v, digits); }
Json run_json(const Linear_run& r) {
  return Json{{"method", r.method},
              {"scalar", r.scalar},
              {"normwise_backward_error", measure(r.errors.normwise_backward_error)},
              {"componentwise_backward_error", measure(r.errors.componentwise_backward_error)},
              {"forward_error", r.errors.forward_error ? measure(*r.errors.forward_error) : Json(nullptr)},
              {"growth_factor", r.growth_factor ? measure(*r.growth_factor) : Json(nullptr)},
              {"time_s", r.time_s}};
}

/// A pivoting method in double must have a backward error <= 10 n u; a
/// larger one is a library regression (`problem`: which system).
void check_backward_error(Section_report& rep, const std::string& problem, int n, const Linear_run& r) {
  const double u = 0x1p-53;
  if (r.method != "none" && r.errors.normwise_backward_error > 10 * n * u)
    rep.failures.push_back(problem + " n=" + std::to_string(n) + ": " + r.method + " has backward error " +
                           text(r.errors.normwise_backward_error) + " > 10 n u");
}

/// (1) The thesis' example under every method, and without pivoting under
/// every scalar; fails unless no pivoting returns (0, 1) and partial (1, 1).
void thesis_example_part(const Experiment_context& ctx, Section_report& rep) {
  ctx.progress("thesis example");
  const auto s = thesis_example();
  const Linear_reference ref(s.a, s.b);
  Text_table t({"method", "scalar", "x0", "x1", "eta (normwise)", "omega (componentwise)", "forward", "growth"});
  t.set_left_columns(2);
  Json rows = Json::array();
  std::vector<std::pair<std::string, std::string>> runs;
  for (const auto& m : linear_method_names()) runs.emplace_back(m, "double");
  for (const std::string sc : {"float", "long-double", "mpfr-53", "mpfr-64", "rational"}) runs.emplace_back("none", sc);
  for (const auto& [m, sc] : runs) {
    const Linear_run r = run_linear_solver(m, sc, ref);
    t.add_row({m, sc, format_17(r.x[0]), format_17(r.x[1]), text(r.errors.normwise_backward_error),
               text(r.errors.componentwise_backward_error), text(*r.errors.forward_error),
               r.growth_factor ? text(*r.growth_factor) : "-"});
    Json j = run_json(r);
    j["x"] = r.x;
    rows.push_back(j);
    if (sc == "double" && (m == "none" || m == "partial"))
      rep.add_headline("Thesis example, " + m + " pivoting in double",
                       "x = (" + format_17(r.x[0]) + ", " + format_17(r.x[1]) + "), backward error " +
                           text(r.errors.normwise_backward_error) + ", forward error " + text(*r.errors.forward_error));
    if (m == "none" && sc == "double" && !(r.x[0] == 0 && r.x[1] == 1))
      rep.failures.push_back("thesis example: no pivoting in double did not return (0, 1)");
    if (m == "partial" && sc == "double" && !(r.x[0] == 1 && r.x[1] == 1))
      rep.failures.push_back("thesis example: partial pivoting did not return (1, 1)");
  }
  rep.add_part("The thesis' example (Sec. 3.2): A = [[phi, 1], [1, 0]], b = [1, 1], phi = 0.1*0.1 - 0.01 = 2^-59 in\n"
               "double; exact solution (1, 1 - phi), condition number " + text(ref.condition().value, 17) +
                   " (exact).\nNo pivoting: backward error 1/2 on a perfectly conditioned problem — the algorithm, not "
                   "the data, is at fault.\n\n",
               t, "thesis_example", {{"phi", s.a(0, 0)}, {"condition_number", ref.condition().value}, {"runs", rows}});
}

/// (2) Hilbert matrices n = 2..14 stored in double: every method's backward
/// and forward errors against kappa.
void hilbert_double_part(const Experiment_context& ctx, Section_report& rep) {
  ctx.progress("Hilbert matrices n = 2..14 in double");
  std::vector<std::string> header = {"n", "kappa"};
  for (const auto& m : linear_method_names()) header.push_back("eta " + m);
  header.push_back("omega partial");
  for (const auto& m : linear_method_names()) header.push_back("fwd " + m);
  header.push_back("2 kappa eta");
  Text_table t(header);
  Json rows = Json::array();
  for (int n = 2; n <= 14; ++n) {
    const auto s = stored_hilbert_system<double>(n);
    const Linear_reference ref(s.a, s.b);
    std::vector<std::string> row = {std::to_string(n), text(ref.condition().value)};
    std::vector<std::string> fwd;
    Json runs = Json::array();
    double eta_partial = 0, omega_partial = 0;
    for (const auto& m : linear_method_names()) {
      const Linear_run r = run_linear_solver(m, "double", ref);
      row.push_back(text(r.errors.normwise_backward_error));
      fwd.push_back(text(*r.errors.forward_error));
      runs.push_back(run_json(r));
      if (m == "partial") eta_partial = r.errors.normwise_backward_error, omega_partial = r.errors.componentwise_backward_error;
      if (m == "partial" && n == 12)
        rep.add_headline("Hilbert n = 12 in double, partial pivoting (kappa " + text(ref.condition().value) + ")",
                         "backward error " + text(r.errors.normwise_backward_error) + ", forward error " +
                             text(*r.errors.forward_error));
      check_backward_error(rep, "Hilbert", n, r);
    }
    row.push_back(text(omega_partial));
    row.insert(row.end(), fwd.begin(), fwd.end());
    row.push_back(text(2 * ref.condition().value * eta_partial));
    t.add_row(row);
    rows.push_back(Json{{"n", n}, {"condition_number", ref.condition().value}, {"runs", runs}});
  }
  rep.add_part("Hilbert matrices H_n and b = H_n * ones, stored in double (measures against the stored system's "
               "exact solution).\nStable methods: backward error at the level of u = 1.1e-16 for every n, forward "
               "error growing with kappa\n(bounded by 2 kappa eta to first order).\n\n",
               t, "hilbert_double", rows);
}

/// Partial pivoting on an exact system at every MPFR precision of the
/// sweep: (bits, forward error).
std::vector<std::pair<int, double>> precision_sweep(const Linear_reference& ref) {
  std::vector<std::pair<int, double>> fwd;
  for (int bits : linear_mpfr_bits()) {
    try {
      const Linear_run r = run_linear_solver("partial", "mpfr-" + std::to_string(bits), ref);
      fwd.emplace_back(bits, *r.errors.forward_error);
    } catch (const Singular_matrix&) {  // a zero pivot at a very low precision
      fwd.emplace_back(bits, std::numeric_limits<double>::infinity());
    }
  }
  return fwd;
}

/// (3) The MPFR precision each exact Hilbert system needs for a forward
/// error <= 1e-3, 1e-6, 1e-12.
void precision_needed_part(const Experiment_context& ctx, Section_report& rep) {
  const int n_max = ctx.quick ? 10 : 14;
  ctx.progress("Hilbert precision sweep n = 2.." + std::to_string(n_max));
  const std::vector<double> targets = {1e-3, 1e-6, 1e-12};
  Text_table t({"n", "kappa (exact H_n)", "log2 kappa", "bits for 1e-3", "bits for 1e-6", "bits for 1e-12", "fwd at 53 bits"});
  Json rows = Json::array();
  for (int n = 2; n <= n_max; ++n) {
    const auto h = hilbert_system(n);
    const Linear_reference ref(h.a, h.b);
    const std::vector<std::pair<int, double>> fwd = precision_sweep(ref);
    std::vector<std::string> row = {std::to_string(n), text(ref.condition().value), format_fixed(std::log2(ref.condition().value), 1)};
    Json needed = Json::object();
    for (double target : targets) {
      int found = -1;
      for (const auto& [bits, f] : fwd)
        if (f <= target) {
          found = bits;
          break;
        }
      row.push_back(found < 0 ? "> " + std::to_string(linear_mpfr_bits().back()) : std::to_string(found));
      needed[format_g(target, 1)] = found < 0 ? Json(nullptr) : Json(found);
    }
    double at53 = 0;
    Json sweep = Json::array();
    for (const auto& [bits, f] : fwd) {
      if (bits == 53) at53 = f;
      sweep.push_back({{"bits", bits}, {"forward_error", measure(f)}});
    }
    row.push_back(text(at53));
    t.add_row(row);
    rows.push_back(
        Json{{"n", n}, {"condition_number", ref.condition().value}, {"bits_needed", needed}, {"sweep", sweep}});
  }
  rep.add_part("Precision needed: the exact Hilbert system H_n x = H_n * ones (x = ones), data correctly rounded "
               "to MPFR at BITS,\npartial pivoting; the smallest BITS of the sweep (" +
                   std::to_string(linear_mpfr_bits().front()) + ".." + std::to_string(linear_mpfr_bits().back()) +
                   ") whose forward error is <= the target.\nRule of thumb: bits ~ log2(kappa / target).\n\n",
               t, "hilbert_precision", rows);
}

/// (4) Random systems in double: every method's backward errors and time,
/// relgeo's elimination against Eigen's LU.
void random_systems_part(const Experiment_context& ctx, Section_report& rep) {
  std::vector<int> sizes = {10, 50, 100};
  if (!ctx.quick) sizes.push_back(200);
  Text_table t({"n", "method", "eta", "omega", "forward", "time", "time / eigen-partial"});
  t.set_left_columns(2);
  Json rows = Json::array();
  for (int n : sizes) {
    ctx.progress("random system n = " + std::to_string(n));
    const auto [a, b] = random_system(n, static_cast<unsigned>(n));
    const Linear_reference ref(a, b, {.exact_solution_limit = 100, .exact_condition_limit = 40});
    std::vector<Linear_run> runs;
    double eigen_time = 0;
    for (const auto& m : linear_method_names()) {
      runs.push_back(run_linear_solver(m, "double", ref, ctx.min_timing_seconds));
      if (m == "eigen-partial") eigen_time = runs.back().time_s;
    }
    for (const auto& r : runs) {
      t.add_row({std::to_string(n), r.method, text(r.errors.normwise_backward_error),
                 text(r.errors.componentwise_backward_error),
                 r.errors.forward_error ? text(*r.errors.forward_error) : "-", format_g(r.time_s * 1e6, 3) + " us",
                 format_fixed(r.time_s / eigen_time, 2)});
      Json j = run_json(r);
      j.update(Json{
          {"n", n}, {"condition_number", ref.condition().value}, {"condition_number_exact", ref.condition().exact}});
      rows.push_back(j);
      check_backward_error(rep, "random", n, r);
    }
    t.add_rule();
  }
  rep.add_part("Random systems (entries uniform in [-1, 1]) in double: every method, its backward errors and "
               "time per solve (fastest of repeated runs).\n\n",
               t, "random_double", rows);
}

}  // namespace

Section_report linear_section(const Experiment_context& ctx) {
  Section_report rep;
  thesis_example_part(ctx, rep);
  hilbert_double_part(ctx, rep);
  precision_needed_part(ctx, rep);
  random_systems_part(ctx, rep);
  return rep;
}

}  // namespace relgeo::tool
