# Warning flags shared by every target of the project.
function(asperity_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion)
  if(ASPERITY_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# One GoogleTest executable per source folder: tests/<folder>/*_test.cpp -> asperity_<name>_tests.
function(asperity_test_folder folder)
  cmake_parse_arguments(ARG "" "" "LIBS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${folder}/*_test.cpp)
  if(NOT sources)
    return()
  endif()
  string(REPLACE "/" "_" name ${folder})
  add_executable(asperity_${name}_tests ${sources})
  target_link_libraries(asperity_${name}_tests PRIVATE ${ARG_LIBS} asperity_test_support
                                                       GTest::gtest_main)
  asperity_warnings(asperity_${name}_tests)
  gtest_discover_tests(asperity_${name}_tests
                       WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
                       PROPERTIES ENVIRONMENT "ASPERITY_BIN=${CMAKE_BINARY_DIR}/bin"
                       DISCOVERY_TIMEOUT 60)
endfunction()
