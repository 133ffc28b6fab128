#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""The plugin's filters in parallel pvbatch with empty pieces.

Run as `mpirun -np 2 pvbatch --force-offscreen-rendering TestParallelPieces.py`.
A single-piece .vtp file puts all data on rank 0, so rank 1 runs every filter
on an empty piece, which is normal in parallel VTK and ParaView: it must give
an empty output without a message (ctest fails the test on any "ERROR" or
"Warning" line, from either rank) while rank 0 builds the real thing.

Environment: as the other Python tests (TIMECRITICAL_PLUGIN, TIMECRITICAL_TEST_OUTPUT_DIR).
"""

import os
import sys
import unittest

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

from timecritical_testing import ProxyTests, load_plugin, output_dir

load_plugin(globals(), ["BuildTotallyOrderedMesh", "ExtractTOMResolution", "BuildMergeTree",
                        "ExtractViewDependentMesh"])


def write_single_piece_sphere():
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(40)
    sphere.SetPhiResolution(40)
    sphere.Update()
    path = os.path.join(output_dir("TestParallelPieces"), "sphere.vtp")
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(sphere.GetOutput())
    writer.SetDataModeToBinary()  # not appended: see the README on libexpat
    writer.SetFileName(path)
    if not writer.Write():
        raise RuntimeError("could not write " + path)
    return path, sphere.GetOutput().GetNumberOfPolys()


class EmptyPieces(ProxyTests, unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.path, cls.triangles = write_single_piece_sphere()

    def setUp(self):
        self.created = []
        self.reader = self.new(XMLPolyDataReader(FileName=[self.path]))

    def test_two_ranks_and_all_data_on_rank_0(self):
        # Otherwise this test would not test empty pieces at all.
        ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
        self.assertEqual(ranks, 2, "run me with mpirun -np 2 pvbatch")
        ids = self.fetch(self.new(ProcessIdScalars(Input=self.reader)))
        owners = vtk_to_numpy(ids.GetPointData().GetArray("ProcessId"))
        self.assertEqual(len(owners), ids.GetNumberOfPoints())
        self.assertEqual(set(owners.tolist()), {0})

    def test_tom_and_extraction(self):
        tom = self.new(BuildTotallyOrderedMesh(Input=self.reader))
        self.assertEqual(self.fetch(tom).GetNumberOfPolys(), self.triangles)
        half = self.new(ExtractTOMResolution(Input=tom, Resolution=0.5))
        extracted = self.fetch(half).GetNumberOfPolys()
        self.assertGreater(extracted, 0)
        self.assertLessEqual(extracted, self.triangles // 2 + 2)

    def test_merge_tree_and_front(self):
        tree = self.new(BuildMergeTree(Input=self.reader))
        self.assertEqual(self.fetch(tree).GetNumberOfPolys(), self.triangles)
        front = self.new(ExtractViewDependentMesh(Input=tree, CameraPosition=[0, 0, 3],
                                                  CameraFocalPoint=[0, 0, 0],
                                                  CameraViewUp=[0, 1, 0]))
        drawn = self.fetch(front).GetNumberOfPolys()
        self.assertGreater(drawn, 0)
        self.assertLessEqual(drawn, self.triangles)


if __name__ == "__main__":
    # No sys.exit(): pvbatch must finalize MPI on rank 0, or mpirun kills rank 1
    # and reports an improper exit. A failure raises, which pvbatch turns into
    # a non-zero exit code.
    result = unittest.main(argv=[sys.argv[0]], exit=False).result
    if not result.wasSuccessful():
        raise RuntimeError("TestParallelPieces failed")
