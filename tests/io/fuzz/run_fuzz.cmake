# cmake -DSOURCE=... -DBINARY=... -DSECONDS=... -P run_fuzz.cmake
# Builds the fuzz project with clang and runs it for SECONDS, seeded with small OBJ files.
find_program(CLANGXX clang++ REQUIRED)
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE} -B ${BINARY} -G Ninja -DCMAKE_CXX_COMPILER=${CLANGXX}
                        -DCMAKE_BUILD_TYPE=RelWithDebInfo RESULT_VARIABLE result)
if(result)
  message(FATAL_ERROR "configuring the fuzz project failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BINARY} -j2 RESULT_VARIABLE result)
if(result)
  message(FATAL_ERROR "building the fuzz target failed")
endif()
file(REMOVE_RECURSE ${BINARY}/corpus)
file(MAKE_DIRECTORY ${BINARY}/corpus)
execute_process(COMMAND ${BINARY}/obj_loader_fuzz -max_total_time=${SECONDS} -timeout=10 -max_len=8192
                        -print_final_stats=1 ${BINARY}/corpus ${SOURCE}/seeds
                RESULT_VARIABLE result)
if(result)
  message(FATAL_ERROR "the fuzz target found a crash (exit ${result}); the reproducer is in the working directory")
endif()
