#include <gtest/gtest.h>

#include "relgeo/core/certified_sign.h"

namespace relgeo {
namespace {

constexpr auto N = Certified_sign::negative, Z = Certified_sign::zero, P = Certified_sign::positive,
               U = Certified_sign::uncertain;

TEST(CertifiedSign, ProductIsDefiniteWhenBothAreOrOneIsZero) {
  EXPECT_EQ(P * P, P);
  EXPECT_EQ(N * N, P);
  EXPECT_EQ(P * N, N);
  EXPECT_EQ(Z * U, Z);
  EXPECT_EQ(U * Z, Z);
  EXPECT_EQ(U * P, U);
  EXPECT_EQ(N * U, U);
}

TEST(CertifiedSign, NegationKeepsUncertainty) {
  EXPECT_EQ(-P, N);
  EXPECT_EQ(-N, P);
  EXPECT_EQ(-Z, Z);
  EXPECT_EQ(-U, U);
}

TEST(CertifiedSign, CertainlyAndPossibly) {
  EXPECT_TRUE(certainly(P, P));
  EXPECT_FALSE(certainly(U, P));
  EXPECT_TRUE(possibly(U, N));
  EXPECT_FALSE(possibly(P, N));
  EXPECT_FALSE(is_certain(U));
  EXPECT_TRUE(is_certain(Z));
}

TEST(CertifiedSign, SignOfValues) {
  EXPECT_EQ(sign_of(-2.5), N);
  EXPECT_EQ(sign_of(0.0), Z);
  EXPECT_EQ(sign_of(-0.0), Z);
  EXPECT_EQ(sign_of(1e-320), P);
  EXPECT_EQ(to_string(U), "uncertain");
}

}  // namespace
}  // namespace relgeo
