# Opens a run's XDMF sidecar with VTK's XDMF reader (the one behind ParaView's "XDMF Reader")
# and prints, per time step and per grid (one per participant with fields, and one per
# point set), the grid and every cell array's size and sum, to compare with the HDF5
# datasets. Needs ParaView (Debian paraview): pvpython scripts/check_xdmf.py run.xmf
# A sidecar with a Mixed topology (the tracker's polyhedra) is read with the Xdmf3 reader
# (ParaView's "XDMF Reader (Xdmf3ReaderS)"): ParaView 5.11's Xdmf2 reader has no polyhedra.
# Each Polyvertex grid (a point set) is first checked against the HDF5 file (with h5py):
# its dataset must exist with the shape its DataItem declares, NumberOfElements x 3; the
# script exits 1 naming the first that does not.
import os
import sys
import xml.etree.ElementTree as ET

from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as S

mixed = 'TopologyType="Mixed"' in open(sys.argv[1]).read()
if mixed:
    from vtkmodules.vtkIOXdmf3 import vtkXdmf3Reader as Reader
else:
    from vtkmodules.vtkIOXdmf2 import vtkXdmfReader as Reader


def polyvertex_problem(grid, folder):
    """Why a Polyvertex grid's points are not its dataset's, or None."""
    n = int(grid.find("Topology").get("NumberOfElements"))
    items = grid.findall("Geometry/DataItem")
    if len(items) != 1:
        return "%d DataItems in its geometry, not 1" % len(items)
    declared = tuple(int(d) for d in items[0].get("Dimensions").split())
    if declared != (n, 3):
        return "DataItem of %s for %d elements" % (declared, n)
    import h5py  # only sidecars with point sets need it

    h5_file, dataset = items[0].text.strip().split(":", 1)
    with h5py.File(os.path.join(folder, h5_file), "r") as f:
        if dataset not in f:
            return "no dataset %s in %s" % (dataset, h5_file)
        if f[dataset].shape != declared:
            return "dataset %s of shape %s, declared %s" % (dataset, f[dataset].shape, declared)
    return None


checked = 0
for grid in ET.parse(sys.argv[1]).iter("Grid"):
    topology = grid.find("Topology")
    if topology is None or topology.get("TopologyType") != "Polyvertex":
        continue
    problem = polyvertex_problem(grid, os.path.dirname(os.path.abspath(sys.argv[1])))
    if problem:
        sys.exit("Polyvertex grid %s: %s" % (grid.get("Name"), problem))
    checked += 1
if checked:
    print("%d Polyvertex grids match their datasets" % checked)


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
        # A point set has points and no cell arrays (vertex cells from Xdmf2, none from Xdmf3).
        shape = ("dims %s" % (d.GetDimensions(),) if hasattr(d, "GetDimensions")
                 else "%d cells, %d points" % (d.GetNumberOfCells(), d.GetNumberOfPoints()))
        print("t=%g %s %s: %s" % (t, d.GetClassName(), shape, ", ".join(out)))
