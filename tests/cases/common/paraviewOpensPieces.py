#------------------------------------------------------------------------------
# tests/cases/common/paraviewOpensPieces.py MASTER_VTK OWNED_VTK
# (run with bin/pvbatch-xvfb)
#
# ParaView opens owned mode's VTK series of pieces (polyhedra.pvtp.series)
# as one data set with, at its last output, the cells, points and cell
# arrays of master mode's polyhedra.vtp.series. Exit status 1 otherwise.
#------------------------------------------------------------------------------
import sys
from paraview.simple import OpenDataFile

masterDir, ownedDir = sys.argv[1], sys.argv[2]
counts = []
for path in (masterDir + "/polyhedra.vtp.series", ownedDir + "/polyhedra.pvtp.series"):
    reader = OpenDataFile(path)
    last = reader.TimestepValues[-1] if len(reader.TimestepValues) else 0
    reader.UpdatePipeline(last)
    info = reader.GetDataInformation()
    counts.append((reader.GetXMLName(), len(reader.TimestepValues), info.GetNumberOfCells(),
                   info.GetNumberOfPoints(), sorted(reader.CellData.keys())))
    print(f"{path}: {counts[-1][0]}, {counts[-1][1]} outputs; at the last: {counts[-1][2]} cells,"
          f" {counts[-1][3]} points, cell arrays {counts[-1][4]}")
same = counts[0][1:] == counts[1][1:] and counts[0][2] > 0
print("ParaView opens the pieces as master mode's files" if same else "FAIL: ParaView sees different data")
sys.exit(0 if same else 1)
