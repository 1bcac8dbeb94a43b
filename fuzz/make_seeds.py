#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets (small valid files, written here) into OUT/<reader>/.

Usage: make_seeds.py OUT
"""
import base64
import os
import struct
import sys

out = sys.argv[1] if len(sys.argv) > 1 else "corpus"

P = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 1)]
T = [(0, 1, 2, 3), (1, 2, 3, 4)]


def put(reader, name, data):
    d = os.path.join(out, reader)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


# ---- Medit
pts = "".join("%g %g %g %d\n" % (p + (i % 2,)) for i, p in enumerate(P))
tets = "".join("%d %d %d %d 1\n" % tuple(v + 1 for v in t) for t in T)
put("medit", "a.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices\n5\n" + pts + "Tetrahedra\n2\n" + tets + "End\n")
put("medit", "b.mesh", "# c\nMeshVersionFormatted 1\nDimension\n3\nTetrahedra 1\n5 4 3 2 9\nEdges 1\n1 2 0\n"
    "Triangles\n1\n1 2 3 7\nCorners 1 5\nRequiredVertices\n1\n2\nVertices 5\n" + pts)
put("medit", "c.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices 4\n0 0 0 0\n1e-300 0 0 0\n0 1e300 0 0\n"
    "0 0 -1 0\nTetrahedra 1\n1 2 3 4 0\nEnd\n")

# ---- TetGen (.node NUL .ele)
node = "5 3 1 1\n" + "".join("%d %g %g %g 0.5 %d\n" % ((i + 1,) + p + (i % 2,)) for i, p in enumerate(P))
ele = "2 4 1\n" + "".join("%d %d %d %d %d 3\n" % ((i + 1,) + tuple(v + 1 for v in t)) for i, t in enumerate(T))
put("tetgen", "a", node + "\0" + ele)
node0 = "# zero based\n5 3\n" + "".join("%d %g %g %g\n" % ((i,) + p) for i, p in enumerate(P))
ele0 = "2 4\n" + "".join("%d %d %d %d %d\n" % ((i,) + t) for i, t in enumerate(T))
put("tetgen", "b", node0 + "\0" + ele0)
put("tetgen", "c", "2 10 1\n0 0 1 2 3 0 0 0 0 0 0 2.0\n1 1 2 3 4 0 0 0 0 0 0 -3.2\n")
put("tetgen", "d", node0 + "\0" + "1 10 0\n0 0 1 2 3 4 4 4 4 4 4\n")

# ---- legacy VTK
head = "# vtk DataFile Version 4.2\nsmall mesh\nASCII\nDATASET UNSTRUCTURED_GRID\n"
vp = "POINTS 5 float\n" + " ".join("%g %g %g" % p for p in P) + "\n"
put("vtk", "a.vtk", head + vp + "CELLS 2 10\n4 0 1 2 3\n4 1 2 3 4\nCELL_TYPES 2\n10\n10\n"
    "CELL_DATA 2\nSCALARS label int 1\nLOOKUP_TABLE default\n3 4\nVECTORS v double\n1 2 3 4 5 6\n"
    "POINT_DATA 5\nSCALARS temp%20x float\nLOOKUP_TABLE default\n0.5 1 2 3 4\n"
    "SCALARS rgb float 3\n0 0 0 1 1 1 2 2 2 3 3 3 4 4 4\nNORMALS n float\n0 0 1 0 0 1 0 0 1 0 0 1 0 0 1\n"
    "FIELD FieldData 2\nf 1 5 double\n10 11 12 13 14\ng 2 5 int\n0 0 0 0 0 0 0 0 0 0\n")
put("vtk", "b.vtk", "# vtk DataFile Version 5.1\nvtk output\nASCII\nDATASET UNSTRUCTURED_GRID\n"
    "POINTS 5 double\n0 0 0 1 0 0 0 1 0 0 0 1 1 1 1\nCELLS 3 8\nOFFSETS vtktypeint64\n0 4 8\n"
    "CONNECTIVITY vtktypeint64\n0 1 2 3 1 2 3 4\nCELL_TYPES 2\n10 10\n")
put("vtk", "c.vtk", head + vp + "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n"
    "CELL_DATA 1\nFIELD F 1\nid 1 1 int\n1\nPOINT_DATA 5\nSCALARS s double\n0 1 2 3 4\n")

# ---- VTK XML
def vtu(fmt, header="UInt32", appended=None):
    pf = struct.pack("<15d", *[c for p in P for c in p])
    conn = struct.pack("<8q", *[v for t in T for v in t])
    offs = struct.pack("<2q", 4, 8)
    types = struct.pack("<2B", 10, 10)
    temp = struct.pack("<5d", 0.5, 1, 2, 3, 4)
    hfmt = "<I" if header == "UInt32" else "<Q"
    arrays = [("temp", "Float64", 1, temp), ("", "Float64", 3, pf), ("connectivity", "Int64", 1, conn),
              ("offsets", "Int64", 1, offs), ("types", "UInt8", 1, types)]
    body = {}
    app = b""
    for name, typ, nc, data in arrays:
        if fmt == "ascii":
            if typ == "Float64":
                vals = struct.unpack("<%dd" % (len(data) // 8), data)
            elif typ == "Int64":
                vals = struct.unpack("<%dq" % (len(data) // 8), data)
            else:
                vals = data
            body[name] = ("format=\"ascii\"", " ".join(str(v) for v in vals))
        elif fmt == "binary":
            body[name] = ("format=\"binary\"", base64.b64encode(struct.pack(hfmt, len(data)) + data).decode())
        else:
            blob = struct.pack(hfmt, len(data)) + data
            off = len(app)
            app += base64.b64encode(blob) if appended == "base64" else blob
            body[name] = ("format=\"appended\" offset=\"%d\"" % off, "")

    def da(name, typ, nc):
        f, txt = body[name]
        n = (" Name=\"%s\"" % name) if name else ""
        return "<DataArray type=\"%s\"%s NumberOfComponents=\"%d\" %s>%s</DataArray>\n" % (typ, n, nc, f, txt)

    s = ("<?xml version=\"1.0\"?>\n<!-- comment -->\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
         "byte_order=\"LittleEndian\" header_type=\"%s\">\n<UnstructuredGrid>\n"
         "<Piece NumberOfPoints=\"5\" NumberOfCells='2'>\n<PointData Scalars=\"temp\">\n" % header)
    s += da("temp", "Float64", 1) + "</PointData>\n<Points>\n" + da("", "Float64", 3) + "</Points>\n<Cells>\n"
    s += da("connectivity", "Int64", 1) + da("offsets", "Int64", 1) + da("types", "UInt8", 1)
    s += "</Cells>\n</Piece>\n</UnstructuredGrid>\n"
    b = s.encode()
    if fmt == "appended":
        b += ("<AppendedData encoding=\"%s\">\n_" % appended).encode() + app + b"\n</AppendedData>\n"
    return b + b"</VTKFile>\n"


put("vtu", "ascii.vtu", vtu("ascii"))
put("vtu", "bin32.vtu", vtu("binary", "UInt32"))
put("vtu", "bin64.vtu", vtu("binary", "UInt64"))
put("vtu", "raw.vtu", vtu("appended", "UInt64", "raw"))
put("vtu", "b64.vtu", vtu("appended", "UInt32", "base64"))
put("vtu", "cdata.vtu", "<?xml version='1.0'?><VTKFile type='UnstructuredGrid' byte_order='BigEndian'>"
    "<UnstructuredGrid><Piece NumberOfPoints='4' NumberOfCells='1'><Points>"
    "<DataArray type='Float32' NumberOfComponents='3' format='ascii'><![CDATA[0 0 0 1 0 0 0 1 0 0 0 1]]>"
    "</DataArray></Points><Cells><DataArray type='Int32' Name='connectivity' format='ascii'>0 1 2 3</DataArray>"
    "<DataArray type='Int32' Name='offsets' format='ascii'>4</DataArray>"
    "<DataArray type='Int32' Name='types' format='ascii'>10</DataArray></Cells></Piece></UnstructuredGrid>"
    "</VTKFile>")

# ---- .off / .ts tetrahedral
put("tet_off", "a.off", "OFF\n# comment\n5 2\n0 0 0 0.5\n1 0 0 1\n0 1 0 2\n0 0 1 3\n1 1 1 4\n0 1 2 3\n1 2 3 4\n")
put("tet_off", "b.ts", "5\n2\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n\n4 0 1 2 3\n4 1 2 3 4\n# trailing\n")
put("tet_off", "c.off", "5 2\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n0 1 2 3\n1 2 3 4\n")

# ---- gmsh .msh (2.2 and 4.1, ASCII and binary; mixed elements, sparse tags, physical names)
TAGS = [10, 3, 700, 8, 9]
names = "$PhysicalNames\n2\n3 7 \"left\"\n2 5 \"skin\"\n$EndPhysicalNames\n"
put("msh", "a22.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n" + names + "$Nodes\n5\n" +
    "".join("%d %g %g %g\n" % ((TAGS[i],) + p) for i, p in enumerate(P)) + "$EndNodes\n$Elements\n4\n"
    "1 15 2 0 1 10\n2 2 2 5 1 10 3 700\n3 4 2 7 1 10 3 700 8\n4 4 3 9 2 0 3 700 8 9\n$EndElements\n"
    "$NodeData\n1\n\"t\"\n1\n0.0\n3\n0\n1\n1\n10 1.5\n$EndNodeData\n")
put("msh", "a41.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n" + names +
    "$Entities\n1 0 1 2\n1 0 0 0 0\n2 0 0 0 1 1 0 1 5 0\n1 0 0 0 1 1 1 1 7 1 2\n2 0 0 0 1 1 1 0 0\n$EndEntities\n"
    "$Nodes\n2 5 3 700\n3 1 0 3\n10\n3\n700\n0 0 0\n1 0 0\n0 1 0\n2 2 1 2\n8\n9\n0 0 1 0.5 0.5\n1 1 1 0 0\n"
    "$EndNodes\n$Elements\n3 4 1 4\n2 2 2 1\n1 10 3 700\n3 1 4 2\n2 10 3 700 8\n3 3 700 8 9\n"
    "3 2 11 1\n4 10 3 700 8 9 9 9 9 9 9\n$EndElements\n")


def msh41_binary(endian):
    q = lambda *v: struct.pack(endian + "%dQ" % len(v), *v)
    i = lambda *v: struct.pack(endian + "%di" % len(v), *v)
    d = lambda *v: struct.pack(endian + "%dd" % len(v), *v)
    b = b"$MeshFormat\n4.1 1 8\n" + i(1) + b"\n$EndMeshFormat\n$Entities\n" + q(0, 0, 0, 1)
    b += i(1) + d(0, 0, 0, 1, 1, 1) + q(1) + i(7) + q(0) + b"\n$EndEntities\n$Nodes\n" + q(1, 5, 3, 700)
    b += i(3, 1, 0) + q(5) + q(*TAGS) + d(*[c for p in P for c in p]) + b"\n$EndNodes\n$Elements\n"
    b += q(2, 3, 1, 3) + i(3, 1, 4) + q(2) + q(1, 10, 3, 700, 8) + q(2, 3, 700, 8, 9)
    b += i(2, 1, 2) + q(1) + q(3, 10, 3, 700) + b"\n$EndElements\n"
    return b


def msh22_binary(endian):
    i = lambda *v: struct.pack(endian + "%di" % len(v), *v)
    d = lambda *v: struct.pack(endian + "%dd" % len(v), *v)
    b = b"$MeshFormat\n2.2 1 8\n" + i(1) + b"\n$EndMeshFormat\n$Nodes\n5\n"
    b += b"".join(i(TAGS[k]) + d(*p) for k, p in enumerate(P)) + b"\n$EndNodes\n$Elements\n3\n"
    b += i(4, 2, 2) + i(1, 7, 1, 10, 3, 700, 8) + i(2, 0, 1, 3, 700, 8, 9) + i(15, 1, 1) + i(3, 0, 9)
    return b + b"\n$EndElements\n"


put("msh", "b41.msh", msh41_binary("<"))
put("msh", "b41be.msh", msh41_binary(">"))
put("msh", "b22.msh", msh22_binary("<"))
put("msh", "b22be.msh", msh22_binary(">"))


# ---- Medit binary .meshb (versions 1-4, both byte orders, a skipped keyword)
def meshb(version, endian):
    r = "f" if version == 1 else "d"
    n = "q" if version == 4 else "i"
    pos = "q" if version >= 3 else "i"
    k = lambda v: struct.pack(endian + "i", v)
    body = b""
    out = k(1) + k(version)
    size = lambda fmt: struct.calcsize(endian + fmt)
    at = len(out)
    out += k(3) + struct.pack(endian + pos, at + 4 + size(pos) + 4) + k(3)
    tri = struct.pack(endian + n * 5, 1, 1, 2, 3, 0)
    at = len(out)
    out += k(6) + struct.pack(endian + pos, at + 4 + size(pos) + len(tri)) + tri
    verts = struct.pack(endian + n, 5) + b"".join(struct.pack(endian + r * 3 + n, *(p + (0,))) for p in P)
    at = len(out)
    out += k(4) + struct.pack(endian + pos, at + 4 + size(pos) + len(verts)) + verts
    tets = struct.pack(endian + n, 2) + b"".join(struct.pack(endian + n * 5, *([v + 1 for v in t] + [3])) for t in T)
    at = len(out)
    out += k(8) + struct.pack(endian + pos, at + 4 + size(pos) + len(tets)) + tets
    return out + k(54) + struct.pack(endian + pos, 0) + body


for version in (1, 2, 3, 4):
    put("meshb", "v%d.meshb" % version, meshb(version, "<"))
put("meshb", "v2be.meshb", meshb(2, ">"))
put("msh", "p41.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 0 1\n1 0 0 0 1 1 1 1 7 0\n$EndEntities\n"
    "$PartitionedEntities\n2\n1\n5 2\n0 0 0 2\n5 3 1 1 1 0 0 0 1 1 1 1 7 0\n6 3 1 1 2 0 0 0 1 1 1 0 0\n"
    "$EndPartitionedEntities\n$Nodes\n1 5 1 5\n3 5 0 5\n1\n2\n3\n4\n5\n" +
    "".join("%g %g %g\n" % p for p in P) + "$EndNodes\n$Elements\n2 2 1 2\n3 5 4 1\n1 1 2 3 4\n3 6 4 1\n2 2 3 4 5\n"
    "$EndElements\n")


# $NodeData and $ElementData: views split over sections, two time steps, a vector view, element data on a
# triangle and on tetrahedra out of tag order; the binary ones with 4-byte tags after a text header
def msh_data(tag_line, binary, endian="<"):
    i = lambda *v: struct.pack(endian + "%di" % len(v), *v)
    d = lambda *v: struct.pack(endian + "%dd" % len(v), *v)

    def view(section, name, step, comps, entries):
        head = ("$%s\n1\n\"%s\"\n1\n0.5\n3\n%d\n%d\n%d\n" % (section, name, step, comps, len(entries))).encode()
        if binary:
            body = b"".join(i(t) + d(*v) for t, v in entries) + b"\n"
        else:
            body = "".join("%d %s\n" % (t, " ".join(repr(x) for x in v)) for t, v in entries).encode()
        return head + body + ("$End%s\n" % section).encode()

    nodes = [(TAGS[k], (0.1 * k,)) for k in range(5)]
    return (view("NodeData", "T", 0, 1, nodes[:3]) + view("NodeData", "T", 0, 1, nodes[3:]) +
            view("NodeData", "T", 1, 1, nodes[::-1]) + view("NodeData", "V", 0, 3, [(10, (1.0, 2.0, 3.0))]) +
            view("ElementData", "E", 0, 1, [(t, (v,)) for t, v in zip(tag_line, (0.5, 1e-300, -2.0, 7.25))]))


put("msh", "d41.msh", open(os.path.join(out, "msh", "a41.msh"), "rb").read() + msh_data((3, 1, 2, 4), False))
put("msh", "d22.msh", open(os.path.join(out, "msh", "a22.msh"), "rb").read() + msh_data((4, 2, 3), False))
put("msh", "d41b.msh", msh41_binary("<") + msh_data((2, 3, 1), True))
put("msh", "d22be.msh", msh22_binary(">") + msh_data((1, 2, 3), True, ">"))

# ---- XDMF (.xdmf): inline XML only (a fuzz input is one stream; HDF5 references are refused there)
xyz = " ".join("%g %g %g" % p for p in P)
conn = " ".join("%d %d %d %d" % t for t in T)


def xdmf(grid, version="3.0"):
    return ("<?xml version=\"1.0\"?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"%s\" "
            "xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n<Domain>\n%s</Domain>\n</Xdmf>\n" % (version, grid))


geo = "<Geometry GeometryType=\"XYZ\"><DataItem Dimensions=\"5 3\" DataType=\"Float\" Precision=\"8\" " \
      "Format=\"XML\">%s</DataItem></Geometry>\n" % xyz
put("xdmf", "tet.xdmf", xdmf(
    "<Grid Name=\"mesh\" GridType=\"Uniform\">\n<Topology TopologyType=\"Tetrahedron\" NumberOfElements=\"2\" "
    "NodesPerElement=\"4\"><DataItem Dimensions=\"2 4\" DataType=\"Int\" Precision=\"8\" Format=\"XML\">%s"
    "</DataItem></Topology>\n%s<Attribute Name=\"phi\" AttributeType=\"Scalar\" Center=\"Node\"><DataItem "
    "Dimensions=\"5\" Format=\"XML\">0.5 1 2 3 4</DataItem></Attribute>\n<Attribute Name=\"label\" "
    "AttributeType=\"Scalar\" Center=\"Cell\"><DataItem Dimensions=\"2\" DataType=\"Int\" Precision=\"4\" "
    "Format=\"XML\">3 7</DataItem></Attribute>\n<Attribute Name=\"q\" Center=\"Cell\"><DataItem Dimensions=\"2 1\" "
    "Format=\"XML\">0.25 1e-300</DataItem></Attribute>\n</Grid>\n" % (conn, geo)))
put("xdmf", "mixed.xdmf", xdmf(
    "<Grid Name=\"mesh\">\n<Topology TopologyType=\"Mixed\" NumberOfElements=\"5\"><DataItem Dimensions=\"24\" "
    "NumberType=\"Int\" Format=\"XML\">6 0 1 2 3 4 0 1 2 2 2 3 4 16 1 3 0 1 2 6 1 2 3 4</DataItem></Topology>\n"
    "%s<Attribute Name=\"gmsh:physical\" Center=\"Cell\"><DataItem Dimensions=\"5\" NumberType=\"UInt\" "
    "Format=\"XML\">1 2 3 4 5</DataItem></Attribute>\n<Attribute Name=\"v\" AttributeType=\"Vector\" "
    "Center=\"Node\"><DataItem Dimensions=\"5 3\" Format=\"XML\">%s</DataItem></Attribute>\n</Grid>\n" % (geo, xyz),
    "2.0"))
put("xdmf", "series.xdmf", xdmf(
    "<Grid Name=\"TimeSeries\" GridType=\"Collection\" CollectionType=\"Temporal\">\n<Grid>"
    "<xi:include xpointer=\"xpointer(//Grid[@Name=&quot;mesh&quot;]/*[self::Topology or self::Geometry])\" />"
    "<Time Value=\"0.0\" /><Attribute Name=\"name_to_read\" Center=\"Cell\"><DataItem Dimensions=\"2\" "
    "DataType=\"Int\" Format=\"XML\">5 6</DataItem></Attribute></Grid>\n</Grid>\n<Grid Name=\"mesh\" "
    "GridType=\"Uniform\">%s<Topology Type=\"Tetrahedron\" BaseOffset=\"1\"><DataItem Dimensions=\"8\" "
    "DataType=\"Int\" Format=\"XML\">%s</DataItem></Topology></Grid>\n"
    % (geo, " ".join(str(v + 1) for t in T for v in t))))
