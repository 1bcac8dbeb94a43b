# Awkward but valid meshes, end to end (decisions: doc/PR_star_octree/robustness.md).  Each mesh is
# written here as .off, `prstar stats FILE --json` and `prstar boundary FILE --json` must succeed
# (exit 0) and report the counts worked out by hand below; the text form of `stats` must print
# the matching warning.  The tool proceeds on all of them: nothing is refused, nothing is
# repaired in the file (negatively oriented tetrahedra are reoriented inside the octree only).
#
# Usage: cmake -DPRSTAR=path/to/prstar -DWORK=scratch_dir -P test_awkward.cmake
cmake_minimum_required(VERSION 3.21)
if(NOT PRSTAR OR NOT WORK)
  message(FATAL_ERROR "usage: cmake -DPRSTAR=... -DWORK=... -P test_awkward.cmake")
endif()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set_property(GLOBAL PROPERTY failures 0)

function(fail name what)
  get_property(n GLOBAL PROPERTY failures)
  math(EXPR n "${n} + 1")
  set_property(GLOBAL PROPERTY failures ${n})
  message(SEND_ERROR "case ${name}: ${what}")
endfunction()

# run(<out var> name args...): runs prstar, requires exit 0, returns stdout.
function(run var name)
  execute_process(COMMAND "${PRSTAR}" ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                  TIMEOUT 60)
  if(NOT rc EQUAL 0)
    fail(${name} "prstar ${ARGN}: exit status '${rc}'\n${err}")
  endif()
  set(${var} "${out}" PARENT_SCOPE)
endfunction()

# expect(name json key=value...): every key of the JSON object must have the value.
function(expect name json)
  foreach(kv IN LISTS ARGN)
    string(REPLACE "=" ";" kv "${kv}")
    list(GET kv 0 key)
    list(GET kv 1 value)
    string(JSON got ERROR_VARIABLE e GET "${json}" ${key})
    if(e)
      fail(${name} "no key '${key}' in ${json}")
    elseif(NOT got STREQUAL value)
      fail(${name} "${key} = ${got}, expected ${value}")
    endif()
  endforeach()
endfunction()

# awkward(name content STATS k=v... BOUNDARY k=v... WARNING regex)
function(awkward name content)
  cmake_parse_arguments(A "" "WARNING" "STATS;BOUNDARY" ${ARGN})
  set(f "${WORK}/${name}.off")
  file(WRITE "${f}" "${content}")
  run(json ${name} stats "${f}" --json)
  expect(${name} "${json}" ${A_STATS})
  foreach(kv 1 4)  # a tiny bucket size too: coincident points must not make the split loop forever
    run(json ${name} stats "${f}" --kv ${kv} --json)
    expect(${name} "${json}" ${A_STATS})
  endforeach()
  run(json ${name} boundary "${f}" --json)
  expect(${name} "${json}" ${A_BOUNDARY})
  run(text ${name} stats "${f}")
  if(A_WARNING AND NOT text MATCHES "${A_WARNING}")
    fail(${name} "the text output does not match '${A_WARNING}':\n${text}")
  endif()
  message(STATUS "${name}: ok")
endfunction()

set(unit "0 0 0\n1 0 0\n0 1 0\n0 0 1\n")

# Coincident points: vertex 5 repeats vertex 1 (1,0,0), so the two tetrahedra share only the edge
# 2-3 (a crack).  V=6, E=6+6-1=11, F=8 (all on the boundary), chi=6-11+8-2=1.  The vertices 2 and 3
# have a link made of two triangles meeting at a point: non-manifold.
awkward(coincident "6 2\n${unit}1 1 1\n1 0 0\n0 1 2 3\n5 2 3 4\n"
  STATS vertices=6 tetrahedra=2 edges=11 triangles=8 boundary_triangles=8 nonmanifold_triangles=0
        euler_characteristic=1 duplicate_vertices=1 unreferenced_vertices=0 reoriented_tetrahedra=0
        degenerate_tetrahedra=0
  BOUNDARY boundary_vertices=4 interior_vertices=0 nonmanifold_vertices=2 unreferenced_vertices=0
  WARNING "warning: 1 duplicate vertices")

