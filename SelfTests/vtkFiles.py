"""Reading ParaView files with VTK's own readers (Debian python3-vtk9), for the tests that check
what Talus writes: checkVtu.py (particle frames) and Tools/CG/Tests/checkVtkOutput.py
(coarse-grained fields). Import it after `import vtk` has succeeded; `fail(message)` is the
caller's way to stop with a message."""
import vtk


def pvd_entries(path, fail):
    """The (time, file) of each DataSet of a .pvd Collection, parsed by vtkXMLDataParser (the
    parser of VTK's collection readers)."""
    parser = vtk.vtkXMLDataParser()
    parser.SetFileName(path)
    if not parser.Parse():
        fail(f"{path}: VTK cannot parse it")
    root = parser.GetRootElement()
    if root.GetName() != "VTKFile" or root.GetAttribute("type") != "Collection":
        fail(f"{path}: not a VTK Collection file")
    collection = root.FindNestedElementWithName("Collection")
    entries = []
    for k in range(collection.GetNumberOfNestedElements()):
        d = collection.GetNestedElement(k)
        entries.append((float(d.GetAttribute("timestep")), d.GetAttribute("file")))
    return entries


def read_without_complaint(reader, path, fail):
    """The data set `reader` (a vtkXML...Reader) reads from `path`; any error or warning it
    reports fails."""
    problems = []
    for event in ("ErrorEvent", "WarningEvent"):
        reader.AddObserver(event, lambda obj, ev: problems.append(ev))
    reader.SetFileName(path)
    reader.Update()
    if problems or reader.GetErrorCode() != 0:
        fail(f"{path}: VTK's reader reports {problems or reader.GetErrorCode()}")
    return reader.GetOutput()
