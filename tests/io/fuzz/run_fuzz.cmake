# cmake -DSOURCE=... -DBINARY=... -DGENERATOR=... -DMAKE_PROGRAM=... -DPREBUILT_LIBRARIES=... -DSECONDS=...
#       -P run_fuzz.cmake
# Builds the fuzz project with clang and runs it for SECONDS, seeded with the small OBJ files of
# seeds/ (plain ones, and saved files with tags, UVs, colours and labels made with the rgbsub binary)
# and libFuzzer's random seed.
# GENERATOR and MAKE_PROGRAM are the outer build's (CMAKE_GENERATOR, CMAKE_MAKE_PROGRAM);
# PREBUILT_LIBRARIES its libraries that the fuzz target links as they are (tests/io/fuzz/CMakeLists.txt).
foreach(required SOURCE BINARY GENERATOR MAKE_PROGRAM PREBUILT_LIBRARIES SECONDS)
  if(NOT DEFINED ${required})
    message(FATAL_ERROR "run_fuzz.cmake needs -D${required}=...")
  endif()
endforeach()
find_program(CLANGXX clang++ REQUIRED)
# A fuzz build made earlier with another generator cannot be reconfigured; start it afresh.
if(EXISTS ${BINARY}/CMakeCache.txt)
  file(STRINGS ${BINARY}/CMakeCache.txt cached_generator REGEX "^CMAKE_GENERATOR:INTERNAL=")
  if(NOT cached_generator STREQUAL "CMAKE_GENERATOR:INTERNAL=${GENERATOR}")
    file(REMOVE_RECURSE ${BINARY})
  endif()
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE} -B ${BINARY} -G "${GENERATOR}" -DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM}
                        -DCMAKE_CXX_COMPILER=${CLANGXX} -DCMAKE_BUILD_TYPE=RelWithDebInfo
                        -DPREBUILT_LIBRARIES=${PREBUILT_LIBRARIES} RESULT_VARIABLE result)
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
