// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkExtractTOMResolution
 * @brief   extracts one resolution of a Totally Ordered Mesh
 *
 * Input: a TOM made by vtkTOMBuilder (validated with vtkTOMFieldData; other
 * input is an error; an empty input, without points and cells, gives an
 * empty output quietly, as does a TOM of no points). Output: an ordinary vtkPolyData with the active points
 * (a prefix of the input points, with their point data) and the triangles of
 * the chosen resolution (with their cell data). The resolution is chosen by a
 * fraction of the triangles (SetResolution), a triangle count
 * (SetTargetTriangles) or a maximum geometric error (SetMaximumError); the
 * last call selects the mode.
 *
 * @sa vtkTOMBuilder vtkTOMFieldData
 */
#ifndef vtkExtractTOMResolution_h
#define vtkExtractTOMResolution_h

#include "TimeCriticalFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"


class TIMECRITICALFILTERS_EXPORT vtkExtractTOMResolution : public vtkPolyDataAlgorithm
{
public:
  static vtkExtractTOMResolution* New();
  vtkTypeMacro(vtkExtractTOMResolution, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum SelectionModes
  {
    BY_RESOLUTION = 0,
    BY_TRIANGLE_COUNT = 1,
    BY_MAXIMUM_ERROR = 2
  };

  ///@{
  /// How the resolution is chosen; the setters below also select their mode.
  vtkSetClampMacro(SelectionMode, int, BY_RESOLUTION, BY_MAXIMUM_ERROR);
  vtkGetMacro(SelectionMode, int);
  ///@}

  ///@{
  /// Fraction of the full triangle count, in [0,1]. Default 1.
  void SetResolution(double r);
  vtkGetMacro(Resolution, double);
  ///@}

  ///@{
  /// At most this many triangles (the coarsest mesh if it has more).
  void SetTargetTriangles(vtkIdType n);
  vtkGetMacro(TargetTriangles, vtkIdType);
  ///@}

  ///@{
  /// Coarsest mesh whose estimated geometric error (world units) is at most this.
  void SetMaximumError(double e);
  vtkGetMacro(MaximumError, double);
  ///@}

  ///@{
  /**
   * Geomorph of the last active vertex: 1 (default) keeps it where it is,
   * 0 moves it onto its substitution target, in between interpolates points
   * and point data, for smooth transitions between resolutions.
   */
  vtkSetClampMacro(GeomorphFactor, double, 0.0, 1.0);
  vtkGetMacro(GeomorphFactor, double);
  ///@}

  ///@{
  /// Result of the last update.
  vtkGetMacro(ExtractedVertexCount, vtkIdType);
  vtkGetMacro(ExtractedTriangleCount, vtkIdType);
  vtkGetMacro(ExtractedError, double);
  vtkGetMacro(ExtractionTime, double);
  ///@}

protected:
  vtkExtractTOMResolution();
  ~vtkExtractTOMResolution() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int SelectionMode = BY_RESOLUTION;
  double Resolution = 1.0;
  vtkIdType TargetTriangles = 0;
  double MaximumError = 0.0;
  double GeomorphFactor = 1.0;
  vtkIdType ExtractedVertexCount = 0;
  vtkIdType ExtractedTriangleCount = 0;
  double ExtractedError = 0.0;
  double ExtractionTime = 0.0;

private:
  vtkExtractTOMResolution(const vtkExtractTOMResolution&) = delete;
  void operator=(const vtkExtractTOMResolution&) = delete;
};

#endif
