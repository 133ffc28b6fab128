// SPDX-License-Identifier: BSD-3-Clause
// vtkTimeCriticalRenderer: waiting for the background hierarchy builds of
// the multiresolution mappers of its actors.
#include "vtkTimeCriticalRenderer.h"

#include "vtkActor.h"
#include "vtkMultiresolutionPolyDataMapper.h"
#include "vtkPropCollection.h"

namespace
{
/// Calls `f` with the multiresolution mapper of every actor among `props`.
template <typename F>
void ForEachMultiresolutionMapper(vtkPropCollection* props, F f)
{
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    vtkActor* actor = vtkActor::SafeDownCast(prop);
    if (auto* mapper =
          actor ? vtkMultiresolutionPolyDataMapper::SafeDownCast(actor->GetMapper()) : nullptr)
    {
      f(mapper);
    }
  }
}
}

void vtkTimeCriticalRenderer::WaitForHierarchies()
{
  ForEachMultiresolutionMapper(
    this->GetViewProps(), [](vtkMultiresolutionPolyDataMapper* m) { m->WaitForHierarchies(); });
}

int vtkTimeCriticalRenderer::GetNumberOfPendingHierarchies()
{
  int pending = 0;
  ForEachMultiresolutionMapper(this->GetViewProps(),
    [&pending](vtkMultiresolutionPolyDataMapper* m) { pending += m->GetNumberOfPendingHierarchies(); });
  return pending;
}
