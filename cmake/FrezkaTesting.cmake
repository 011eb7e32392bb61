include(GoogleTest)

# frezka_add_gtest(NAME LABEL <label> SOURCES <files...> LIBS <targets...>)
# A GoogleTest executable whose tests are discovered when ctest runs, labelled by module.
function(frezka_add_gtest name)
    cmake_parse_arguments(ARG "" "LABEL" "SOURCES;LIBS" ${ARGN})
    add_executable(${name} ${ARG_SOURCES})
    target_link_libraries(${name} PRIVATE ${ARG_LIBS} GTest::gtest GTest::gtest_main GTest::gmock)
    gtest_discover_tests(${name}
        DISCOVERY_MODE PRE_TEST
        PROPERTIES LABELS "${ARG_LABEL}" ENVIRONMENT "QT_QPA_PLATFORM=offscreen"
        TEST_PREFIX "${ARG_LABEL}.")
endfunction()

# frezka_add_qtest(NAME LABEL <label> SOURCES <files...> LIBS <targets...> [XVFB] [ARGS <args...>])
# A QTest executable run offscreen (or under xvfb-run with XVFB); ARGS go to the test's command
# (QtTest: the test functions to run).
function(frezka_add_qtest name)
    cmake_parse_arguments(ARG "XVFB" "LABEL" "SOURCES;LIBS;ARGS" ${ARGN})
    add_executable(${name} ${ARG_SOURCES})
    target_link_libraries(${name} PRIVATE ${ARG_LIBS} Qt6::Test)
    if(ARG_XVFB)
        add_test(NAME ${ARG_LABEL}.${name} COMMAND xvfb-run -a $<TARGET_FILE:${name}> ${ARG_ARGS})
        set_tests_properties(${ARG_LABEL}.${name} PROPERTIES LABELS "${ARG_LABEL};xvfb")
    else()
        add_test(NAME ${ARG_LABEL}.${name} COMMAND ${name} ${ARG_ARGS})
        set_tests_properties(${ARG_LABEL}.${name} PROPERTIES
            LABELS "${ARG_LABEL}" ENVIRONMENT "QT_QPA_PLATFORM=offscreen")
    endif()
endfunction()
