# GMP (with its C++ interface gmpxx) and MPFR, found through pkg-config as the
# imported targets PkgConfig::RELGEO_GMP and PkgConfig::RELGEO_MPFR, and
# Boost's headers (Boost::headers: Boost.Sort's pdqsort in relgeo/hull).
# Included by relgeo's own CMakeLists.txt and by the installed relgeoConfig.cmake,
# so a client finds the same libraries relgeo's targets name.
find_package(PkgConfig REQUIRED)
if(NOT TARGET PkgConfig::RELGEO_GMP)
  pkg_check_modules(RELGEO_GMP REQUIRED IMPORTED_TARGET gmpxx gmp)
endif()
if(NOT TARGET PkgConfig::RELGEO_MPFR)
  pkg_check_modules(RELGEO_MPFR REQUIRED IMPORTED_TARGET mpfr)
endif()
if(NOT TARGET Boost::headers)
  find_package(Boost 1.70 REQUIRED CONFIG)
endif()
