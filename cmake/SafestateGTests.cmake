# safestate_add_gtests(PATTERN LIBRARY): one GoogleTest executable per source file of the
# calling directory matching PATTERN (so a test may replace the global operator new),
# linked with LIBRARY and registered with ctest through gtest_discover_tests. The glob
# re-runs on every build, picking up new test files.
function(safestate_add_gtests pattern library)
  find_package(GTest REQUIRED)
  include(GoogleTest)
  file(GLOB test_sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${pattern})
  foreach(test_source IN LISTS test_sources)
    get_filename_component(test_name ${test_source} NAME_WE)
    add_executable(${test_name} ${test_source})
    target_include_directories(${test_name} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
    target_link_libraries(${test_name} PRIVATE ${library} GTest::gtest GTest::gtest_main)
    target_compile_options(${test_name} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Werror)
    # Lets tests read the design pages (table audits compare the C++ rows with them).
    target_compile_definitions(${test_name} PRIVATE SAFESTATE_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
    gtest_discover_tests(${test_name} DISCOVERY_TIMEOUT 60)
  endforeach()
endfunction()
