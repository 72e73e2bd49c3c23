# Converts bench/tests/silhouette_check.jts with jts-to-tachyon and checks what
# the Tachyon scene says: one object per primitive (a capped cylinder is an
# FCYLINDER and two RINGs), the lights, the camera mirrored in z, one TEXDEF per
# distinct material. Also checks that a primitive Tachyon has no shape for (the
# showcase's ellipsoid) is a located error (exit 1), that a missing scene is an
# I/O error (exit 3), and that neither writes anything.
include(${CMAKE_CURRENT_LIST_DIR}/converter_check.cmake)
convert(${SCENE} ${OUT})
expect_count("\nBEGIN_SCENE\n" 1)
expect_count("\nEND_SCENE\n" 1)
expect_count("\nRESOLUTION 240 160\n" 1)
expect_count("\n  RAYDEPTH 3\n" 1)                   # recurse_depth 2, plus the primary ray
expect_count("\n  ANTIALIASING 0\n" 1)
expect_count("\n  ASPECTRATIO 1\n" 1)                # aspect 1.5 = 240 / 160
expect_count("\n  ZOOM 1.37373870973\n" 1)          # 1 / (2 tan 20 degrees)
expect_count("\n  CENTER 1 3 -8\n" 1)                # the camera, z mirrored
expect_count("\nLIGHT CENTER 5 8 -6 RAD 0 COLOR 0.7 0.7 0.7\n" 1)
expect_count("\nLIGHT " 2)
expect_count("\nTEXDEF m[0-9] " 6)
expect_count("\nPLANE CENTER 0 0 -0 NORMAL 0 1 -0 m[0-9]\n" 1)
expect_count("\nSPHERE CENTER -2 1 -0 RAD 1 m[0-9]\n" 1)
expect_count("\nSPHERE CENTER 0.5 0.6 -1.5 RAD 0.6 m[0-9]\n" 1)   # scaled 0.6, moved
expect_count("\nSPHERE " 2)
expect_count("\nFCYLINDER BASE 0 0.3 1 APEX 2.5 0.3 1 RAD 0.3 m[0-9]\n" 1)   # zrotate -90
expect_count("\nFCYLINDER " 3)
expect_count("\nRING CENTER [^\n]* INNER 0 OUTER " 6)
expect_count("PHONG PLASTIC 0.5 PHONG_SIZE 40" 1)
expect_count("SPECULAR 0.3 " 1)                      # the red sphere's reflection

execute_process(COMMAND ${CONVERTER} ${SHOWCASE} ${OUT}.showcase RESULT_VARIABLE status
                ERROR_VARIABLE message)
if(NOT status EQUAL 1 OR NOT message MATCHES "showcase.jts:[0-9]+:[0-9]+: error: Tachyon cannot show"
   OR EXISTS ${OUT}.showcase)
    message(FATAL_ERROR "an ellipsoid should be exit 1 with a located message: ${status} ${message}")
endif()
expect_missing_scene_fails(${SCENE} ${OUT})
