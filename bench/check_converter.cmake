# Converts the showcase with jts-to-pov and checks what the POV-Ray scene says:
# one object per primitive, the lights, the camera mirrored in z, no gamma,
# glass and the checker; then the mesh scene's triangles and meshes as mesh2,
# and the globe scene's image maps on a plane, a sphere and a cylinder; and
# language 1.2: a light's radius as a circular area light, the lens as focal
# blur, the sky map as a sky_sphere, generated normals as the mesh2's own.
# Also checks that a missing scene is an I/O error (exit 3) and writes nothing.
include(${CMAKE_CURRENT_LIST_DIR}/converter_check.cmake)
convert(${SCENE} ${OUT})
expect_count("\n#version 3\\.7;" 1)
expect_count("assumed_gamma 1\\.0" 1)
expect_count("max_trace_level 5 " 1)             # recurse_depth 4, plus the primary ray
expect_count("\nsphere \\{" 5)
expect_count("\ncylinder \\{" 2)
expect_count("\nplane \\{" 2)
expect_count("\nlight_source \\{" 3)
expect_count("location <0, 2.4, -9>" 1)        # the camera "Main", z mirrored
expect_count("plane \\{ <0, 0, -1>, -7" 1)     # the backdrop, normal mirrored
expect_count("brilliance 1 phong" 8)           # diffuse_k 1 everywhere; 8 specular objects
expect_count("rgbt <" 1)                       # the glass ball transmits
expect_count("interior \\{ ior 1.5 \\}" 1)
expect_count("checker rgb" 1)                  # the backdrop
expect_count(" matrix <" 3)                    # the ellipsoid and the two cylinders

expect_missing_scene_fails(${SCENE} ${OUT})

if(DEFINED MESH_SCENE)
    convert(${MESH_SCENE} ${OUT}.mesh.pov)
    expect_count("\nmesh2 \\{" 6)                  # two meshes and four triangles
    expect_count(" normal_vectors \\{ " 1)          # only the smooth one
    expect_count(" face_indices \\{ 20020," 2)      # the knot, twice (one file)
    expect_count("uv_mapping pigment \\{ image_map \\{ png " 1)
endif()

if(DEFINED GLOBE_SCENE)
    convert(${GLOBE_SCENE} ${OUT}.globe.pov)
    expect_count("\nplane \\{ [^\n]* map_type 0 \\} matrix <0.5, 0, -0, 0, 0, 0.5," 1)  # map_size 0.5
    expect_count("\nsphere \\{ [^\n]* map_type 1 \\} matrix <0, 0, 1, 0, 1, 0, -1, 0, 0," 1)
    expect_count("\nunion \\{\n cylinder \\{ [^\n]* open [^\n]* map_type 2 \\} matrix <0, 0, 1, 0, 1.6, 0," 1)
    expect_count("\n disc \\{ [^\n]* map_type 0 \\} matrix <1.2, 0, 0, 0, 0, -1.2, 0, 1, 0, -0.6, 0, 0.6>" 2)
    expect_count("uv_mapping" 0)
endif()

if(DEFINED LANGUAGE_1_2_SCENE)
    convert(${LANGUAGE_1_2_SCENE} ${OUT}.1.2.pov)
    # radius 0.5: a disk of diameter 1; 10 shadow samples: 4 x 4 points
    expect_count("area_light <1, 0, 0>, <0, 1, 0>, 4, 4 circular orient" 1)
    expect_count("area_light" 1)                    # radius 0: a point light, whatever its samples
    # focus_distance 6 along the view axis; aperture 0.05 is POV-Ray's 0.2; samples 16
    expect_count(" focal_point <0, 1.25579159, -2.04633274> aperture 0.2 blur_samples 16, 16 }" 1)
    expect_count("\nsky_sphere \\{ pigment \\{ image_map \\{ png \"[^\"]*tiles\\.png\" gamma 1\\.0 interpolate 2 map_type 1 \\} matrix <0, 0, -1, 0, 1, 0, -1, 0, 0," 1)
    # smooth_angle 180 on a tetrahedron: each corner's normal points away from its centre
    expect_count(" normal_vectors \\{ 12(, <-?0\\.577350269, -?0\\.577350269, -?0\\.577350269>)+ \\}" 1)
    expect_count(" normal_indices \\{ 4, <0, 1, 2>, <3, 4, 5>, <6, 7, 8>, <9, 10, 11> \\}" 1)
endif()
