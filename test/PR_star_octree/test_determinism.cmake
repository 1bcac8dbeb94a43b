# Deterministic results: every command below is run twice and its outputs (stdout, written files)
# must be byte for byte identical (file(SHA256)), timings excepted: the JSON "seconds" fields are
# removed with a regular expression before comparing.
#  - prstar generate (Mesh_3 and TetGen), twice, to two files;
#  - prstar stats --json (several k_v) on the generated meshes;
#  - prstar boundary --json and -o X.vtu, prstar curvature --json -o X.vtu --csv X.csv (when the
#    tool has these commands).
#
# Usage: cmake -DPRSTAR=path/to/prstar -DWORK=scratch_dir -P test_determinism.cmake
cmake_minimum_required(VERSION 3.21)
if(NOT PRSTAR OR NOT WORK)
  message(FATAL_ERROR "usage: cmake -DPRSTAR=... -DWORK=... -P test_determinism.cmake")
endif()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set_property(GLOBAL PROPERTY compared 0)

function(prstar out_var)
  execute_process(COMMAND "${PRSTAR}" ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                  TIMEOUT 300)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "prstar ${ARGN}: exit status '${rc}'\n${err}")
  endif()
  # timings: "seconds": <number> (and a trailing/leading comma) are not compared
  string(REGEX REPLACE ",? *\"seconds\": *[-+0-9.eE]+" "" out "${out}")
  set(${out_var} "${out}" PARENT_SCOPE)
endfunction()

function(same what a b)
  get_property(n GLOBAL PROPERTY compared)
  math(EXPR n "${n} + 1")
  set_property(GLOBAL PROPERTY compared ${n})
  if(NOT a STREQUAL b)
    message(SEND_ERROR "${what}: the two runs differ:\n--- run 1\n${a}\n--- run 2\n${b}")
  endif()
endfunction()

function(same_files what f1 f2)
  file(SHA256 "${f1}" h1)
  file(SHA256 "${f2}" h2)
  same("${what} (${f1} vs ${f2})" "${h1}" "${h2}")
endfunction()

function(has_command name var)
  execute_process(COMMAND "${PRSTAR}" ${name} --help RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET TIMEOUT 60)
  if(rc EQUAL 0)
    set(${var} TRUE PARENT_SCOPE)
  else()
    set(${var} FALSE PARENT_SCOPE)
    message(STATUS "prstar has no '${name}' command: not checked")
  endif()
endfunction()
has_command(boundary have_boundary)
has_command(curvature have_curvature)

set(meshes)
foreach(g "balls.vtu;--shape;balls;--cell-size;0.12"
          "torus.mesh;--shape;torus;--cell-size;0.12;--tetgen"
          "ellipsoid.mesh;--shape;ellipsoid;--cell-size;0.1")
  list(POP_FRONT g name)
  foreach(run 1 2)
    prstar(json_${run} generate ${g} -o "${WORK}/${run}_${name}" --json --quiet)
    string(REPLACE "${WORK}/${run}_" "" json_${run} "${json_${run}}")
  endforeach()
  same("generate ${name} --json" "${json_1}" "${json_2}")
  same_files("generate ${name}" "${WORK}/1_${name}" "${WORK}/2_${name}")
  list(APPEND meshes "${WORK}/1_${name}")
endforeach()

foreach(mesh IN LISTS meshes)
  get_filename_component(base "${mesh}" NAME_WE)
  foreach(kv 1 8 50 inf "4,16,inf")
    prstar(a stats "${mesh}" --kv ${kv} --json)
    prstar(b stats "${mesh}" --kv ${kv} --json)
    same("stats ${mesh} --kv ${kv} --json" "${a}" "${b}")
  endforeach()
  if(have_boundary)
    foreach(run 1 2)
      prstar(json_${run} boundary "${mesh}" --kv 8 --json -o "${WORK}/${base}_boundary_${run}.vtu")
      string(REPLACE "${base}_boundary_${run}" "OUT" json_${run} "${json_${run}}")
    endforeach()
    same("boundary ${mesh} --json" "${json_1}" "${json_2}")
    same_files("boundary ${mesh} -o" "${WORK}/${base}_boundary_1.vtu" "${WORK}/${base}_boundary_2.vtu")
  endif()
  if(have_curvature)
    foreach(run 1 2)
      prstar(json_${run} curvature "${mesh}" --field z --kv 8 --json -o "${WORK}/${base}_curv_${run}.vtu"
             --csv "${WORK}/${base}_curv_${run}.csv")
      string(REPLACE "${base}_curv_${run}" "OUT" json_${run} "${json_${run}}")
    endforeach()
    same("curvature ${mesh} --json" "${json_1}" "${json_2}")
    same_files("curvature ${mesh} -o" "${WORK}/${base}_curv_1.vtu" "${WORK}/${base}_curv_2.vtu")
    same_files("curvature ${mesh} --csv" "${WORK}/${base}_curv_1.csv" "${WORK}/${base}_curv_2.csv")
  endif()
endforeach()

get_property(n GLOBAL PROPERTY compared)
message(STATUS "test_determinism: ${n} comparisons")
