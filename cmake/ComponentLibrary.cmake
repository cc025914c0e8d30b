# component_library(NAME ALIAS EXCLUDE regex TESTS dir)
# The static library of one component under src/<component>/ (the Safety service, the
# protection active object): every .cpp of the calling directory but those matching
# EXCLUDE (demos, fuzz targets), include/ as its public headers, SAFESTATE_WARNINGS,
# position-independent (the Python modules link it), its GoogleTest directory TESTS and
# its install rule (neither in a scikit-build wheel build).
function(component_library NAME ALIAS)
  cmake_parse_arguments(ARG "" "EXCLUDE;TESTS" "" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  list(FILTER sources EXCLUDE REGEX "${ARG_EXCLUDE}")
  add_library(${NAME} STATIC ${sources})
  add_library(${ALIAS} ALIAS ${NAME})
  target_include_directories(${NAME} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:include>)
  target_compile_options(${NAME} PRIVATE ${SAFESTATE_WARNINGS})
  set_target_properties(${NAME} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  if(SKBUILD)
    return()
  endif()
  if(SAFESTATE_BUILD_TESTS)
    add_subdirectory(${ARG_TESTS} ${CMAKE_CURRENT_BINARY_DIR}/tests)
  endif()
  include(GNUInstallDirs)
  install(TARGETS ${NAME} EXPORT safestateTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
endfunction()
