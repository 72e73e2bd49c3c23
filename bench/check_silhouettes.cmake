# Runs bench/check_silhouettes.py on bench/tests/silhouette_check.jts twice:
# with Tachyon as it is, the silhouettes must agree (exit 0); with a Tachyon
# that drops the cylinders, the check must say DISAGREE and exit 1.
execute_process(COMMAND ${PYTHON} ${CHECK} --cli ${CLI} --converter ${CONVERTER} --tachyon ${TACHYON}
                        ${SCENE} ${WORK}/as_is
                RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT status EQUAL 0 OR NOT output MATCHES "silhouettes agree")
    message(FATAL_ERROR "the silhouettes should agree: ${status}\n${output}${errors}")
endif()
execute_process(COMMAND ${PYTHON} ${CHECK} --cli ${CLI} --converter ${CONVERTER}
                        --tachyon ${DROPPING_TACHYON} ${SCENE} ${WORK}/without_cylinders
                RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT status EQUAL 1 OR NOT output MATCHES "silhouettes DISAGREE")
    message(FATAL_ERROR "missing cylinders should fail the check: ${status}\n${output}${errors}")
endif()
