// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkExtractViewDependentMesh
 * @brief   extracts the view-dependent front of a merge tree as a surface
 *
 * Takes the output of vtkMergeTreeBuilder (a TOM with its merge tree, see
 * vtkMergeTreeFieldData) and a camera, refines the merge tree for that view
 * (Xia, El-Sana & Varshney, section 5; timecritical::ViewDependentRefinement)
 * and produces the front as an ordinary vtkPolyData: the display vertices with
 * their point data and the display triangles with the cell data of the
 * triangles they come from. The TOM and merge-tree arrays are left out.
 *
 * The camera and the data share one coordinate system (world coordinates:
 * the camera's model transform is ignored). A split is made while the
 * node's error projects to more than PixelThreshold pixels in a viewport of
 * ViewportSize pixels; the threshold shrinks by SilhouetteFactor near
 * silhouettes and by HighlightFactor near specular highlights of the light at
 * LightDirection, and back-facing regions stay coarse. Regions outside the
 * four side planes of the view frustum stay coarse (the camera's clipping
 * range is not used). With SetRefinementModeToBudget() the front is refined
 * where the projected error is largest until TriangleBudget triangles, never
 * below PixelThreshold (a floor: set it to 0 to spend the whole budget).
 *
 * The settings follow timecritical::RefinementSettings (RefinementSettings.h),
 * as in vtkMultiresolutionPolyDataMapper and vtkTimeCriticalRenderer: the modes
 * are numbered BUDGET = 0, FIXED_ACCURACY = 1; a number out of range (NaN
 * included) is an error and leaves the setting as it was; a mode out of range
 * is clamped.
 *
 * Every front is a fold-free triangulation of the input's topology: a closed
 * manifold input gives a closed manifold output with the same Euler
 * characteristic. The refinement state is kept between executions, so that
 * moving the camera (whose modification time is part of this filter's) updates
 * the front incrementally.
 *
 * A proxy cannot hold a vtkCamera: SetCameraPosition(), SetCameraFocalPoint(),
 * SetCameraViewUp(), SetCameraViewAngle(), SetCameraParallelProjection() and
 * SetCameraParallelScale() set the same values on the camera in use (the one
 * given to SetCamera(), or the filter's own one).
 *
 * @sa vtkMergeTreeBuilder vtkMergeTreeFieldData vtkExtractTOMResolution
 */
#ifndef vtkExtractViewDependentMesh_h
#define vtkExtractViewDependentMesh_h

#include "TimeCriticalFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h" // for vtkSmartPointer

#include <memory> // for std::unique_ptr

class vtkCamera;
class vtkIdList;
class vtkPolyData;

class TIMECRITICALFILTERS_EXPORT vtkExtractViewDependentMesh : public vtkPolyDataAlgorithm
{
public:
  static vtkExtractViewDependentMesh* New();
  vtkTypeMacro(vtkExtractViewDependentMesh, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The camera the front is refined for, in the data's coordinates. By
   * default the filter has its own camera (VTK's default view); nullptr gives
   * it back its own camera.
   */
  void SetCamera(vtkCamera* camera);
  vtkCamera* GetCamera();
  ///@}

  ///@{
  /// Camera settings for proxies and scripts: forwarded to GetCamera().
  void SetCameraPosition(double x, double y, double z);
  void SetCameraFocalPoint(double x, double y, double z);
  void SetCameraViewUp(double x, double y, double z);
  void SetCameraViewAngle(double degrees);
  void SetCameraParallelProjection(bool parallel);
  void SetCameraParallelScale(double scale);
  ///@}

  ///@{
  /// Size of the viewport in pixels (width, height), both at least 1. Default 512 x 512.
  void SetViewportSize(int width, int height);
  vtkGetVector2Macro(ViewportSize, int);
  ///@}

  ///@{
  /// Screen-space error threshold tau in pixels, finite and >= 0 (0: full detail in view).
  /// Default 1.
  void SetPixelThreshold(double tau);
  vtkGetMacro(PixelThreshold, double);
  ///@}

  ///@{
  /// Direction towards the light in world coordinates (need not be unit). Default (0, 0, 1).
  void SetLightDirection(double x, double y, double z);
  void SetLightDirection(const double direction[3])
  {
    this->SetLightDirection(direction[0], direction[1], direction[2]);
  }
  vtkGetVector3Macro(LightDirection, double);
  ///@}

  ///@{
  /// Keep regions facing away from the camera coarse. Default on.
  vtkSetMacro(BackFaceSimplification, bool);
  vtkGetMacro(BackFaceSimplification, bool);
  vtkBooleanMacro(BackFaceSimplification, bool);
  ///@}

  ///@{
  /// Keep regions outside the view frustum's side planes coarse. Default on.
  vtkSetMacro(FrustumCulling, bool);
  vtkGetMacro(FrustumCulling, bool);
  vtkBooleanMacro(FrustumCulling, bool);
  ///@}

  ///@{
  /// Near silhouettes, multiply the threshold by SilhouetteFactor, in (0, 1]. Default on, 0.25
  /// (as vtkMultiresolutionPolyDataMapper and vtkTimeCriticalRenderer).
  vtkSetMacro(SilhouetteRefinement, bool);
  vtkGetMacro(SilhouetteRefinement, bool);
  vtkBooleanMacro(SilhouetteRefinement, bool);
  void SetSilhouetteFactor(double factor);
  vtkGetMacro(SilhouetteFactor, double);
  ///@}

  ///@{
  /// Near highlights, multiply the threshold by HighlightFactor, in (0, 1]. Default on, 0.5
  /// (as vtkMultiresolutionPolyDataMapper and vtkTimeCriticalRenderer).
  vtkSetMacro(HighlightRefinement, bool);
  vtkGetMacro(HighlightRefinement, bool);
  vtkBooleanMacro(HighlightRefinement, bool);
  void SetHighlightFactor(double factor);
  vtkGetMacro(HighlightFactor, double);
  ///@}

  /// The numbering of timecritical::RefinementMode, as in the mapper and the renderer.
  enum RefinementModes
  {
    BUDGET = 0,         ///< refine where the error is largest until TriangleBudget triangles
    FIXED_ACCURACY = 1, ///< split while the projected error exceeds PixelThreshold
    TRIANGLE_BUDGET = BUDGET ///< the budget mode's former name, kept for old scripts
  };

  ///@{
  /// How the front is chosen, clamped to [BUDGET, FIXED_ACCURACY]. Default FIXED_ACCURACY.
  vtkSetClampMacro(RefinementMode, int, BUDGET, FIXED_ACCURACY);
  vtkGetMacro(RefinementMode, int);
  void SetRefinementModeToBudget() { this->SetRefinementMode(BUDGET); }
  void SetRefinementModeToFixedAccuracy() { this->SetRefinementMode(FIXED_ACCURACY); }
  /// The budget mode's former name, kept for old scripts.
  void SetRefinementModeToTriangleBudget() { this->SetRefinementMode(BUDGET); }
  ///@}

  /**
   * The mode in the numbering this filter had before it took the common one
   * (0 = fixed accuracy, 1 = triangle budget): what ParaView state files and
   * scripts written then hold in the filter's RefinementMode property. Sets
   * RefinementMode to the same mode in the common numbering; other values are
   * an error and ignored.
   */
  void SetLegacyRefinementMode(int legacyMode);

  ///@{
  /// Triangles of the front in BUDGET mode (at least the coarsest mesh), in
  /// [0, 2147483647]. Default 10000.
  void SetTriangleBudget(vtkIdType budget);
  vtkGetMacro(TriangleBudget, vtkIdType);
  ///@}

  ///@{
  /**
   * Add the cell array LocalLevelArrayName() (unsigned short): per triangle,
   * how coarse the front is there, 0 where it is at full resolution, up to
   * the tree's level count where it is at its coarsest. Default off.
   */
  vtkSetMacro(GenerateLocalLevels, bool);
  vtkGetMacro(GenerateLocalLevels, bool);
  vtkBooleanMacro(GenerateLocalLevels, bool);
  static const char* LocalLevelArrayName() { return "LocalLevel"; }
  ///@}

  ///@{
  /// Statistics of the last execution.
  vtkGetMacro(NumberOfDisplayVertices, vtkIdType);
  vtkGetMacro(NumberOfDisplayTriangles, vtkIdType);
  vtkGetMacro(NumberOfSplits, vtkIdType);
  vtkGetMacro(NumberOfMerges, vtkIdType);
  vtkGetMacro(NumberOfForcedSplits, vtkIdType);
  vtkGetMacro(RefinementTime, double);
  ///@}

  /// Includes the camera's modification time, so that moving it re-executes.
  vtkMTimeType GetMTime() override;

protected:
  vtkExtractViewDependentMesh();
  ~vtkExtractViewDependentMesh() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkSmartPointer<vtkCamera> Camera;
  int ViewportSize[2] = { 512, 512 };
  double PixelThreshold = 1.0;
  double LightDirection[3] = { 0.0, 0.0, 1.0 };
  bool BackFaceSimplification = true;
  bool FrustumCulling = true;
  bool SilhouetteRefinement = true;
  double SilhouetteFactor = 0.25;
  bool HighlightRefinement = true;
  double HighlightFactor = 0.5;
  int RefinementMode = FIXED_ACCURACY;
  vtkIdType TriangleBudget = 10000;
  bool GenerateLocalLevels = false;

  vtkIdType NumberOfDisplayVertices = 0;
  vtkIdType NumberOfDisplayTriangles = 0;
  vtkIdType NumberOfSplits = 0;
  vtkIdType NumberOfMerges = 0;
  vtkIdType NumberOfForcedSplits = 0;
  double RefinementTime = 0.0;

private:
  vtkExtractViewDependentMesh(const vtkExtractViewDependentMesh&) = delete;
  void operator=(const vtkExtractViewDependentMesh&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;

  // The steps of RequestData().
  void ResetStatistics();
  /// 1: ready to refine, 0: error (reported), -1: nothing to refine (empty output).
  int PrepareRefinement(vtkPolyData* input);
  bool InitializeRefinement(vtkPolyData* input);
  void UpdateFront();
  vtkIdType CopyDisplayVertices(vtkPolyData* input, vtkPolyData* output, vtkIdList* pointIds);
  bool CopyDisplayTriangles(vtkPolyData* input, vtkPolyData* output);
  void AddLocalLevels(vtkPolyData* output, vtkIdList* pointIds);
  static void PassFieldData(vtkPolyData* input, vtkPolyData* output);
};

#endif
