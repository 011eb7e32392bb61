# ctest driver for the fuzzer: configure + build the stand-alone fuzz project with clang, then
# run the target for a bounded number of inputs, seeded with the good and bad corpus.
#   cmake -DSOURCE=<this dir> -DBINARY=<build dir> -DDATA=<tests/gcode/data> -DRUNS=<n> -P run_fuzz.cmake
find_program(CLANGXX NAMES clang++ clang++-14)
if(NOT CLANGXX)
    message(FATAL_ERROR "clang++ not found (needed for libFuzzer)")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE} -B ${BINARY} -G Ninja
                        -DCMAKE_CXX_COMPILER=${CLANGXX} -DCMAKE_BUILD_TYPE=Debug
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "configuring the fuzz target failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BINARY} -j2 RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "building the fuzz target failed")
endif()
file(REMOVE_RECURSE ${BINARY}/corpus)
file(MAKE_DIRECTORY ${BINARY}/corpus)
file(GLOB seeds ${DATA}/good/*.nc ${DATA}/bad/*.nc)
file(COPY ${seeds} DESTINATION ${BINARY}/corpus)
execute_process(COMMAND ${BINARY}/gcode_fuzz -runs=${RUNS} -max_len=4096 -timeout=10 -max_total_time=15
                        -rss_limit_mb=2048 -print_final_stats=1
                        -artifact_prefix=${BINARY}/ ${BINARY}/corpus
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the fuzzer found a failing input (see above)")
endif()
