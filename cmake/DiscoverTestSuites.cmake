# Run after a GoogleTest executable is built (cmake -P): lists its suites and writes OUTPUT, a ctest file with one test
# per suite, "<prefix>.<Suite>", run as EXECUTABLE --gtest_filter=<Suite>.* [--configuration <prefix>]. A process per
# suite instead of per test: the first test of a process pays for the driver, the validation layer and the shader
# compiles (about a second on lavapipe), which per test was most of the suite's time. Negative controls (tests named
# *CatchesFault) run in a test of their own per suite, "<prefix>.<Suite>.CatchesFault", so `ctest -R CatchesFault`
# selects them; with several configurations they run on the first only (a broken render does not depend on it).
# Sweeps named *OnOneConfiguration (every filter, every light kind against the same ray cast, long camera walks) run
# likewise in "<prefix>.<Suite>.OnOneConfiguration" on the first configuration: the parity tests hold every other
# configuration to the same pixels, so a sweep's verdict carries over, and each configuration keeps one check of
# its own against the ground truth.
# Inputs: EXECUTABLE, OUTPUT, ENVIRONMENT (one VAR=value), and CONFIGURATIONS (comma-separated: a test per
# configuration, prefixed with its name, which the executable gets as --configuration) or PREFIX (one test).
execute_process(COMMAND "${EXECUTABLE}" --gtest_list_tests OUTPUT_VARIABLE listing RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} --gtest_list_tests failed (${status}): ${listing}")
endif()

# The listing: "Suite." on its own line, then "  Test" lines; parameterized names carry a "  # GetParam() = ..." tail.
string(REPLACE "\n" ";" lines "${listing}")
set(suites "")
foreach(line IN LISTS lines)
  string(REGEX REPLACE " *#.*$" "" line "${line}")
  if(line MATCHES "^([^ ].*)\\.$")
    set(suite "${CMAKE_MATCH_1}")
    list(APPEND suites "${suite}")
  elseif(line MATCHES "^  (.+CatchesFault)$")
    set("controls_${suite}" TRUE)
  elseif(line MATCHES "^  (.+OnOneConfiguration)$")
    set("sweeps_${suite}" TRUE)
  elseif(line MATCHES "^  ")
    set("checks_${suite}" TRUE)
  endif()
endforeach()

if(DEFINED CONFIGURATIONS)
  string(REPLACE "," ";" prefixes "${CONFIGURATIONS}")
else()
  set(prefixes "${PREFIX}")
endif()
list(GET prefixes 0 first)
set(content "")
function(add_suite_test name filter)
  if(DEFINED CONFIGURATIONS)
    set(configuration_argument " --configuration ${prefix}")
  endif()
  string(APPEND content "add_test([=[${name}]=] [=[${EXECUTABLE}]=]${configuration_argument} [=[--gtest_filter=${filter}]=])\n"
                        "set_tests_properties([=[${name}]=] PROPERTIES ENVIRONMENT [=[${ENVIRONMENT}]=])\n")
  set(content "${content}" PARENT_SCOPE)
endfunction()
foreach(prefix IN LISTS prefixes)
  foreach(suite IN LISTS suites)
    if(DEFINED "checks_${suite}")
      add_suite_test("${prefix}.${suite}" "${suite}.*-*CatchesFault:*OnOneConfiguration")
    endif()
    if(prefix STREQUAL first AND DEFINED "controls_${suite}")
      add_suite_test("${prefix}.${suite}.CatchesFault" "${suite}.*CatchesFault")
    endif()
    if(prefix STREQUAL first AND DEFINED "sweeps_${suite}")
      add_suite_test("${prefix}.${suite}.OnOneConfiguration" "${suite}.*OnOneConfiguration")
    endif()
  endforeach()
endforeach()
file(WRITE "${OUTPUT}" "${content}")
