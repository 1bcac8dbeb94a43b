# Malformed inputs, end to end: every case below is written by this script into WORK, run through
# `prstar stats FILE` with a bounded address space (prlimit --as=2 GB) and a timeout, and must give
#  - exit code 1 or 2 (not a signal, not a timeout, not 0),
#  - exactly one line on stderr, starting with "prstar stats: ", naming the file and matching the
#    case's regular expression (the problem), and nothing on stdout.
# Cases: truncation in each section, counts that disagree with the data, indices out of range or
# not integers, non-finite or non-numeric coordinates, headers announcing 10^15 entries in a tiny
# file (the reader must not allocate for them), unsupported cell types and dimensions, broken
# encodings (base64 garbage, unterminated XML, compressed data), and the file system saying no.
#
# Usage: cmake -DPRSTAR=path/to/prstar -DWORK=scratch_dir -P test_malformed.cmake
cmake_minimum_required(VERSION 3.21)
if(NOT PRSTAR OR NOT WORK)
  message(FATAL_ERROR "usage: cmake -DPRSTAR=... -DWORK=... -P test_malformed.cmake")
endif()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

# Under AddressSanitizer (scripts/test_sanitizers.sh sets PRSTAR_NO_PRLIMIT), the address space
# cannot be limited (the shadow memory alone is terabytes of it): ASAN_OPTIONS max_allocation_size_mb
# and allocator_may_return_null bound the allocations instead.
find_program(PRLIMIT prlimit)
if(PRLIMIT AND NOT "$ENV{PRSTAR_NO_PRLIMIT}")
  set(limit ${PRLIMIT} --as=2000000000)
else()
  message(STATUS "no prlimit: the address space is not limited")
  set(limit)
endif()

set_property(GLOBAL PROPERTY cases 0)
set_property(GLOBAL PROPERTY failures 0)

function(fail name what)
  get_property(n GLOBAL PROPERTY failures)
  math(EXPR n "${n} + 1")
  set_property(GLOBAL PROPERTY failures ${n})
  message(SEND_ERROR "case ${name}: ${what}")
endfunction()

# Runs `prstar stats PATH` and checks the outcome (see the header); `shown` is the file name the
# message must hold (default PATH).
function(check name path regex)
  set(shown "${path}")
  if(ARGC GREATER 3)
    set(shown "${ARGV3}")
  endif()
  get_property(n GLOBAL PROPERTY cases)
  math(EXPR n "${n} + 1")
  set_property(GLOBAL PROPERTY cases ${n})
  execute_process(COMMAND ${limit} "${PRSTAR}" stats "${path}" --quiet
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 30)
  if(NOT rc MATCHES "^[12]$")
    fail(${name} "exit status '${rc}' (expected 1 or 2)\n${err}")
    return()
  endif()
  if(NOT out STREQUAL "")
    fail(${name} "unexpected output on stdout: ${out}")
  endif()
  string(REGEX REPLACE "\n$" "" line "${err}")
  if(line MATCHES "\n")
    fail(${name} "more than one line on stderr:\n${err}")
  endif()
  string(FIND "${line}" "prstar stats: ${shown}" at)
  if(NOT at EQUAL 0)
    fail(${name} "the message does not start with 'prstar stats: ${shown}': ${line}")
  endif()
  if(VERBOSE)
    message(STATUS "${name}: ${line}")
  endif()
  if(NOT line MATCHES "${regex}")
    fail(${name} "the message does not match '${regex}': ${line}")
  endif()
endfunction()

# Writes `content` to WORK/name and checks it.
function(case name content regex)
  file(WRITE "${WORK}/${name}" "${content}")
  check(${name} "${WORK}/${name}" "${regex}")
endfunction()

# A TetGen pair: WORK/name.node and WORK/name.ele, checked through the .node file; the message
# must name `shown` (node or ele).
function(tetgen_case name node ele shown regex)
  file(WRITE "${WORK}/${name}.node" "${node}")
  file(WRITE "${WORK}/${name}.ele" "${ele}")
  check(${name} "${WORK}/${name}.node" "${regex}" "${WORK}/${name}.${shown}")
