#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""TimeCritical demo: build a Totally Ordered Mesh and show it at several resolutions.

Usage:
  /usr/bin/python3 scripts/tom_demo.py --output DIR [--mesh FILE] [options]

Without --mesh the demo generates its own surface: the isosurface of a
synthetic volume (blended Gaussian blobs along a trefoil knot plus a few
bubbles, roughened by smooth deterministic noise), about 300k triangles.
--mesh reads .obj, .ply (including triangle-strip PLY files such as igea.ply),
.stl, .vtp and legacy .vtk files.

It builds the TOM (timed), extracts 100/50/25/10/5 % of the triangles (each
timed), renders every resolution offscreen with the same camera through
vtkTOMPolyDataMapper, and writes to DIR:
  tom_<percent>.png        one 512x512 image per resolution
  tom_<percent>_edges.png  a close-up of the same with the triangle edges drawn
  montage.png              the five images side by side, close-ups below
  summary.json        the table printed at the end, and the build figures

Needs the `timecritical` Python package of a TimeCritical build on PYTHONPATH
(<build>/lib/python3/dist-packages) and ParaView's VTK (/usr/bin/python3 on
Debian). Rendering needs an X display: run under `xvfb-run -a` on a headless
machine, or pass --no-render.
"""

import argparse
import glob
import json
import os
import platform
import sys
import time

RESOLUTIONS = (1.0, 0.5, 0.25, 0.1, 0.05)
HERE = os.path.dirname(os.path.abspath(__file__))


def fail(message, code=2):
    sys.stderr.write("tom_demo: " + message.rstrip() + "\n")
    sys.exit(code)


# ---------------------------------------------------------------------------
# Imports, with messages that say what to do.
try:
    import numpy as np
except ImportError:
    fail("numpy is missing: run the demo with /usr/bin/python3 (Debian's python3-numpy).")

try:
    from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand, vtkVersion
except ImportError:
    fail("cannot import VTK's `vtkmodules` with %s.\nRun the demo with /usr/bin/python3, "
         "which imports ParaView's VTK (Debian package python3-paraview)." % sys.executable)


def import_timecritical():
    try:
        import timecritical
        return timecritical, None
    except ImportError as first_error:
        # A build tree next to the sources is a likely home; say which one is used.
        root = os.path.dirname(HERE)
        for candidate in sorted(glob.glob(os.path.join(root, "build*", "lib", "python3",
                                                       "dist-packages"))):
            if os.path.isfile(os.path.join(candidate, "timecritical", "__init__.py")):
                sys.path.insert(0, candidate)
                try:
                    import timecritical
                    return timecritical, candidate
                except ImportError:
                    sys.path.remove(candidate)
                    sys.modules.pop("timecritical", None)
        fail("cannot import the TimeCritical Python package (%s).\n"
             "Build TimeCritical (scripts/build.sh) and set PYTHONPATH to the build tree's\n"
             "Python folder, for example:\n"
             "  export PYTHONPATH=%s/build/lib/python3/dist-packages\n"
             "  /usr/bin/python3 %s --output demo-output"
             % (first_error, root, sys.argv[0]))


timecritical, found_in = import_timecritical()
vtkTOMBuilder = timecritical.vtkTOMBuilder
vtkExtractTOMResolution = timecritical.vtkExtractTOMResolution
vtkTOMPolyDataMapper = timecritical.vtkTOMPolyDataMapper

from vtkmodules.util.misc import calldata_type  # noqa: E402
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData  # noqa: E402
from ply_strips import read_ply_tristrips  # noqa: E402


# ---------------------------------------------------------------------------
class Messages:
    """Collects the errors and warnings of VTK objects instead of printing them."""

    def __init__(self, *objects):
        self.errors, self.warnings = [], []

        @calldata_type(VTK_STRING)
        def on_error(_obj, _event, text):
            self.errors.append(first_line(text))

        @calldata_type(VTK_STRING)
        def on_warning(_obj, _event, text):
            self.warnings.append(first_line(text))

        self._keep = (on_error, on_warning)
        for obj in objects:
            for target in (obj, obj.GetExecutive()) if hasattr(obj, "GetExecutive") else (obj,):
                target.AddObserver(vtkCommand.ErrorEvent, on_error)
                target.AddObserver(vtkCommand.WarningEvent, on_warning)


def first_line(text):
    """The message of a VTK error/warning without its 'ERROR: In file, line' header."""
    lines = [line.strip() for line in (text or "").splitlines() if line.strip()]
    lines = [line for line in lines if not line.startswith(("ERROR: In", "Warning: In"))]
    message = lines[0] if lines else ""
    # "vtkTOMBuilder (0x...): message" -> "message"
    if "): " in message:
        message = message.split("): ", 1)[1]
    return message


# ---------------------------------------------------------------------------
# The default mesh: an isosurface of a synthetic volume.
def bspline_upsampling(m, n):
    """n x m matrix of periodic cubic B-spline weights from m coarse to n fine samples."""
    u = np.arange(n) * (m / n)
    weights = np.zeros((n, m))
    base = np.floor(u).astype(int)
    for offset in (-1, 0, 1, 2):
        i = base + offset
        d = np.abs(u - i)
        w = np.where(d < 1.0, (4.0 - 6.0 * d ** 2 + 3.0 * d ** 3) / 6.0,
                     np.where(d < 2.0, (2.0 - d) ** 3 / 6.0, 0.0))
        np.add.at(weights, (np.arange(n), i % m), w)
    return weights


def smooth_noise(n, seed, coarse=64):
    """Deterministic smooth noise in [-1, 1] on an n^3 grid (band-limited, B-spline upsampled)."""
    rng = np.random.default_rng(seed)
    k2 = (np.fft.fftfreq(coarse)[:, None, None] ** 2 + np.fft.fftfreq(coarse)[None, :, None] ** 2
          + np.fft.fftfreq(coarse)[None, None, :] ** 2)
    # Two octaves: broad swellings and finer ripples.
    band = np.exp(-k2 / (2.0 * 0.035 ** 2)) + 0.12 * np.exp(-k2 / (2.0 * 0.14 ** 2))
    noise = np.fft.ifftn(np.fft.fftn(rng.standard_normal((coarse,) * 3)) * band).real
    w = bspline_upsampling(coarse, n).astype(np.float32)
    noise = noise.astype(np.float32)
    noise = np.tensordot(w, noise, axes=(1, 0))  # [n, m, m]
    noise = np.tensordot(noise, w, axes=(2, 1))  # [n, m, n]
    noise = np.einsum("bj,ajc->abc", w, noise, optimize=True)  # [n, n, n]
    noise /= np.abs(noise).max()
    return noise


def synthetic_volume(n):
    """Scalar field on an n^3 grid over [-1.6, 1.6]^3 and its iso value."""
    lo, hi = -1.6, 1.6
    h = (hi - lo) / (n - 1)
    field = np.zeros((n, n, n), dtype=np.float32)  # indexed [z, y, x]
    axis = np.linspace(lo, hi, n).astype(np.float32)

    def add_blob(center, sigma, weight):
        # Separable Gaussian, added only within 3 sigma of its centre.
        radius = 3.0 * sigma
        first = np.clip(np.floor((np.asarray(center) - radius - lo) / h).astype(int), 0, n)
        last = np.clip(np.ceil((np.asarray(center) + radius - lo) / h).astype(int) + 1, 0, n)
        gx, gy, gz = (np.exp(-((axis[first[c]:last[c]] - center[c]) / sigma) ** 2)
                      for c in range(3))
        field[first[2]:last[2], first[1]:last[1], first[0]:last[0]] += (
            weight * gz[:, None, None] * gy[None, :, None] * gx[None, None, :])

    # A trefoil knot of overlapping blobs, thick and thin along its length.
    samples = 240
    for i in range(samples):
        t = 2.0 * np.pi * i / samples
        p = 0.42 * np.array([np.sin(t) + 2.0 * np.sin(2.0 * t),
                             np.cos(t) - 2.0 * np.cos(2.0 * t),
                             -np.sin(3.0 * t)])
        sigma = 0.17 + 0.06 * np.sin(3.0 * t + 0.5)
        add_blob(p, sigma, 0.35)
    # Bubbles that melt into the knot.
    for center, sigma in (((0.0, 0.0, 0.0), 0.42), ((0.85, 0.55, 0.45), 0.22),
                          ((-0.9, 0.45, -0.4), 0.24), ((0.05, -1.0, 0.5), 0.2)):
        add_blob(center, sigma, 1.6)
    field += 0.5 * smooth_noise(n, seed=20240517)
    return field, lo, h, 1.0


def generate_mesh(n):
    from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D, vtkPolyDataConnectivityFilter

    field, origin, spacing, iso = synthetic_volume(n)
    image = vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetOrigin(origin, origin, origin)
    image.SetSpacing(spacing, spacing, spacing)
    scalars = numpy_to_vtk(field.ravel(), deep=True)
    scalars.SetName("Field")
    image.GetPointData().SetScalars(scalars)

    contour = vtkFlyingEdges3D()
    contour.SetInputData(image)
    contour.SetValue(0, iso)
    contour.ComputeNormalsOn()  # smooth normals from the field's gradient
    contour.ComputeGradientsOff()
    contour.ComputeScalarsOff()
    # Noise makes small floating islands: keep the main surface only.
    largest = vtkPolyDataConnectivityFilter()
    largest.SetInputConnection(contour.GetOutputPort())
    largest.SetExtractionModeToLargestRegion()
    largest.Update()
    mesh = vtkPolyData()
    mesh.DeepCopy(largest.GetOutput())
    return mesh, "synthetic isosurface (trefoil knot of Gaussian blobs + noise, %d^3 grid)" % n


# ---------------------------------------------------------------------------
# Reading a mesh file.
def read_mesh(path):
    from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
    from vtkmodules.vtkIOLegacy import vtkPolyDataReader
    from vtkmodules.vtkIOPLY import vtkPLYReader
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

    if not os.path.isfile(path):
        fail("no such mesh file: %s" % path)
    extension = os.path.splitext(path)[1].lower()
    readers = {".obj": vtkOBJReader, ".ply": vtkPLYReader, ".stl": vtkSTLReader,
               ".vtp": vtkXMLPolyDataReader, ".vtk": vtkPolyDataReader}
    if extension not in readers:
        fail("unsupported mesh format %r: use .obj, .ply, .stl, .vtp or .vtk" % extension)
    reader = readers[extension]()
    reader.SetFileName(path)
    messages = Messages(reader)
    reader.Update()
    if messages.errors:
        fail("cannot read %s: %s" % (path, messages.errors[0]))
    mesh = vtkPolyData()
    mesh.DeepCopy(reader.GetOutput())
    if extension == ".ply" and mesh.GetNumberOfPolys() == 0 and mesh.GetNumberOfPoints() > 0:
        try:
            mesh = read_ply_tristrips(path)  # vtkPLYReader ignores triangle strips
        except (ValueError, KeyError) as error:
            fail("%s: vtkPLYReader found no faces and the strip decoder failed: %s"
                 % (path, error))
    if mesh.GetNumberOfPolys() + mesh.GetNumberOfStrips() == 0:
        fail("%s holds no surface (no polygons or triangle strips)" % path)
    return mesh, os.path.basename(path)


def ensure_normals(mesh):
    """Point normals for smooth shading; they travel through the TOM."""
    if mesh.GetPointData().GetNormals() is not None:
        return mesh
    from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
    normals = vtkPolyDataNormals()
    normals.SetInputData(mesh)
    normals.SplittingOff()  # keeps the points as they are
    normals.ComputeCellNormalsOff()
    normals.Update()
    out = vtkPolyData()
    out.DeepCopy(normals.GetOutput())
    return out


# ---------------------------------------------------------------------------
# Rendering.
class Renderer:
    def __init__(self, tom, size):
        from vtkmodules.vtkRenderingCore import (vtkActor, vtkRenderer, vtkRenderWindow,
                                                 vtkTextActor, vtkLightKit)
        import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text)
        import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL overrides)

        self.mapper = vtkTOMPolyDataMapper()
        self.mapper.SetInputData(tom)
        self.messages = Messages(self.mapper)
        actor = vtkActor()
        actor.SetMapper(self.mapper)
        self.actor = actor
        prop = actor.GetProperty()
        prop.SetColor(0.86, 0.52, 0.30)
        prop.SetAmbient(0.08)
        prop.SetDiffuse(0.85)
        prop.SetSpecular(0.35)
        prop.SetSpecularPower(40.0)
        prop.SetSpecularColor(1.0, 0.95, 0.85)
        self.renderer = vtkRenderer()
        self.renderer.AddActor(actor)
        self.renderer.GradientBackgroundOn()
        self.renderer.SetBackground(0.06, 0.07, 0.10)
        self.renderer.SetBackground2(0.30, 0.34, 0.42)
        self.renderer.RemoveAllLights()
        kit = vtkLightKit()
        kit.AddLightsToRenderer(self.renderer)
        self.text = vtkTextActor()
        self.text.GetTextProperty().SetFontSize(max(12, size // 32))
        self.text.GetTextProperty().SetColor(0.95, 0.95, 0.95)
        self.text.SetPosition(10, 10)
        self.renderer.AddActor2D(self.text)
        self.window = vtkRenderWindow()
        self.window.SetOffScreenRendering(1)
        self.window.SetSize(size, size)
        self.window.SetMultiSamples(0)
        self.renderer.UseFXAAOn()  # cheap antialiasing, also on software OpenGL
        self.window.AddRenderer(self.renderer)
        # One camera for every resolution, framed on the full mesh.
        self.renderer.ResetCamera(tom.GetBounds())
        camera = self.renderer.GetActiveCamera()
        camera.Azimuth(28.0)
        camera.Elevation(22.0)
        camera.Zoom(1.25)
        self.renderer.ResetCameraClippingRange(tom.GetBounds())

    def render(self, resolution, label, frames=9):
        """Renders at a resolution; returns (first frame ms, median ms of the next frames)."""
        self.mapper.SetResolution(resolution)
        self.text.SetInput(label)
        start = time.perf_counter()
        self.window.Render()
        self.finish()
        first = 1000.0 * (time.perf_counter() - start)
        times = []
        for _ in range(frames):
            start = time.perf_counter()
            self.window.Render()
            self.finish()
            times.append(1000.0 * (time.perf_counter() - start))
        return first, float(np.median(times))

    def render_closeup(self, label, path, zoom=3.2):
        """Same resolution, closer and with the triangle edges drawn (for the montage)."""
        camera = self.renderer.GetActiveCamera()
        saved = (camera.GetPosition(), camera.GetFocalPoint(), camera.GetViewAngle())
        prop = self.actor.GetProperty()
        prop.EdgeVisibilityOn()
        prop.SetEdgeColor(0.18, 0.09, 0.04)
        camera.Zoom(zoom)
        self.text.SetInput(label)
        self.renderer.ResetCameraClippingRange()
        self.window.Render()
        image = self.save(path)
        prop.EdgeVisibilityOff()
        camera.SetPosition(saved[0])
        camera.SetFocalPoint(saved[1])
        camera.SetViewAngle(saved[2])
        self.renderer.ResetCameraClippingRange()
        return image

    def finish(self):
        # Rendering is asynchronous: wait for the frame (glFinish).
        self.window.WaitForCompletion()

    def save(self, path):
        from vtkmodules.vtkIOImage import vtkPNGWriter
        from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

        grab = vtkWindowToImageFilter()
        grab.SetInput(self.window)
        grab.ShouldRerenderOff()  # the frame as rendered
        grab.ReadFrontBufferOff()
        grab.Update()
        image = vtkImageData()
        image.DeepCopy(grab.GetOutput())
        writer = vtkPNGWriter()
        writer.SetFileName(path)
        writer.SetInputData(image)
        writer.Write()
        return image

    def gl_info(self):
        try:
            info = self.window.ReportCapabilities()
            renderer = [l for l in info.splitlines() if "OpenGL renderer" in l]
            return renderer[0].split(":", 1)[1].strip() if renderer else ""
        except Exception:  # noqa: BLE001 - informational only
            return ""


def write_montage(images, closeups, path):
    """Shaded images in the top row, close-ups with edges below."""
    from vtkmodules.vtkFiltersCore import vtkImageAppend
    from vtkmodules.vtkIOImage import vtkPNGWriter

    rows = vtkImageAppend()
    rows.SetAppendAxis(1)  # image y grows upwards: the bottom row goes first
    for row_images in (closeups, images):
        if not row_images:
            continue
        row = vtkImageAppend()
        row.SetAppendAxis(0)
        for image in row_images:
            row.AddInputData(image)
        rows.AddInputConnection(row.GetOutputPort())
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(rows.GetOutputPort())
    writer.Write()


# ---------------------------------------------------------------------------
def main(argv=None):
    parser = argparse.ArgumentParser(
        description="Build a Totally Ordered Mesh, extract and render it at several resolutions.")
    parser.add_argument("--output", required=True, help="folder for the images and summary.json")
    parser.add_argument("--mesh", help="surface to use (.obj, .ply, .stl, .vtp, .vtk); "
                                       "default: a generated isosurface")
    parser.add_argument("--grid", type=int, default=280,
                        help="grid size of the generated volume (default 200: ~300k triangles)")
    parser.add_argument("--size", type=int, default=512, help="image size in pixels (default 512)")
    parser.add_argument("--no-render", action="store_true", help="skip the images")
    args = parser.parse_args(argv)
    if args.grid < 16:
        parser.error("--grid must be at least 16")
    if args.size < 32:
        parser.error("--size must be at least 32")
    render = not args.no_render
    if render and sys.platform.startswith("linux") and not os.environ.get("DISPLAY"):
        fail("rendering needs an X display and DISPLAY is not set.\n"
             "Run under a virtual one:  xvfb-run -a /usr/bin/python3 %s --output %s ...\n"
             "or pass --no-render for the table only." % (sys.argv[0], args.output))
    os.makedirs(args.output, exist_ok=True)
    if found_in:
        print("note: PYTHONPATH lacks TimeCritical; using the build found at %s" % found_in)

    # Input.
    start = time.perf_counter()
    if args.mesh:
        mesh, name = read_mesh(args.mesh)
    else:
        mesh, name = generate_mesh(args.grid)
    mesh = ensure_normals(mesh)
    input_seconds = time.perf_counter() - start
    print("input: %s: %d points, %d cells (%.2f s to %s)"
          % (name, mesh.GetNumberOfPoints(), mesh.GetNumberOfCells(), input_seconds,
             "read" if args.mesh else "generate"))

    # Build.
    builder = vtkTOMBuilder()
    builder.SetInputData(mesh)
    messages = Messages(builder)
    start = time.perf_counter()
    builder.Update()
    build_seconds = time.perf_counter() - start
    for warning in messages.warnings:
        print("warning: " + warning)
    if messages.errors:
        fail("building the TOM failed: " + messages.errors[0], code=1)
    tom = builder.GetOutput()
    counts = vtk_to_numpy(tom.GetFieldData().GetArray("TOMCounts")).tolist()
    diagonal = tom.GetLength()
    print("TOM: %d vertices, %d triangles, base mesh %d vertices / %d triangles; "
          "built in %.3f s (%.0f k triangles/s; filter's own time %.3f s)"
          % (counts[0], counts[1], counts[2], counts[3], build_seconds,
             counts[1] / max(build_seconds, 1e-9) / 1000.0, builder.GetBuildTime()))

    # Extract and render.
    view = Renderer(tom, args.size) if render else None
    rows, images, closeups, problems = [], [], [], []
    extractor = vtkExtractTOMResolution()
    extractor.SetInputData(tom)
    extract_messages = Messages(extractor)
    for resolution in RESOLUTIONS:
        extractor.SetResolution(resolution)
        start = time.perf_counter()
        extractor.Update()
        extract_ms = 1000.0 * (time.perf_counter() - start)
        if extract_messages.errors:
            fail("extraction at %g failed: %s" % (resolution, extract_messages.errors[0]), code=1)
        out = extractor.GetOutput()
        row = {
            "resolution": resolution,
            "triangles": out.GetNumberOfPolys(),
            "vertices": out.GetNumberOfPoints(),
            "error": extractor.GetExtractedError(),
            "error_percent_of_diagonal": 100.0 * extractor.GetExtractedError() / diagonal,
            "extract_ms": extract_ms,
            "extract_filter_ms": 1000.0 * extractor.GetExtractionTime(),
        }
        if view:
            percent = int(round(100 * resolution))
            label = "%d%%  %s triangles" % (percent, format(row["triangles"], ","))
            first_ms, render_ms = view.render(resolution, label)
            image_path = os.path.join(args.output, "tom_%03d.png" % percent)
            images.append(view.save(image_path))
            closeups.append(view.render_closeup(
                "%d%%  close-up with edges" % percent,
                os.path.join(args.output, "tom_%03d_edges.png" % percent)))
            row.update({
                "render_ms": render_ms,
                "first_frame_ms": first_ms,
                "rendered_triangles": view.mapper.GetRenderedTriangles(),
                "rendered_vertices": view.mapper.GetRenderedVertices(),
                "image": os.path.basename(image_path),
            })
            if (row["rendered_triangles"], row["rendered_vertices"]) != (row["triangles"],
                                                                         row["vertices"]):
                problems.append("at %g the mapper drew %d triangles / %d vertices, the "
                                "extraction has %d / %d" % (
                                    resolution, row["rendered_triangles"],
                                    row["rendered_vertices"], row["triangles"], row["vertices"]))
        rows.append(row)
    if view:
        problems += ["mapper: " + text for text in view.messages.errors + view.messages.warnings]
    previous = None
    for row in rows:  # coarser resolutions never have more triangles or vertices
        if previous and (row["triangles"] > previous["triangles"]
                         or row["vertices"] > previous["vertices"]):
            problems.append("resolution %g has more triangles or vertices than %g"
                            % (row["resolution"], previous["resolution"]))
        previous = row

    montage = None
    if images:
        montage = os.path.join(args.output, "montage.png")
        write_montage(images, closeups, montage)

    # Report.
    header = ("resolution", "triangles", "vertices", "error", "error %diag", "extract ms",
              "render ms")
    print()
    print("%10s %10s %10s %12s %11s %11s %10s" % header)
    for row in rows:
        print("%9d%% %10d %10d %12.5g %10.3f%% %11.2f %10s"
              % (round(100 * row["resolution"]), row["triangles"], row["vertices"],
                 row["error"], row["error_percent_of_diagonal"], row["extract_ms"],
                 "%.2f" % row["render_ms"] if "render_ms" in row else "-"))
    summary = {
        "mesh": name,
        "mesh_file": os.path.abspath(args.mesh) if args.mesh else None,
        "input_points": mesh.GetNumberOfPoints(),
        "input_cells": mesh.GetNumberOfCells(),
        "bounding_box_diagonal": diagonal,
        "tom": {"vertices": counts[0], "triangles": counts[1], "base_vertices": counts[2],
                "base_triangles": counts[3], "error_curve_samples":
                    tom.GetFieldData().GetArray("TOMErrorCurve").GetNumberOfTuples()},
        "build_seconds": build_seconds,
        "build_filter_seconds": builder.GetBuildTime(),
        "build_triangles_per_second": counts[1] / max(build_seconds, 1e-9),
        "dropped_cells": builder.GetNumberOfDroppedCells(),
        "merged_points": builder.GetNumberOfMergedPoints(),
        "resolutions": rows,
        "image_size": args.size if render else None,
        "montage": os.path.basename(montage) if montage else None,
        "render_ms_note": "median of 9 frames after the first (first_frame_ms, which "
                          "uploads the index buffer); wall clock including glFinish",
        "opengl_renderer": view.gl_info() if view else None,
        "vtk_version": vtkVersion.GetVTKVersion(),
        "python": sys.executable,
        "machine": platform.machine(),
        "timecritical_package": os.path.dirname(timecritical.__file__),
        "problems": problems,
    }
    summary_path = os.path.join(args.output, "summary.json")
    with open(summary_path, "w") as stream:
        json.dump(summary, stream, indent=2)
        stream.write("\n")
    print()
    print("wrote %s%s" % (summary_path, "" if not images else
                          ", %d images and %s" % (2 * len(images), os.path.basename(montage))))
    for problem in problems:
        sys.stderr.write("tom_demo: problem: %s\n" % problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
