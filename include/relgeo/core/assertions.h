// relgeo/core/assertions.h — contract checks.
//
// RELGEO_precondition(expr, msg) throws relgeo::Precondition_violation when expr
// is false. It is on by default (the checks are cheap); define
// RELGEO_NO_PRECONDITIONS to compile them out. Expensive checks (e.g. exact
// postconditions) use RELGEO_expensive_precondition and are on only when
// RELGEO_CHECK_EXPENSIVE is defined.
#pragma once

#include <string>

#include "relgeo/core/errors.h"

namespace relgeo::internal {
[[noreturn]] inline void precondition_failed(const char* expr, const std::string& msg,
                                             const char* file, int line) {
  throw Precondition_violation(std::string("relgeo: precondition violated: ") + msg + " [" +
                               expr + "] at " + file + ":" + std::to_string(line));
}
}  // namespace relgeo::internal

#ifdef RELGEO_NO_PRECONDITIONS
#define RELGEO_precondition(expr, msg) ((void)0)
#else
#define RELGEO_precondition(expr, msg) \
  ((expr) ? (void)0 : ::relgeo::internal::precondition_failed(#expr, (msg), __FILE__, __LINE__))
#endif

#ifdef RELGEO_CHECK_EXPENSIVE
#define RELGEO_expensive_precondition(expr, msg) RELGEO_precondition(expr, msg)
#else
#define RELGEO_expensive_precondition(expr, msg) ((void)0)
#endif
