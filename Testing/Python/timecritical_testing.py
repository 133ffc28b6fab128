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
