// tools/relgeo/commands/linsolve/command.cpp — `relgeo linsolve`: solve A x = b from a
// matrix file (or a built-in example) with a method in a scalar, and report
// both backward errors, the forward error against the exact rational
// solution and the condition number.
#include "commands/linsolve/command.h"

#include <cmath>
#include <limits>
#include <ostream>
#include <sstream>

#include "commands/linsolve/facade.h"
#include "relgeo/io/json.h"
#include "relgeo/io/number_text.h"
#include "relgeo/io/text_file.h"
#include "relgeo_fixtures/linear/test_problems.h"

namespace relgeo::tool {

namespace {

using io::Json;

/// [A | b] from the matrix file text (format: linsolve_help_footer).
Linear_system<double> parse_system(const std::string& text, const std::string& source) {
  std::vector<std::vector<double>> rows;
  std::istringstream lines(text);
  std::string line;
  std::size_t number = 0;
  while (std::getline(lines, line)) {
    ++number;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    for (char& c : line)
      if (c == ',' || c == '\t' || c == '\r') c = ' ';
    std::istringstream tokens(line);
    std::vector<double> row;
    std::string tok;
    while (tokens >> tok)
      row.push_back(io::parse_double(tok, source, number));
    if (row.empty()) continue;
    if (!rows.empty() && row.size() != rows.front().size())
      throw io::Parse_error(source, number, std::to_string(row.size()) +
                        " numbers, but the first row has " + std::to_string(rows.front().size()) +
                        " (every row: n entries of A, then b_i)");
    rows.push_back(std::move(row));
  }
  if (rows.empty()) throw io::Parse_error(source, 0, "no matrix (empty file)");
  const std::size_t n = rows.size();
  if (rows.front().size() != n + 1)
    throw io::Parse_error(source, 0, std::to_string(n) + " rows of " + std::to_string(rows.front().size()) +
                      " numbers; a system of n equations needs n rows of n + 1 numbers (A, then b)");
  Linear_system<double> s{Dense_matrix<double>(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n)),
                          Dense_vector<double>(static_cast<Eigen::Index>(n))};
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j)
      s.a(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = rows[i][j];
    s.b(static_cast<Eigen::Index>(i)) = rows[i][n];
  }
  return s;
}

std::string vector_text(const std::vector<double>& v, std::size_t max_listed = 8) {
  std::string s = "(";
  for (std::size_t i = 0; i < v.size() && i < max_listed; ++i) s += (i ? ", " : "") + format_17(v[i]);
  if (v.size() > max_listed) s += ", ... (" + std::to_string(v.size()) + " entries)";
  return s + ")";
}

}  // namespace

std::string linsolve_help_footer() {
  return linear_methods_help() + "Scalars (--scalar): " + linear_scalars_summary() +
         ". The data are correctly rounded to the scalar; every measure is taken against the "
         "file's data (doubles), exactly.\n"
         "\nMatrix file: n lines of n + 1 numbers, the row of A followed by b_i, separated by "
         "blanks or commas; '#' starts a comment; blank lines are ignored. Decimal literals are "
         "correctly rounded to double; NaN, infinities, garbage and rows of different lengths are "
         "refused (exit 2, naming the line). Instead of a file: --example thesis (the thesis' 2x2 "
         "system, phi = 0.1*0.1 - 0.01 in double) or --hilbert N (the N x N Hilbert matrix and "
         "b = H * ones, correctly rounded to double).\n"
         "\nMeasures (infinity norms, exact arithmetic, rounded upward):\n"
         "  normwise backward error       eta = ||b - A x|| / (||A|| ||x|| + ||b||) (Rigal-Gaches)\n"
         "  componentwise backward error  omega = max_i |b - A x|_i / (|A| |x| + |b|)_i (Oettli-Prager)\n"
         "  forward error                 ||x - x*|| / ||x*||, x* the exact rational solution (n <= "
         "--exact-limit; null beyond)\n"
         "  condition number              ||A|| ||A^-1||: exact for n <= 40 (and <= --exact-limit), "
         "else Hager-Higham's estimate\n"
         "  forward error bound           2 kappa eta / (1 - kappa eta), first-order perturbation "
         "bound (null when kappa eta >= 1)\n"
         "  growth factor                 max |u_ij| / max |a_ij| (relgeo's elimination only)\n"
         "\nJSON fields: input, n, method, scalar, unit_roundoff, status (ok|failed), failure, x (17 "
         "digits, rounded to double), normwise_backward_error, componentwise_backward_error, "
         "forward_error, condition_number, condition_number_exact, forward_error_bound, "
         "growth_factor, residual_norm, exact_solution (rounded to double, or null), time_s; "
         "infinite measures are the string \"inf\".\n"
         "Defaults: --method partial --scalar double --exact-limit 100; the matrix file may be given positionally "
         "(relgeo linsolve FILE).\n"
         "Exit codes: 0 solved; 1 the solver failed (zero pivot in a rounding scalar, non-finite "
         "solution); 2 bad input (also an exactly singular matrix: rank < n).\n";
}

