# relgeo_optional_target(NAME DEFINE MACRO LIBS lib... [SYSTEM_INCLUDES dir...]):
# the optional INTERFACE target relgeo::NAME (exported as relgeo::NAME) over
# relgeo and LIBS, which defines MACRO=1 for every target that links it (one
# definition per program, never a macro set by hand); relgeo_export_NAME is
# set in the caller's scope for install(TARGETS).
function(relgeo_optional_target name)
  cmake_parse_arguments(ARG "" "DEFINE" "LIBS;SYSTEM_INCLUDES" ${ARGN})
  add_library(relgeo_${name} INTERFACE)
  add_library(relgeo::${name} ALIAS relgeo_${name})
  set_target_properties(relgeo_${name} PROPERTIES EXPORT_NAME ${name})
  target_link_libraries(relgeo_${name} INTERFACE relgeo ${ARG_LIBS})
  if(ARG_SYSTEM_INCLUDES)
    target_include_directories(relgeo_${name} SYSTEM INTERFACE ${ARG_SYSTEM_INCLUDES})
  endif()
  target_compile_definitions(relgeo_${name} INTERFACE ${ARG_DEFINE}=1)
  set(relgeo_export_${name} relgeo_${name} PARENT_SCOPE)
endfunction()
