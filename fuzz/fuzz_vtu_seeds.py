#!/usr/bin/python3
"""Seeds of fuzz_vtu and fuzz_vtk for the compressed and binary paths, written by VTK itself:
VTU with zlib, lz4 and lzma blocks (inline base64 and appended raw, UInt32 and UInt64 headers, both
byte orders, small blocks so that files have several), and legacy VTK binary (5.1 and 4.2), on a
small grid with tetrahedra, a triangle, labels and point data.  Skipped (with a message) when VTK's
Python bindings are absent; make_seeds.py writes the other seeds.

Usage: fuzz_vtu_seeds.py OUT   (writes OUT/vtu/z_* and OUT/vtk/z_*)
"""
import os
import sys

out = sys.argv[1] if len(sys.argv) > 1 else "corpus"
try:
    import vtk
except ImportError:
    print("fuzz_vtu_seeds.py: no VTK Python bindings, compressed/binary seeds not written")
    sys.exit(0)

pts = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 1)]
g = vtk.vtkUnstructuredGrid()
p = vtk.vtkPoints()
for x in pts:
    p.InsertNextPoint(*x)
g.SetPoints(p)
for t, ids in ((10, (0, 1, 2, 3)), (10, (1, 2, 3, 4)), (5, (0, 1, 2))):
    idl = vtk.vtkIdList()
    for i in ids:
        idl.InsertNextId(i)
    g.InsertNextCell(t, idl)
lab = vtk.vtkIntArray()
lab.SetName("label")
for v in (3, 4, 5):
    lab.InsertNextValue(v)
g.GetCellData().AddArray(lab)
temp = vtk.vtkDoubleArray()
temp.SetName("temperature")
for v in (0.5, 1, 2, 3, 4):
    temp.InsertNextValue(v)
g.GetPointData().AddArray(temp)

for d in ("vtu", "vtk"):
    os.makedirs(os.path.join(out, d), exist_ok=True)
n = 0
for comp in ("ZLib", "LZ4", "LZMA"):
    for mode in ("Binary", "Appended"):
        for header in ("UInt32", "UInt64"):
            for order in ("LittleEndian", "BigEndian"):
                w = vtk.vtkXMLUnstructuredGridWriter()
                w.SetFileName(os.path.join(out, "vtu", f"z_{comp}_{mode}_{header}_{order}.vtu"))
                w.SetInputData(g)
                getattr(w, f"SetCompressorTypeTo{comp}")()
                w.SetBlockSize(64)
                getattr(w, f"SetDataModeTo{mode}")()
                w.SetEncodeAppendedData(False)
                getattr(w, f"SetHeaderTypeTo{header}")()
                getattr(w, f"SetByteOrderTo{order}")()
                w.Write()
                n += 1
for version in (51, 42):
    w = vtk.vtkUnstructuredGridWriter()
    w.SetFileName(os.path.join(out, "vtk", f"z_binary_{version}.vtk"))
    w.SetInputData(g)
    w.SetFileTypeToBinary()
    if hasattr(w, "SetFileVersion"):
        w.SetFileVersion(version)
    w.Write()
    n += 1
print(f"fuzz_vtu_seeds.py: {n} seeds")
