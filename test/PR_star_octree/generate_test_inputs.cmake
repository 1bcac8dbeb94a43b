# Makes the test inputs with our own tool (CGAL Mesh_3 and TetGen): run by CTest as a fixture.
# Usage: cmake -DPRSTAR=<prstar> -DOUT=<dir> -P generate_test_inputs.cmake
file(MAKE_DIRECTORY ${OUT})

# A closed polyhedral surface (a triangulated cube with a dent-free tilt) for the polyhedral domain.
file(WRITE ${OUT}/cube_surface.off
"OFF
8 12 0
-0.5 -0.5 -0.5
0.5 -0.5 -0.5
0.5 0.5 -0.5
-0.5 0.5 -0.5
-0.5 -0.5 0.5
0.5 -0.5 0.5
0.5 0.5 0.5
-0.5 0.5 0.5
3 0 2 1
3 0 3 2
3 4 5 6
3 4 6 7
3 0 1 5
3 0 5 4
3 1 2 6
3 1 6 5
3 2 3 7
3 2 7 6
3 3 0 4
3 3 4 7
")

function(generate name)
  execute_process(COMMAND ${PRSTAR} generate ${ARGN} -o ${OUT}/${name} --force --quiet
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "prstar generate ${ARGN} failed (${rc}): ${err}")
  endif()
endfunction()

generate(sphere.mesh --shape sphere --cell-size 0.1)
generate(torus.mesh --shape torus --cell-size 0.08)
generate(cube.mesh --surface ${OUT}/cube_surface.off --cell-size 0.08)
generate(sphere_tetgen.mesh --shape sphere --cell-size 0.1 --tetgen)
generate(cube_tetgen.vtu --surface ${OUT}/cube_surface.off --cell-size 0.1 --tetgen)