endfunction()

# ---------------------------------------------------------------- Medit (.mesh)
set(mh "MeshVersionFormatted 2\nDimension 3\n")
set(mv "Vertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n")
case(m_empty.mesh "" "empty|MeshVersionFormatted")
case(m_no_version.mesh "Dimension 3\n" ":1: .*MeshVersionFormatted")
case(m_dim2.mesh "MeshVersionFormatted 2\nDimension 2\n" ":2: .*Dimension 2")
case(m_dim4.mesh "MeshVersionFormatted 2\nDimension 4\n" ":2: .*Dimension 4")
case(m_trunc_vertices.mesh "${mh}Vertices\n4\n0 0 0 0\n1 0 0 0\n" ":7: vertex 3: unexpected end of file")
case(m_trunc_tetrahedra.mesh "${mh}${mv}Tetrahedra\n2\n1 2 3 4 0\n" "end of file")
case(m_trunc_in_line.mesh "${mh}${mv}Tetrahedra\n1\n1 2 3" "end of file|found 3|expected")
case(m_count_short.mesh "${mh}Vertices\n5\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\nTetrahedra\n1\n1 2 3 4 0\nEnd\n"
     ":9: .*(Tetrahedra|number)")
case(m_index_range.mesh "${mh}${mv}Tetrahedra\n1\n1 2 3 5 0\nEnd\n" ":11: tetrahedron 1: vertex index 5 out of range")
case(m_index_zero.mesh "${mh}${mv}Tetrahedra\n1\n0 1 2 3 0\nEnd\n" ":11: tetrahedron 1: vertex index 0 out of range")
case(m_index_float.mesh "${mh}${mv}Tetrahedra\n1\n1 2.5 3 4 0\nEnd\n" ":11: .*2\\.5.* not an integer")
case(m_coord_nan.mesh "${mh}Vertices\n1\n0 nan 0 0\n" ":5: .*not finite")
case(m_coord_text.mesh "${mh}Vertices\n1\n0 zero 0 0\n" ":5: .*(number|zero)")
case(m_huge_count.mesh "${mh}Vertices\n1000000000000000\n0 0 0 0\n" "1000000000000000|end of file")
case(m_unknown_keyword.mesh "${mh}${mv}Foo\n1\n" ":9: .*Foo")
case(m_no_tetrahedra.mesh "${mh}${mv}End\n" "no 'Tetrahedra' section")

# ---------------------------------------------------------------- TetGen (.node/.ele)
set(tn "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n")
tetgen_case(t_trunc_node "5 3 0 0\n1 0 0 0\n2 1 0 0\n" "0 4 0\n" node "end of file")
tetgen_case(t_trunc_ele "${tn}" "2 4 0\n1 1 2 3 4\n" ele "end of file")
tetgen_case(t_index_range "${tn}" "1 4 0\n1 1 2 3 6\n" ele ":2: .*6.*out of range")
tetgen_case(t_index_negative "${tn}" "1 4 0\n1 1 2 -3 4\n" ele ":2: .*-3")
tetgen_case(t_index_text "${tn}" "1 4 0\n1 1 two 3 4\n" ele ":2: .*(integer|two)")
tetgen_case(t_coord_inf "5 3 0 0\n1 0 0 0\n2 inf 0 0\n" "0 4 0\n" node ":3: .*not finite")
tetgen_case(t_dim2 "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n" "0 4 0\n" node ":1: .*(dimension|2)")
tetgen_case(t_triangles "${tn}" "1 3 0\n1 1 2 3\n" ele ":1: .*(3|nodes)")
tetgen_case(t_huge_count "1000000000000000 3 0 0\n1 0 0 0\n" "0 4 0\n" node ":1: .*1000000000000000")
tetgen_case(t_huge_ele "${tn}" "1000000000000000 4 0\n1 1 2 3 4\n" ele "1000000000000000|end of file")
tetgen_case(t_extra_ele "${tn}" "1 4 0\n1 1 2 3 4\n2 2 3 4 5\n" ele ":3: ")
file(WRITE "${WORK}/t_missing_ele.node" "${tn}")
check(t_missing_ele "${WORK}/t_missing_ele.node" "no such file.*\\.node and its \\.ele" "${WORK}/t_missing_ele.ele")
file(WRITE "${WORK}/t_missing_node.ele" "1 4 0\n1 1 2 3 4\n")
check(t_missing_node "${WORK}/t_missing_node.ele" "no such file" "${WORK}/t_missing_node.node")

