# Opens a run's XDMF sidecar with VTK's XDMF reader (the one behind ParaView's "XDMF Reader")
# and prints, per time step, the grid and every cell array's size and sum, to compare with
# the HDF5 datasets. Needs ParaView (Debian paraview): pvpython scripts/check_xdmf.py run.xmf
import sys
from vtkmodules.vtkIOXdmf2 import vtkXdmfReader
r = vtkXdmfReader()
r.SetFileName(sys.argv[1])
r.UpdateInformation()
info = r.GetOutputInformation(0)
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as S
times = info.Get(S.TIME_STEPS()) or [0.0]
for t in times:
    r.UpdateTimeStep(t)
    d = r.GetOutputDataObject(0)
    cd = d.GetCellData()
    out = []
    for i in range(cd.GetNumberOfArrays()):
        a = cd.GetArray(i)
        s = sum(a.GetComponent(j, c) for j in range(a.GetNumberOfTuples()) for c in range(a.GetNumberOfComponents()))
        out.append("%s[%dx%d] sum %.6g" % (a.GetName(), a.GetNumberOfTuples(), a.GetNumberOfComponents(), s))
    print("t=%g %s dims %s: %s" % (t, d.GetClassName(), d.GetDimensions(), ", ".join(out)))
