"""pvbatch: the plugin's server-manager XML is valid and complete.

- The XML parses, ParaView knows the proxy it defines, and "PPIRay Volume" is
  offered for unstructured grids and for structured grids.
- Every property the XML declares appears in the display's ListProperties()
  and its default equals the mapper's own default (so the GUI starts where a
  VTK user of the mapper starts).
- Setting each one reaches the mapper.

PLUGIN "auto": the plugin is not loaded by the script but must have been
auto-loaded from PV_PLUGIN_PATH.

Usage: pvbatch TestPPIRayPluginXML.py PLUGIN|auto XML
"""
import os
import sys
import xml.etree.ElementTree as ElementTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ppiray_pvtest as pt  # noqa: E402

from paraview import servermanager  # noqa: E402
from paraview.simple import Hide, Render, Show, Tetrahedralize, Transform, Wavelet  # noqa: E402

# A value different from the default for each property, and the mapper getter.
NEW_VALUES = {
    "IntegrationMode": ("Exact Linear", 1, "GetIntegrationMode"),
    "HexahedronMode": ("Fast", 1, "GetHexahedronMode"),
    "PPIRayNonlinearSubdivisionLevel": (2, 2, "GetNonlinearSubdivisionLevel"),
    "MaximumNumberOfPeels": (7, 7, "GetMaximumNumberOfPeels"),
    "NonConvexMode": ("Automatic", 2, "GetNonConvexMode"),
    "TetrahedronLayout": ("Compact", 1, "GetTetrahedronLayout"),
    "MarchStage": ("Compute", 1, "GetMarchStage"),
    "PsiTableSize": (128, 128, "GetPsiTableSize"),
    "PreIntegrationTableSize": (32, 32, "GetPreIntegrationTableSize"),
    "TerminationOpacity": (0.95, 0.95, "GetTerminationOpacity"),
    "PPIRayBlendMode": ("Isosurfaces", 5, "GetBlendMode"),
    "PPIRayAverageIPScalarRange": ([10.0, 20.0], [10.0, 20.0], "GetAverageIPScalarRange"),
    # Repeatable, no default; kept in the volume property (rendering checked
    # by TestPPIRayRepresentation).
    "PPIRayIsosurfaceValues": ([100.0, 150.0], None, None),
    "Shade": (1, None, None),
}


def numbers(value):
    """A property value, an XML default string or a getter's result as a list of floats."""
    if isinstance(value, str):
        return [float(x) for x in value.split()]
    return [float(x) for x in value] if hasattr(value, "__len__") else [float(value)]


def same(a, b):
    """Equal within float precision (defaults such as VTK_FLOAT_MAX pass through float)."""
    a, b = numbers(a), numbers(b)
    return len(a) == len(b) and all(abs(x - y) <= 1e-6 * max(1.0, abs(x)) for x, y in zip(a, b))


def declared_properties(xml_path):
    """{name: default string} of the properties PPIRayVolumeRepresentation declares."""
    root = ElementTree.parse(xml_path).getroot()
    proxy = root.find("./ProxyGroup/RepresentationProxy[@name='PPIRayVolumeRepresentation']")
    if proxy is None:
        pt.fail("no PPIRayVolumeRepresentation in %s" % xml_path)
    return {p.get("name"): p.get("default_values") for p in proxy
            if p.tag.endswith("VectorProperty")}


def main(plugin, xml_path):
    if plugin != "auto":
        pt.load_plugin(plugin)
    failures = []
    declared = declared_properties(xml_path)
    if set(declared) != set(NEW_VALUES):
        failures.append("declared properties %s; this test knows %s"
                        % (sorted(declared), sorted(NEW_VALUES)))

    definitions = servermanager.ProxyManager().GetProxyDefinitionManager()
    if not definitions.HasDefinition("representations", "PPIRayVolumeRepresentation"):
        failures.append("ParaView did not register PPIRayVolumeRepresentation")

    view = pt.render_view((64, 64))
    # Structured grids get the representation too (PLOT3D, curvilinear CFD):
    # Transform turns the wavelet's image data into a vtkStructuredGrid.
    curvilinear = Transform(Input=Wavelet(WholeExtent=[-2, 2, -2, 2, -2, 2]))
    structured = Show(curvilinear, view)
    if structured.GetXMLName() != "StructuredGridRepresentation":
        failures.append("Transform(Wavelet) shown as %s" % structured.GetXMLName())
    if pt.REPRESENTATION not in structured.GetProperty("Representation").Available:
        failures.append("'%s' is not offered for structured grids" % pt.REPRESENTATION)
    Hide(curvilinear, view)

    display = pt.show_volume(Tetrahedralize(Input=Wavelet(WholeExtent=[-4, 4, -4, 4, -4, 4])),
                             view, "RTData")
    Render(view)
    listed = set(display.ListProperties())
    mapper = pt.mapper_of(display)
    for name, default in sorted(declared.items()):
        if name not in listed:
            failures.append("%s is not in ListProperties()" % name)
            continue
        value, expected, getter = NEW_VALUES[name]
        if getter is None:
            display.SetPropertyWithName(name, value)
            kept = display.GetPropertyValue(name)
            if (list(kept) if hasattr(kept, "__len__") else kept) != value:
                failures.append("%s = %r not kept" % (name, value))
            continue
        mapper_default = getattr(mapper, getter)()
        if not same(default, mapper_default):
            failures.append("%s: XML default %s, mapper default %s" % (name, default, mapper_default))
        display.SetPropertyWithName(name, value)
        Render(view)
        got = getattr(mapper, getter)()
        if not same(got, expected):
            failures.append("%s = %r reached the mapper as %r" % (name, value, got))
    # Every blend mode entry: the mapper's blend mode (vtkVolumeMapper's values).
    for text, blend in (("Composite", 0), ("Maximum Intensity", 1), ("Minimum Intensity", 2),
                        ("Average Intensity", 3), ("Additive", 4), ("Isosurfaces", 5),
                        ("Composite With Isosurfaces", 0)):
        display.PPIRayBlendMode = text
        Render(view)
        if mapper.GetBlendMode() != blend:
            failures.append("PPIRayBlendMode %s reached the mapper as %d" % (text, mapper.GetBlendMode()))
    pt.finish(failures)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        pt.fail("usage: " + __doc__.strip().splitlines()[-1])
    main(*sys.argv[1:])
