# ctest -P script: perpixel_render and `marbler render --aa none` must write the same bytes for
# one genome. Variables: PERPIXEL, MARBLER, GENOME, WIDTH, KERNEL (MARBLER_KERNEL for marbler),
# OUT (a folder for the two images).
file(MAKE_DIRECTORY "${OUT}")
set(plain "${OUT}/perpixel-${KERNEL}.ppm")
set(rendered "${OUT}/marbler-${KERNEL}.ppm")
file(REMOVE "${plain}" "${rendered}")
execute_process(COMMAND "${PERPIXEL}" "${GENOME}" "${plain}" "${WIDTH}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "perpixel_render failed (${rc})")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -E env "MARBLER_KERNEL=${KERNEL}"
                        "${MARBLER}" render "${GENOME}" -o "${rendered}" --width "${WIDTH}" --aa none --quiet
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "marbler render failed (${rc})")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${plain}" "${rendered}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${plain} and ${rendered} differ")
endif()