# ---------------------------------------------------------------- legacy VTK (.vtk)
set(vh "# vtk DataFile Version 4.2\nsmall mesh\nASCII\nDATASET UNSTRUCTURED_GRID\n")
set(vp "POINTS 5 float\n0 0 0 1 0 0 0 1 0\n0 0 1 1 1 1\n")
set(vc "CELLS 2 10\n4 0 1 2 3\n4 1 2 3 4\nCELL_TYPES 2\n10 10\n")
case(v_empty.vtk "" "# vtk DataFile Version")
case(v_binary.vtk "# vtk DataFile Version 4.2\nx\nBINARY\n" ":3: .*binary")
case(v_polydata.vtk "# vtk DataFile Version 4.2\nx\nASCII\nDATASET POLYDATA\n" ":4: .*POLYDATA")
# A tetrahedron and a triangle: the tetrahedron is kept, the triangle reported (mixed-cell files are
# read since issue 12).
file(WRITE "${WORK}/v_triangle.vtk" "${vh}${vp}CELLS 2 9\n4 0 1 2 3\n3 1 2 3\nCELL_TYPES 2\n10 5\n")
execute_process(COMMAND ${PRSTAR} stats ${WORK}/v_triangle.vtk --json RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err TIMEOUT 60)
if(NOT rc EQUAL 0 OR NOT out MATCHES "\"tetrahedra\": 1," OR NOT err MATCHES "1 tetrahedra kept; skipped the other cells: 1 triangle")
  fail(v_triangle.vtk "mixed cells: rc ${rc}, stdout ${out}, stderr ${err}")
endif()
case(v_hexahedron.vtk "${vh}${vp}CELLS 1 9\n8 0 1 2 3 4 0 1 2\nCELL_TYPES 1\n12\n" "cell 0 .*type 12")
case(v_cells_size.vtk "${vh}${vp}CELLS 2 11\n4 0 1 2 3\n4 1 2 3 4\nCELL_TYPES 2\n10 10\n" "10 values.*11")
case(v_trunc_points.vtk "${vh}POINTS 5 float\n0 0 0 1 0 0\n" "end of file.*POINTS|POINTS.*end of file")
case(v_trunc_cells.vtk "${vh}${vp}CELLS 2 10\n4 0 1 2 3\n" "end of file")
case(v_no_cell_types.vtk "${vh}${vp}CELLS 1 5\n4 0 1 2 3\n" "no CELL_TYPES")
case(v_index_range.vtk "${vh}${vp}CELLS 1 5\n4 0 1 2 5\nCELL_TYPES 1\n10\n" "vertex index 5 out of range")
case(v_index_float.vtk "${vh}${vp}CELLS 1 5\n4 0 1 2 3.5\nCELL_TYPES 1\n10\n" "(integer|3\\.5)")
case(v_coord_nan.vtk "${vh}POINTS 1 float\n0 nan 0\n" ":6: .*not finite")
case(v_coord_text.vtk "${vh}POINTS 1 float\n0 x 0\n" ":6: .*(number|'x')")
case(v_huge_points.vtk "${vh}POINTS 1000000000000000 float\n0 0 0\n" "1000000000000000|end of file")
case(v_huge_cells.vtk "${vh}${vp}CELLS 1000000000000000 5000000000000000\n4 0 1 2 3\n" "1000000000000000|end of file")
case(v_point_data.vtk "${vh}${vp}${vc}POINT_DATA 4\n" ":13: .*POINT_DATA 4 for 5 points")