# Unreferenced vertices: one tetrahedron and two isolated points.  The Euler characteristic counts
# the vertices of the tetrahedra only: 4-6+4-1=1.
awkward(unreferenced "6 1\n${unit}5 5 5\n-3 2 1\n0 1 2 3\n"
  STATS vertices=6 tetrahedra=1 edges=6 triangles=4 boundary_triangles=4 euler_characteristic=1
        duplicate_vertices=0 unreferenced_vertices=2 degenerate_tetrahedra=0
  BOUNDARY boundary_vertices=4 nonmanifold_vertices=0 unreferenced_vertices=2
  WARNING "2 vertices in no tetrahedron")

# Zero volume: (1,1,-1) lies on the plane x+y+z=1 of the face 1-2-3, so tetrahedron 1 is flat.
# V=5, E=6+3=9, F=4+3=7 (the shared face is interior: 6 on the boundary), chi=5-9+7-2=1.
awkward(zero_volume "5 2\n${unit}1 1 -1\n0 1 2 3\n1 2 3 4\n"
  STATS vertices=5 tetrahedra=2 edges=9 triangles=7 boundary_triangles=6 euler_characteristic=1
        degenerate_tetrahedra=1 reoriented_tetrahedra=0 nonmanifold_triangles=0
  BOUNDARY boundary_vertices=5 nonmanifold_vertices=0
  WARNING "warning: 1 tetrahedra have zero volume")

# Inverted: tetrahedron 0 listed as 0 2 1 3 (negative orientation), tetrahedron 1 positive.
awkward(inverted "5 2\n${unit}1 1 1\n0 2 1 3\n1 2 3 4\n"
  STATS vertices=5 tetrahedra=2 edges=9 triangles=7 boundary_triangles=6 euler_characteristic=1
        reoriented_tetrahedra=1 degenerate_tetrahedra=0
  BOUNDARY boundary_vertices=5 nonmanifold_vertices=0
  WARNING "1 tetrahedra listed with negative orientation")

# Non-manifold triangle: 0-1-2 is a face of three tetrahedra (apexes 3, 4 below, 5).  V=6,
# E=3+3*3=12, F=1+3*3=10 (9 on the boundary), chi=6-12+10-3=1; 0, 1 and 2 are non-manifold.
awkward(nonmanifold_triangle "6 3\n${unit}0 0 -1\n1 1 1\n0 1 2 3\n0 2 1 4\n0 1 2 5\n"
  STATS vertices=6 tetrahedra=3 edges=12 triangles=10 boundary_triangles=9 nonmanifold_triangles=1
        euler_characteristic=1 reoriented_tetrahedra=0
  BOUNDARY boundary_vertices=3 nonmanifold_vertices=3
  WARNING "warning: 1 triangles are shared by three or more tetrahedra")

# Non-manifold vertex: two tetrahedra touching at vertex 0 only.  V=7, E=12, F=8, chi=7-12+8-2=1.
awkward(nonmanifold_vertex "7 2\n${unit}-1 0 0\n0 -1 0\n0 0 -1\n0 1 2 3\n0 5 4 6\n"
  STATS vertices=7 tetrahedra=2 edges=12 triangles=8 boundary_triangles=8 nonmanifold_triangles=0
        euler_characteristic=1 reoriented_tetrahedra=0
  BOUNDARY boundary_vertices=6 nonmanifold_vertices=1 interior_vertices=0)

# Several connected components: three disjoint tetrahedra, chi = 3 * 1 = 3.
awkward(components "12 3\n${unit}5 0 0\n6 0 0\n5 1 0\n5 0 1\n0 5 0\n1 5 0\n0 6 0\n0 5 1\n0 1 2 3\n4 5 6 7\n8 9 10 11\n"
  STATS vertices=12 tetrahedra=3 edges=18 triangles=12 boundary_triangles=12 euler_characteristic=3
        nonmanifold_triangles=0 duplicate_vertices=0 unreferenced_vertices=0
  BOUNDARY boundary_vertices=12 nonmanifold_vertices=0)

# All at once, with the same point repeated 6 times (one leaf of coincident points at any k_v).
awkward(everything "11 3\n${unit}1 1 1\n1 1 1\n1 1 1\n1 1 1\n1 1 1\n1 1 1\n9 9 9\n0 2 1 3\n1 2 3 4\n1 2 3 5\n"
  STATS vertices=11 tetrahedra=3 duplicate_vertices=5 unreferenced_vertices=5 reoriented_tetrahedra=1
        nonmanifold_triangles=1 degenerate_tetrahedra=0
  BOUNDARY unreferenced_vertices=5)

get_property(failures GLOBAL PROPERTY failures)
message(STATUS "test_awkward: ${failures} failures")
