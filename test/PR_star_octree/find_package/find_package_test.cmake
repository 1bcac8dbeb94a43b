# Installs the package from the build tree into a temporary prefix, then configures, builds and runs
# the outside project of this folder against the installed headers (find_package(PR_star_octree)).
#
#   cmake -DBUILD_DIR=<this project's build> -DSOURCE_DIR=<this folder> -DWORK=<scratch folder>
#         [-DCXX=<compiler>] [-DBUILD_TYPE=Release] [-DREPO_INCLUDE=<source include/ folder>]
#         -P find_package_test.cmake
# REPO_INCLUDE, when given, must not appear on the outside program's compile line.
cmake_minimum_required(VERSION 3.21)
foreach(var BUILD_DIR SOURCE_DIR WORK)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "find_package_test.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT BUILD_TYPE)
  set(BUILD_TYPE Release)
endif()

set(prefix ${WORK}/prefix)
set(outside ${WORK}/build)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${ARGN}\n${out}\n${err}")
  endif()
  set(output "${out}" PARENT_SCOPE)
endfunction()

# 1. Install the library component only (headers and CMake package; the tool need not be built).
run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} --component PR_star_octree_library)
file(GLOB_RECURSE config ${prefix}/*/PR_star_octreeConfig.cmake)
if(NOT config)
  message(FATAL_ERROR "no PR_star_octreeConfig.cmake installed under ${prefix}")
endif()
if(NOT EXISTS ${prefix}/include/CGAL/PR_star_octree.h OR NOT EXISTS ${prefix}/include/CGAL/PR_star_octree/boundary.h)
  message(FATAL_ERROR "the headers are not installed under ${prefix}/include")
endif()

# 2. Configure the outside project with only the prefix to find the package.
set(configure_args -S ${SOURCE_DIR} -B ${outside} -DCMAKE_BUILD_TYPE=${BUILD_TYPE} -DCMAKE_PREFIX_PATH=${prefix}
                   -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
if(CXX)
  list(APPEND configure_args -DCMAKE_CXX_COMPILER=${CXX})
endif()
run("configure" ${CMAKE_COMMAND} ${configure_args})
string(REGEX MATCH "PR_star_octree_DIR: [^\n]*" found "${output}")
string(FIND "${found}" "${prefix}/" at)
if(NOT at GREATER 0)
  message(FATAL_ERROR "the package was not found in the install prefix ${prefix}: '${found}'")
endif()

# 3. Build: the include path must be the installed one.
run("build" ${CMAKE_COMMAND} --build ${outside} --verbose)
string(FIND "${output}" "${prefix}/include" at)
if(at LESS 0)
  message(FATAL_ERROR "the outside program was not compiled against ${prefix}/include:\n${output}")
endif()
if(REPO_INCLUDE)
  string(FIND "${output}" "${REPO_INCLUDE}" at)
  if(NOT at LESS 0)
    message(FATAL_ERROR "the outside program saw the source tree's headers (${REPO_INCLUDE}):\n${output}")
  endif()
endif()

# 4. Run and check the boundary flags.
file(GLOB_RECURSE program ${outside}/boundary_flags)
if(NOT program)
  message(FATAL_ERROR "boundary_flags was not built in ${outside}")
endif()
run("boundary_flags" ${program})
message("${output}")
foreach(expected "vertex 0: interior" "boundary vertices: 8" "interior vertices: 1" "boundary triangles: 12")
  string(FIND "${output}" "${expected}\n" at)
  if(at LESS 0)
    message(FATAL_ERROR "boundary_flags: '${expected}' expected in its output")
  endif()
endforeach()
foreach(v 1 2 3 4 5 6 7 8)
  string(FIND "${output}" "vertex ${v}: boundary\n" at)
  if(at LESS 0)
    message(FATAL_ERROR "boundary_flags: vertex ${v} (a corner of the cube) should be a boundary vertex")
  endif()
endforeach()