int run_linsolve_command(const Linsolve_options& o, Streams io) {
  std::ostream& out = io.out;
  std::ostream& err = io.err;
  validate_linear_combination(o.method, o.scalar);
  const int sources = (!o.input.empty()) + (!o.example.empty()) + (o.hilbert > 0);
  if (sources != 1) throw Usage_error("give exactly one of a matrix file (FILE or --input FILE), --example thesis, --hilbert N");
  if (o.exact_limit < 0) throw Usage_error("--exact-limit must be >= 0");
  Linear_system<double> s;
  std::string name;
  if (!o.input.empty()) {
    name = o.input == "-" ? "<stdin>" : o.input;
    s = parse_system(o.input == "-" ? io::read_text_stream(io.in) : io::read_text_file(o.input, "matrix file"), name);
  } else if (!o.example.empty()) {
    if (o.example != "thesis") throw Usage_error("--example: unknown example '" + o.example + "'; examples: thesis");
    s = thesis_example();
    name = "thesis example";
  } else {
    s = stored_hilbert_system<double>(o.hilbert);
    name = "hilbert " + std::to_string(o.hilbert);
  }
  const auto limit = static_cast<std::size_t>(o.exact_limit);
  // An exactly singular matrix is bad input (exit 2): Singular_matrix with
  // Error_code::invalid_input propagates to main.
  const Linear_reference ref(s.a, s.b, {.exact_solution_limit = limit, .exact_condition_limit = std::min<std::size_t>(limit, 40)});
  const Linear_outcome outcome = solve_linear_system(o.method, o.scalar, ref);
  const Linear_run& run = outcome.run;
  const std::string& failure = outcome.failure;
  const bool failed = outcome.failed();
  const double kappa = outcome.condition.value;
  const std::optional<double>& bound = outcome.forward_error_bound;
  const std::vector<double>& exact = outcome.exact_solution;
  const std::string scalar_u = format_g(scalar_unit_roundoff(o.scalar), 3);

  if (o.format == Format::json) {
    Json j{{"input", name}};
    j.update(linear_outcome_json(outcome, ref));
    out << io::dump_json(j) << '\n';
  } else {
    auto kv = [&](const std::string& k, const std::string& v) {
      out << k << std::string(k.size() < 30 ? 30 - k.size() : 1, ' ') << v << '\n';
    };
    kv("input", name + " (n = " + std::to_string(ref.size()) + ")");
    kv("method", o.method);
    kv("scalar", o.scalar + " (u = " + scalar_u + ")");
    kv("status", failed ? "failed: " + failure : "ok");
    if (!failed) {
      kv("x", vector_text(run.x));
      kv("normwise backward error", measure_text(run.errors.normwise_backward_error) + "  (Rigal-Gaches eta)");
      kv("componentwise backward error", measure_text(run.errors.componentwise_backward_error) + "  (Oettli-Prager omega)");
      kv("forward error", run.errors.forward_error ? measure_text(*run.errors.forward_error) + "  (against the exact rational solution)"
                                                   : std::string("not computed (n > --exact-limit)"));
    }
    kv("condition number", measure_text(kappa) + (outcome.condition.exact ? "  (exact)" : "  (Hager-Higham estimate)"));
    if (!failed) {
      kv("forward error bound", bound ? measure_text(*bound) + "  (2 kappa eta / (1 - kappa eta))" : std::string("none (kappa eta >= 1)"));
      if (run.growth_factor) kv("growth factor", measure_text(*run.growth_factor));
      kv("residual norm", measure_text(run.errors.residual_norm));
    }
    if (!exact.empty()) kv("exact solution", vector_text(exact) + "  (rounded to double)");
    if (!failed) kv("time", format_g(run.time_s * 1e6, 3) + " us");
  }
  if (failed) {
    err << "relgeo: failure: " << one_line(failure) << '\n';
    return exit_failure;
  }
  return exit_success;
}

}  // namespace relgeo::tool