# ---------------------------------------------------------------- VTK XML (.vtu)
set(uh "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n")
set(up "<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">\n<Points>\n<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0 0 0 1</DataArray>\n</Points>\n")
set(uc "<Cells>\n<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2 3</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">4</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10</DataArray>\n</Cells>\n")
set(ue "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n")
case(u_not_xml.vtu "hello\n" ":1: .*root element")
case(u_unterminated.vtu "${uh}${up}${uc}</Piece>\n" "(end of file|unterminated|not closed|closing|</)")
case(u_unterminated_tag.vtu "${uh}<Piece NumberOfPoints=\"4" "(end of file|unterminated|not closed)")
case(u_polydata.vtu "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\">\n<PolyData/>\n</VTKFile>\n" "PolyData")
case(u_triangle.vtu "${uh}${up}<Cells>\n<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">5</DataArray>\n</Cells>\n${ue}"
     "cell 0 .*type 5")
case(u_index_range.vtu "${uh}${up}<Cells>\n<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2 4</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">4</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10</DataArray>\n</Cells>\n${ue}"
     "4 out of range")
case(u_no_connectivity.vtu "${uh}${up}<Cells>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">4</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10</DataArray>\n</Cells>\n${ue}"
     "connectivity")
case(u_coord_nan.vtu "${uh}<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">\n<Points>\n<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 nan 0 0 0 1</DataArray>\n</Points>\n${uc}${ue}"
     "not finite")
case(u_points_2d.vtu "${uh}<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">\n<Points>\n<DataArray type=\"Float32\" NumberOfComponents=\"2\" format=\"ascii\">0 0 1 0 0 1 1 1</DataArray>\n</Points>\n${uc}${ue}"
     "NumberOfComponents|components")
case(u_base64_garbage.vtu "${uh}<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">\n<Points>\n<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">!!not*base64$$</DataArray>\n</Points>\n${uc}${ue}"
     "base64")
# the block header announces 4 GB of data, 12 bytes follow
case(u_base64_header_lies.vtu "${uh}<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">\n<Points>\n<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">/////wAAAAAAAAAAAAAAAA==</DataArray>\n</Points>\n${uc}${ue}"
     "(4294967295|bytes|short|end)")
case(u_huge_points.vtu "${uh}<Piece NumberOfPoints=\"1000000000000000\" NumberOfCells=\"1\">\n<Points>\n<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">MAAAAAAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/AAAAAAAAAAAAAAAAAACAPw==</DataArray>\n</Points>\n${uc}${ue}"
     "points do not fit")
case(u_compressed.vtu "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" compressor=\"vtkZLibDataCompressor\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">\n<Points>\n<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">AQAAAAAAAAAAAAAA</DataArray>\n</Points>\n${uc}${ue}"
     "compress")
case(u_appended_offset.vtu "${uh}<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">\n<Points>\n<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"appended\" offset=\"99999\"/>\n</Points>\n${uc}</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_abc\n</AppendedData>\n</VTKFile>\n"
     "offset 99999")

# ---------------------------------------------------------------- .off / .ts
set(ov "0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n")
case(o_empty.off "# nothing\n" "empty file")
case(o_coff.off "COFF\n5 1\n" ":1: .*COFF")
case(o_trunc_vertices.off "5 1\n0 0 0\n1 0 0\n" "end of file")
case(o_trunc_tetrahedra.off "5 2\n${ov}0 1 2 3\n" "end of file")
case(o_extra.off "5 1\n${ov}0 1 2 3\n1 2 3 4\n" ":8: ")
case(o_index_negative.off "5 1\n${ov}0 -1 2 3\n" ":7: .*-1 out of range")
case(o_index_overflow.off "5 1\n${ov}0 1 2 99999999999999999999\n" ":7: .*64-bit")
case(o_cell_size.off "5 1\n${ov}3 0 1 2 3\n" ":7: .*4 vertex indices")
case(o_coord_inf.off "5 1\n0 0 0\n1 inf 0\n" ":3: .*not finite")
case(o_huge.off "1000000000000000 1000000000000000\n0 0 0\n" "1000000000000000|end of file")

# ---------------------------------------------------------------- XDMF (.xdmf, and its .h5)
# (-DHDF5=TRUE when prstar was built with HDF5; the .h5 files are written with h5py when present)
set(xh "<?xml version=\"1.0\"?>\n<Xdmf Version=\"3.0\">\n<Domain>\n<Grid Name=\"mesh\" GridType=\"Uniform\">\n")
set(xg "<Geometry GeometryType=\"XYZ\">\n<DataItem Dimensions=\"5 3\" Format=\"XML\">0 0 0 1 0 0 0 1 0 0 0 1 1 1 1</DataItem>\n</Geometry>\n")
set(xe "</Grid>\n</Domain>\n</Xdmf>\n")
case(x_truncated.xdmf "${xh}<Topology TopologyType=\"Tetrahedron\">\n<DataItem DataType=\"Int\" Format=\"XML\">0 1 2 3</DataItem>\n</Topology>\n${xg}</Grid>\n"
     "unexpected end of file: element <Domain> of line 3 is not closed")
case(x_ne_larger.xdmf "${xh}<Topology TopologyType=\"Tetrahedron\" NumberOfElements=\"3\">\n<DataItem DataType=\"Int\" Format=\"XML\">0 1 2 3</DataItem>\n</Topology>\n${xg}${xe}"
     ":5: NumberOfElements=\"3\" but the data hold 4 values")
case(x_dims_larger.xdmf "${xh}<Topology TopologyType=\"Tetrahedron\">\n<DataItem Dimensions=\"1000000000000 4\" DataType=\"Int\" Format=\"XML\">0 1 2 3</DataItem>\n</Topology>\n${xg}${xe}"
     ":6: the topology: 4 values, 4000000000000 expected")
case(x_index_range.xdmf "${xh}<Topology TopologyType=\"Tetrahedron\">\n<DataItem DataType=\"Int\" Format=\"XML\">0 1 2 5</DataItem>\n</Topology>\n${xg}${xe}"
     ":6: cell 0: vertex index 5 out of range")
case(x_hexahedron.xdmf "${xh}<Topology TopologyType=\"Hexahedron\">\n<DataItem DataType=\"Int\" Format=\"XML\">0 1 2 3 4 0 1 2</DataItem>\n</Topology>\n${xg}${xe}"
     ":5: TopologyType 'Hexahedron' is not a tetrahedral mesh")
set(xh5 "${xh}<Topology TopologyType=\"Tetrahedron\">\n<DataItem Dimensions=\"1 4\" DataType=\"Int\" Format=\"HDF\">@STEM@.h5:/t</DataItem>\n</Topology>\n<Geometry GeometryType=\"XYZ\">\n<DataItem Dimensions=\"@NV@ 3\" Format=\"HDF\">@STEM@.h5:/g</DataItem>\n</Geometry>\n${xe}")
string(REPLACE "@STEM@" "x_missing" content "${xh5}")
string(REPLACE "@NV@" "4" content "${content}")
if(HDF5)
  case(x_missing_h5.xdmf "${content}" ":9: HDF5 file '.*x_missing.h5' \\(of x_missing.h5:/g\\): no such file")
else()
  case(x_missing_h5.xdmf "${content}" "x_missing_h5.xdmf: this build of the package has no HDF5 support")
endif()
execute_process(COMMAND /usr/bin/python3 -c "import h5py" RESULT_VARIABLE no_h5py OUTPUT_QUIET ERROR_QUIET)
if(HDF5 AND no_h5py EQUAL 0)
  # points of 2 coordinates where Dimensions says 3; a dataset of 4 billion points (never written: a
  # tiny file), refused by the memory check before anything is allocated
  execute_process(COMMAND /usr/bin/python3 -c "
import h5py, numpy as np
with h5py.File('${WORK}/x_shape.h5', 'w') as f:
    f['g'] = np.zeros((4, 2)); f['t'] = np.array([[0, 1, 2, 3]], dtype=np.int32)
with h5py.File('${WORK}/x_huge.h5', 'w') as f:
    f.create_dataset('g', (4000000000, 3), dtype='f8', chunks=(1024, 3))
    f.create_dataset('t', (1, 4), dtype='i8', chunks=(1, 4))
" RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    fail(x_h5 "h5py could not write the .h5 files")
  endif()
  string(REPLACE "@STEM@" "x_shape" content "${xh5}")
  string(REPLACE "@NV@" "4" content "${content}")
  case(x_shape.xdmf "${content}" ":9: the geometry: the dataset x_shape.h5:/g has dimensions 4 x 2 \\(8 values\\), Dimensions=\"4 3\" announces 12")
  string(REPLACE "@STEM@" "x_huge" content "${xh5}")
  string(REPLACE "@NV@" "4000000000" content "${content}")
  case(x_huge.xdmf "${content}" ":8: the mesh announced \\(4000000000 vertices, 1 tetrahedra\\) needs about .* refused before reading it")
else()
  message(STATUS "XDMF cases with .h5 files: skipped (prstar without HDF5, or no h5py)")
endif()

# ---------------------------------------------------------------- gmsh (.msh): $NodeData, $ElementData
# (one tetrahedron on lines 16-20; a data section from line 21, its entries from line 30)
set(gh "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n")
set(ge "$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 4\n$EndElements\n")
set(gd "1\n\"d\"\n1\n0\n3\n0\n1\n")
case(g_version.msh "$MeshFormat\n4.0 0 8\n$EndMeshFormat\n" ":2: unsupported .msh format version '4.0'")
case(g_node_tag.msh "${gh}$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 7\n$EndElements\n" ":19: element 1: node tag 7 is not in \\$Nodes")
case(g_nodedata_node.msh "${gh}${ge}$NodeData\n${gd}1\n9 1.5\n$EndNodeData\n" ":30: \\$NodeData 'd': node tag 9 is not in \\$Nodes")
case(g_nodedata_nan.msh "${gh}${ge}$NodeData\n${gd}2\n1 0.5\n2 nan\n$EndNodeData\n" ":31: value 'nan' is not finite")
case(g_nodedata_text.msh "${gh}${ge}$NodeData\n${gd}1\n1 one\n$EndNodeData\n" ":30: value 'one' is not a number")
case(g_nodedata_short.msh "${gh}${ge}$NodeData\n${gd}2\n1 0.5\n$EndNodeData\n" ":31: node tag '\\$EndNodeData' is not an integer")
case(g_nodedata_long.msh "${gh}${ge}$NodeData\n${gd}1\n1 0.5\n2 0.5\n$EndNodeData\n" ":31: expected \\$EndNodeData")
case(g_nodedata_int_tags.msh "${gh}${ge}$NodeData\n1\n\"d\"\n1\n0\n2\n0\n1\n$EndNodeData\n" "2 integer tags, at least 3 expected")
case(g_nodedata_components.msh "${gh}${ge}$NodeData\n1\n\"d\"\n1\n0\n3\n0\n0\n1\n1 1\n$EndNodeData\n" "0 components per entry")
case(g_nodedata_quote.msh "${gh}${ge}$NodeData\n1\n\"d\n1\n0\n" ":23: unterminated string tag")
case(g_nodedata_first.msh "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$NodeData\n${gd}0\n$EndNodeData\n" ":4: \\$NodeData before \\$Nodes")
case(g_nodedata_huge.msh "${gh}${ge}$NodeData\n${gd}1000000000000000\n1 0.5\n" "end of file")
case(g_elementdata_tag.msh "${gh}${ge}$ElementData\n${gd}1\n5 2\n$EndElementData\n" ":30: \\$ElementData 'd': element tag 5 is not in \\$Elements")
case(g_elementdata_first.msh "${gh}$ElementData\n${gd}0\n$EndElementData\n" ":16: \\$ElementData before \\$Elements")
case(g_elementdata_inf.msh "${gh}${ge}$ElementData\n${gd}1\n1 1e999\n$EndElementData\n" ":30: value '1e999' is not finite")

# ---------------------------------------------------------------- counts that fit the index type but lie
# (10^9 vertices announced in a tiny file: reserving for them would exceed the 2 GB address space
# given by prlimit and end in "out of memory" instead of the expected message)
case(l_medit.mesh "${mh}Vertices\n1000000000\n0 0 0 0\n" ":6: vertex 2: unexpected end of file")
tetgen_case(l_tetgen "1000000000 3 0 0\n1 0 0 0\n" "0 4 0\n" node "end of file: 1 points read, 1000000000 declared")
tetgen_case(l_tetgen_ele "${tn}" "1000000000 4 0\n1 1 2 3 4\n" ele "end of file: 1 tetrahedra read, 1000000000 declared")
case(l_vtk.vtk "${vh}POINTS 1000000000 float\n0 0 0\n" "end of file")
case(l_vtk_cells.vtk "${vh}${vp}CELLS 1000000000 5000000000\n4 0 1 2 3\n" "end of file")
case(l_vtu.vtu "${uh}<Piece NumberOfPoints=\"1000000000\" NumberOfCells=\"1000000000\">\n<Points>\n<DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">MAAAAAAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/AAAAAAAAAAAAAAAAAACAPw==</DataArray>\n</Points>\n${uc}${ue}"
     "(48 bytes|12 values|expected 3000000000|3000000000)")
case(l_off.off "1000000000 1000000000\n0 0 0\n" "end of file: 1 vertices read, 1000000000 declared")

# ---------------------------------------------------------------- a vertex listed twice in a tetrahedron
# (PR_star_octree_3 refuses these; the readers refuse them first, with the file and the line)
case(r_medit.mesh "${mh}${mv}Tetrahedra\n1\n1 2 2 4 0\nEnd\n" ":11: tetrahedron 1: vertex index 2 listed twice")
tetgen_case(r_tetgen "${tn}" "1 4 0\n1 1 2 3 1\n" ele ":2: tetrahedron 1: vertex index 1 listed twice")
case(r_vtk.vtk "${vh}${vp}CELLS 1 5\n4 0 1 3 3\nCELL_TYPES 1\n10\n" "cell 0: vertex index 3 listed twice")
case(r_vtu.vtu "${uh}${up}<Cells>\n<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 0 2 3</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">4</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10</DataArray>\n</Cells>\n${ue}"
     "cell 0: vertex index 0 listed twice")
case(r_off.off "5 1\n${ov}0 1 1 3\n" ":7: tetrahedron 1: vertex index 1 listed twice")

# ---------------------------------------------------------------- the file system says no
file(MAKE_DIRECTORY "${WORK}/f_directory.mesh")
check(f_directory "${WORK}/f_directory.mesh" "is a directory")
check(f_missing_dir "${WORK}/no/such/folder/a.vtk" "no such file")
check(f_missing "${WORK}/missing.vtu" "no such file")
case(f_unknown_extension.xyz "0 0 0\n" "unknown file extension '\\.xyz'")
case(f_no_extension "0 0 0\n" "no file extension")

get_property(cases GLOBAL PROPERTY cases)
get_property(failures GLOBAL PROPERTY failures)
message(STATUS "test_malformed: ${cases} cases, ${failures} failures")
if(cases LESS 30)
  message(FATAL_ERROR "test_malformed: only ${cases} cases")
endif()
