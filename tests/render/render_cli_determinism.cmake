# ctest script: `rgbsub render` twice on the same input must write the same bytes.
foreach(run a b)
  execute_process(COMMAND ${RGBSUB} render ${INPUT} -o ${WORK_DIR}/${run}.png --size 200x150 --mode rgb --wire --limit --base
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "rgbsub render exited with ${rc}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK_DIR}/a.png ${WORK_DIR}/b.png RESULT_VARIABLE differ)
if(differ)
  message(FATAL_ERROR "two renders of ${INPUT} differ")
endif()
