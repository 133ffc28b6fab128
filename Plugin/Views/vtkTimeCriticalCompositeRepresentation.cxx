// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTimeCriticalCompositeRepresentation.h"

#include "vtkObjectFactory.h"
#include "vtkTimeCriticalSurfaceRepresentation.h"

#include <cstring>

vtkStandardNewMacro(vtkTimeCriticalCompositeRepresentation);

namespace
{
/// The keys (and vtkGeometryRepresentation types) of ParaView's surface representation.
const char* const SurfaceKeys[] = { "Points", "Wireframe", "Surface", "Surface With Edges" };

bool IsSurfaceKey(const char* key)
{
  for (const char* surfaceKey : SurfaceKeys)
  {
    if (key && std::strcmp(key, surfaceKey) == 0)
    {
      return true;
    }
  }
  return false;
}
} // namespace

vtkTimeCriticalCompositeRepresentation::vtkTimeCriticalCompositeRepresentation() = default;
vtkTimeCriticalCompositeRepresentation::~vtkTimeCriticalCompositeRepresentation() = default;

//------------------------------------------------------------------------------
void vtkTimeCriticalCompositeRepresentation::AddRepresentation(
  const char* key, vtkPVDataRepresentation* repr)
{
  if (auto* surface = vtkTimeCriticalSurfaceRepresentation::SafeDownCast(repr))
  {
    this->TimeCriticalSurface = surface;
    for (const char* surfaceKey : SurfaceKeys)
    {
      this->Superclass::RemoveRepresentation(surfaceKey);
      this->Superclass::AddRepresentation(surfaceKey, surface);
    }
    return;
  }
  if (this->TimeCriticalSurface && IsSurfaceKey(key))
  {
    return; // the time-critical surface holds this key
  }
  this->Superclass::AddRepresentation(key, repr);
}

//------------------------------------------------------------------------------
void vtkTimeCriticalCompositeRepresentation::SetActiveRepresentation(const char* key)
{
  if (this->TimeCriticalSurface && IsSurfaceKey(key))
  {
    this->TimeCriticalSurface->SetRepresentation(key);
  }
  this->Superclass::SetActiveRepresentation(key);
}

vtkTimeCriticalSurfaceRepresentation* vtkTimeCriticalCompositeRepresentation::GetTimeCriticalSurface()
{
  return this->TimeCriticalSurface;
}

//------------------------------------------------------------------------------
void vtkTimeCriticalCompositeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TimeCriticalSurface: " << this->TimeCriticalSurface.GetPointer() << "\n";
}
