// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSMExtractViewDependentMeshProxy
 * @brief   the proxy of Extract View-Dependent Mesh: reads its former mode numbering from state
 *
 * Extract View-Dependent Mesh used to number its refinement modes
 * 0 = Fixed Accuracy, 1 = Triangle Budget in its XML property RefinementMode;
 * it now has the plugin's common numbering (0 = budget, 1 = fixed accuracy)
 * in the property Mode. A state file written before holds RefinementMode
 * only: this proxy translates it into Mode while loading, so that the client
 * (the panel, Python, the next saved state) and the server agree on the mode
 * the file was saved with.
 *
 * @sa vtkExtractViewDependentMesh
 */
#ifndef vtkSMExtractViewDependentMeshProxy_h
#define vtkSMExtractViewDependentMeshProxy_h

#include "TimeCriticalViewsModule.h" // for export macro
#include "vtkSMSourceProxy.h"

class vtkPVXMLElement;

class TIMECRITICALVIEWS_EXPORT vtkSMExtractViewDependentMeshProxy : public vtkSMSourceProxy
{
public:
  static vtkSMExtractViewDependentMeshProxy* New();
  vtkTypeMacro(vtkSMExtractViewDependentMeshProxy, vtkSMSourceProxy);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Loads `element`, with a former RefinementMode turned into Mode first.
  int LoadXMLState(vtkPVXMLElement* element, vtkSMProxyLocator* locator) override;

  /**
   * Rewrites the proxy state `element` in place: a Property "RefinementMode"
   * (the former numbering) becomes "Mode" with the common numbering, unless
   * the state already has Mode. Returns whether it rewrote anything.
   */
  static bool TranslateLegacyRefinementMode(vtkPVXMLElement* element);

protected:
  vtkSMExtractViewDependentMeshProxy();
  ~vtkSMExtractViewDependentMeshProxy() override;

private:
  vtkSMExtractViewDependentMeshProxy(const vtkSMExtractViewDependentMeshProxy&) = delete;
  void operator=(const vtkSMExtractViewDependentMeshProxy&) = delete;
};

#endif
