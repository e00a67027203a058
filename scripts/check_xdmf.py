# Opens a run's XDMF sidecar with VTK's XDMF reader (the one behind ParaView's "XDMF Reader")
# and prints, per time step and per grid (one per participant with fields), the grid and
# every cell array's size and sum, to compare with the HDF5 datasets. Needs ParaView
# (Debian paraview): pvpython scripts/check_xdmf.py run.xmf
# A sidecar with a Mixed topology (the tracker's polyhedra) is read with the Xdmf3 reader
# (ParaView's "XDMF Reader (Xdmf3ReaderS)"): ParaView 5.11's Xdmf2 reader has no polyhedra.
import os
import sys
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as S

mixed = 'TopologyType="Mixed"' in open(sys.argv[1]).read()
if mixed:
    from vtkmodules.vtkIOXdmf3 import vtkXdmf3Reader as Reader
else:
    from vtkmodules.vtkIOXdmf2 import vtkXdmfReader as Reader


def grids(d):
    """The grids inside the readers' blocks (the Xdmf3 reader wraps even a single one)."""
    if d is None:
        return
    if d.IsA("vtkMultiBlockDataSet"):
        for i in range(d.GetNumberOfBlocks()):
            yield from grids(d.GetBlock(i))
    else:
        yield d


r = Reader()
# The Xdmf3 reader joins a bare file name to the HDF5 one ("run.xmfrun.h5"): give it a path.
r.SetFileName(os.path.abspath(sys.argv[1]))
r.UpdateInformation()
info = r.GetOutputInformation(0)
times = info.Get(S.TIME_STEPS()) or [0.0]
for t in times:
    r.UpdateTimeStep(t)
    for d in grids(r.GetOutputDataObject(0)):
        cd = d.GetCellData()
        out = []
        for i in range(cd.GetNumberOfArrays()):
            a = cd.GetArray(i)
            s = sum(a.GetComponent(j, c) for j in range(a.GetNumberOfTuples()) for c in range(a.GetNumberOfComponents()))
            out.append("%s[%dx%d] sum %.6g" % (a.GetName(), a.GetNumberOfTuples(), a.GetNumberOfComponents(), s))
        shape = "dims %s" % (d.GetDimensions(),) if hasattr(d, "GetDimensions") else "%d cells" % d.GetNumberOfCells()
        print("t=%g %s %s: %s" % (t, d.GetClassName(), shape, ", ".join(out)))
