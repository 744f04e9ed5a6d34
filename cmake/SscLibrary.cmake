# ssc_library(name SOURCES ... PUBLIC_LIBS ... [PRIVATE_LIBS ...]): a static library of the
# project, included from the repository root, with the project's warnings.
function(ssc_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_LIBS;PRIVATE_LIBS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC "${PROJECT_SOURCE_DIR}")
  target_link_libraries(${name} PUBLIC ${ARG_PUBLIC_LIBS} PRIVATE ${ARG_PRIVATE_LIBS} ssc_warnings)
endfunction()
