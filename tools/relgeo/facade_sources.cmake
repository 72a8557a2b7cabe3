# tools/relgeo/facade_sources.cmake — the tool's kernel-free facades: non-template
# functions that take a kernel (or scalar) by name and run the algorithm under
# it (the dispatch*.cpp files behind them), with the kernel registry, the
# text helpers they use and the JSON records of their reports: the library
# relgeo_tool_facades (CMakeLists.txt here), linked by the tool and by the
# Python module (python/).
# Paths relative to tools/relgeo.
# cli/text.cpp and kernels/registry.cpp come in the object library
# relgeo_tool_kernel_registry (CMakeLists.txt), which the OpenCASCADE plug-in
# links too.
set(relgeo_tool_facade_sources
  commands/orient_grid/dispatch.cpp
  commands/hull/facade.cpp
  commands/hull/dispatch.cpp
  commands/linsolve/facade.cpp
  commands/linsolve/dispatch.cpp
  commands/extrusion/dispatch.cpp
  commands/subdivide/dispatch_float.cpp
  commands/subdivide/dispatch_exact.cpp
  commands/boolean/names.cpp
  commands/boolean/dispatch.cpp
  commands/boolean/dispatch_subdivision.cpp
  commands/csg/dispatch.cpp
  commands/csg/tree.cpp
  commands/join/dispatch.cpp
  commands/join/facade.cpp)
# Their JSON records (untimed: relgeo_untimed).
set(relgeo_tool_facade_report_sources
  commands/hull/report.cpp
  commands/extrusion/report.cpp
  commands/boolean/report.cpp
  commands/boolean/subdivision_report.cpp
  commands/csg/report.cpp)
