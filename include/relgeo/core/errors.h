// relgeo/core/errors.h — the typed errors every public entry reports.
//
// One rule for every area (STYLE rule 9):
//  * bad input — data the caller cannot cheaply check (NaN, empty ranges,
//    unreadable files, invalid meshes, self-intersecting operands): a class
//    derived from relgeo::Error whose code() tells the kind, thrown before any
//    work (Invalid_input and its subclasses, Invalid_mesh, Invalid_operand...);
//  * a broken precondition — a wrong call the documentation rules out and a
//    cheap check finds (sizes that differ, a degenerate triangle given to
//    intersect_triangles): Precondition_violation, through RELGEO_precondition
//    where the check may be compiled out (RELGEO_NO_PRECONDITIONS), thrown
//    directly where a broken precondition would otherwise mean undefined
//    behaviour or an unsound answer (those checks stay on). It is never caught
//    inside relgeo: not control flow;
//  * the algorithm's own failure on valid input (a kernel that cannot decide,
//    non-termination, a repair that does not converge): the result's status
//    with a message naming the phase, where the result has one (hulls,
//    Booleans, CSG, joining, subdivision Booleans); otherwise
//    Error(Error_code::computation_failure).
// All derive from relgeo::Error, so `catch (const relgeo::Error&)` sees all.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace relgeo {

/// The kind of a reported error.
enum class Error_code {
  invalid_input,           ///< input violates a documented requirement
  non_finite_coordinate,   ///< a coordinate is NaN or infinite
  empty_input,             ///< a range that must not be empty is empty
  unreadable_file,         ///< a file cannot be opened or parsed
  precondition_violation,  ///< the caller broke a documented precondition
  computation_failure      ///< the algorithm detected its own failure (e.g. non-termination)
};

/// Short stable name of an error code (used in JSON reports).
constexpr std::string_view to_string(Error_code c) noexcept {
  switch (c) {
    case Error_code::invalid_input: return "invalid_input";
    case Error_code::non_finite_coordinate: return "non_finite_coordinate";
    case Error_code::empty_input: return "empty_input";
    case Error_code::unreadable_file: return "unreadable_file";
    case Error_code::precondition_violation: return "precondition_violation";
    case Error_code::computation_failure: return "computation_failure";
  }
  return "unknown";
}

/// Base of every exception relgeo throws.
class Error : public std::runtime_error {
 public:
  Error(Error_code code, const std::string& what) : std::runtime_error(what), code_(code) {}
  Error_code code() const noexcept { return code_; }

 private:
  Error_code code_;
};

/// Input that no algorithm of relgeo accepts (NaN, empty, malformed...).
class Invalid_input : public Error {
 public:
  explicit Invalid_input(const std::string& what, Error_code code = Error_code::invalid_input)
      : Error(code, what) {}
};

/// A coordinate is NaN or infinite.
class Non_finite_input : public Invalid_input {
 public:
  explicit Non_finite_input(const std::string& what)
      : Invalid_input(what, Error_code::non_finite_coordinate) {}
};

/// A file could not be read or parsed.
class Unreadable_file : public Invalid_input {
 public:
  explicit Unreadable_file(const std::string& what)
      : Invalid_input(what, Error_code::unreadable_file) {}
};

/// The caller broke a documented precondition.
class Precondition_violation : public Error {
 public:
  explicit Precondition_violation(const std::string& what)
      : Error(Error_code::precondition_violation, what) {}
};

}  // namespace relgeo
