// Both backends of relgeo/mesh/internal/parallel.h in one program: the
// serial one and oneTBB's are distinct functions (a program that mixes
// translation units built with and without RELGEO_HAS_TBB keeps both), and
// the same pair searches give the same pairs, in the same order, on either
// and on 1 or 2 threads.
#include <gtest/gtest.h>

#include "mesh/parallel_backend.h"

namespace {

using relgeo_test::Backend_run;

TEST(ParallelBackends, SerialAndTbbUnitsKeepTheirOwnBackend) {
  const Backend_run serial = relgeo_test::serial_backend_run(2), tbb = relgeo_test::tbb_backend_run(2);
  EXPECT_NE(serial.thread_count, tbb.thread_count);  // not one of them merged into the other by the linker
  EXPECT_EQ(serial.threads_used, 1);
  EXPECT_EQ(tbb.threads_used, 2);
}

TEST(ParallelBackends, SerialAndTbbUnitsFindTheSamePairs) {
  const Backend_run reference = relgeo_test::serial_backend_run(1);
  ASSERT_GT(reference.cross_pairs.size(), 1000u);
  ASSERT_GT(reference.self_pairs.size(), reference.cross_pairs.size());
  for (const Backend_run& run : {relgeo_test::serial_backend_run(2), relgeo_test::tbb_backend_run(1),
                                 relgeo_test::tbb_backend_run(2)}) {
    EXPECT_EQ(run.cross_pairs, reference.cross_pairs);
    EXPECT_EQ(run.self_pairs, reference.self_pairs);
  }
}

}  // namespace
