# binding_module(NAME BINDING_SOURCE SOURCES src... [OUTPUT_DIR dir] [LINK targets...])
# One pybind11 module of a variant build (conform/wrong_variant/): the binding source
# compiled with the given library sources, the repository's include/ directory, gcov
# instrumentation when SAFESTATE_COVERAGE is ON, the .so written to OUTPUT_DIR.
include(${CMAKE_CURRENT_LIST_DIR}/Warnings.cmake)

function(binding_module NAME BINDING_SOURCE)
  cmake_parse_arguments(ARG "" "OUTPUT_DIR" "SOURCES;LINK" ${ARGN})
  pybind11_add_module(${NAME} NO_EXTRAS ${BINDING_SOURCE} ${ARG_SOURCES})
  target_include_directories(${NAME} PRIVATE ${REPO}/include)
  # The warnings of bindings/python/CMakeLists.txt: the same compile line as setup.sh's
  # binding, so that an unpatched binding source is a ccache hit.
  target_compile_options(${NAME} PRIVATE ${SAFESTATE_WARNINGS})
  if(ARG_LINK)
    target_link_libraries(${NAME} PRIVATE ${ARG_LINK})
  endif()
  if(SAFESTATE_COVERAGE)
    target_compile_options(${NAME} PRIVATE --coverage -O0)
    target_link_options(${NAME} PRIVATE --coverage)
  endif()
  set_target_properties(${NAME} PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${ARG_OUTPUT_DIR})
endfunction()
