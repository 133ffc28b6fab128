"""Helpers shared by the Python tests (imported from the tests' own folder,
which python3, pvpython and pvbatch put first on sys.path)."""

import os
import sys
import tempfile

PLUGIN = os.environ.get("TIMECRITICAL_PLUGIN", "")
SHARED_DATA_DIR = os.environ.get(
    "TIMECRITICAL_SHARED_DATA_DIR",
    os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "shared", "data"))
COW = os.path.join(SHARED_DATA_DIR, "cow.obj")


def load_plugin(namespace, names):
    """Loads TIMECRITICAL_PLUGIN with paraview.simple.LoadPlugin into namespace
    (the caller's globals()) and exits with a message unless it defines names."""
    from paraview.simple import LoadPlugin
    if not PLUGIN or not os.path.isfile(PLUGIN):
        sys.stderr.write("TIMECRITICAL_PLUGIN must name the built TimeCritical.so "
                         "(<build>/lib/paraview-plugins/TimeCritical/TimeCritical.so); got %r\n"
                         % PLUGIN)
        sys.exit(1)
    LoadPlugin(PLUGIN, remote=False, ns=namespace)
    for name in names:
        if name not in namespace:
            sys.stderr.write("LoadPlugin(%s) did not define %s\n" % (PLUGIN, name))
            sys.exit(1)


def read_png(path):
    """The RGB pixels of a PNG file as a numpy array, rows from the top (VTK's
    images start at the bottom)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height = image.GetDimensions()[:2]
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, -1)
    return pixels[::-1, :, :3]


def noisy_cube(n=8, noise=0.6 / 8):
    """A closed cube [-0.5, 0.5]^3 as a vtkPolyData, each face split into n x n
    quads (two triangles each) that share the points of the cube's edges, so
    that its 12 edges are 90-degree creases of one closed surface; every
    face-interior point moves off its face by a fixed pseudo-random amount in
    [-noise/2, noise/2], so that the collapse order depends on how the creases
    are held (the C++ tests' NoisyCube, TestvtkCollapseHierarchyBuilder.cxx)."""
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    ids = {}
    coordinates = []

    def point(ijk):
        if ijk not in ids:
            ids[ijk] = len(coordinates)
            coordinates.append([c / n - 0.5 for c in ijk])
        return ids[ijk]

    polys = vtkCellArray()
    for a in range(3):
        u, v = (a + 1) % 3, (a + 2) % 3
        for side in (0, n):
            for i in range(n):
                for j in range(n):
                    def corner(di, dj):
                        ijk = [0, 0, 0]
                        ijk[a], ijk[u], ijk[v] = side, i + di, j + dj
                        return point(tuple(ijk))
                    # Counter-clockwise in (u, v): normal +a, outward on the far side.
                    q = [corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)]
                    if side == 0:
                        q[1], q[3] = q[3], q[1]
                    polys.InsertNextCell(3, (q[0], q[1], q[2]))
                    polys.InsertNextCell(3, (q[0], q[2], q[3]))
    points = vtkPoints()
    points.SetDataTypeToDouble()
    state = 12345
    for p in coordinates:
        on = [k for k in range(3) if abs(p[k]) == 0.5]
        state = (state * 1664525 + 1013904223) % 2 ** 32
        if len(on) == 1:
            k = on[0]
            p[k] += (1.0 if p[k] > 0 else -1.0) * noise * ((state >> 8) / float(1 << 24) - 0.5)
        points.InsertNextPoint(*p)
    cube = vtkPolyData()
    cube.SetPoints(points)
    cube.SetPolys(polys)
    return cube


def output_dir(prefix):
    """A new scratch folder, inside TIMECRITICAL_TEST_OUTPUT_DIR when set."""
    folder = os.environ.get("TIMECRITICAL_TEST_OUTPUT_DIR")
    if folder:
        os.makedirs(folder, exist_ok=True)
        return tempfile.mkdtemp(prefix=prefix + "-", dir=folder)
    return tempfile.mkdtemp(prefix=prefix + "-")


class ProxyTests:
    """Mixin for unittest.TestCase classes that create paraview.simple proxies:
    new() registers a proxy for deletion after the test (newest first), fetch()
    updates one and brings its data to the client. setUp() must set
    self.created = [] before calling new()."""

    def tearDown(self):
        from paraview.simple import Delete
        for proxy in self.created:
            Delete(proxy)

    def new(self, proxy):
        self.created.insert(0, proxy)
        return proxy

    def fetch(self, proxy):
        from paraview import servermanager
        proxy.UpdatePipeline()
        data = servermanager.Fetch(proxy)
        self.assertIsNotNone(data)
        return data


# The Time-Critical Render View's tests (Testing/Python and Testing/Plugin/Views).

VIEW_SIZE = [480, 360]


def sphere(resolution=200, center=(0, 0, 0)):
    """A paraview.simple Sphere source of resolution x resolution."""
    from paraview.simple import Sphere
    return Sphere(ThetaResolution=resolution, PhiResolution=resolution, Center=list(center))


def screenshot(view, folder, name):
    """Saves a VIEW_SIZE screenshot of view as folder/name and returns its pixels."""
    from paraview.simple import SaveScreenshot
    path = os.path.join(folder, name)
    SaveScreenshot(path, view, ImageResolution=VIEW_SIZE)
    return read_png(path)


def leaf_mapper(view):
    """The multiresolution mapper of the first object the view's renderer drew."""
    renderer = view.GetClientSideObject().GetRenderer()
    return renderer.GetObjectActor(0).GetMapper()


class ViewTests(ProxyTests):
    """ProxyTests with view(): a new Time-Critical Render View of VIEW_SIZE
    without orientation axes, with the given properties set."""

    def view(self, **properties):
        return self.new_view("TimeCriticalRenderView", **properties)

    def new_view(self, xml_name, **properties):
        from paraview.simple import CreateView
        view = self.new(CreateView(xml_name))
        view.ViewSize = VIEW_SIZE
        view.OrientationAxesVisibility = 0
        for key, value in properties.items():
            setattr(view, key, value)
        return view
