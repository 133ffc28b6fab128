// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSMTimeCriticalRenderViewProxy.h"

#include "vtkObjectFactory.h"
#include "vtkPVView.h"
#include "vtkSMSettings.h"

namespace
{
bool GUIDefaultsAdded = false; // once per process (proxies are made on the client's main thread)
}

vtkStandardNewMacro(vtkSMTimeCriticalRenderViewProxy);

//------------------------------------------------------------------------------
vtkSMTimeCriticalRenderViewProxy::vtkSMTimeCriticalRenderViewProxy()
{
  // Before the proxy manager initializes this proxy from the settings.
  if (vtkSMTimeCriticalRenderViewProxy::IsGUIApplication())
  {
    vtkSMTimeCriticalRenderViewProxy::AddGUIDefaults();
  }
}

vtkSMTimeCriticalRenderViewProxy::~vtkSMTimeCriticalRenderViewProxy() = default;

//------------------------------------------------------------------------------
bool vtkSMTimeCriticalRenderViewProxy::IsGUIApplication()
{
  return vtkPVView::GetUseGenericOpenGLRenderWindow();
}

bool vtkSMTimeCriticalRenderViewProxy::AddGUIDefaults()
{
  if (GUIDefaultsAdded)
  {
    return false;
  }
  GUIDefaultsAdded = vtkSMSettings::GetInstance()->AddCollectionFromString(
    vtkSMTimeCriticalRenderViewProxy::GetGUIDefaults(),
    vtkSMTimeCriticalRenderViewProxy::GetGUIDefaultsPriority());
  return GUIDefaultsAdded;
}

const char* vtkSMTimeCriticalRenderViewProxy::GetGUIDefaults()
{
  return R"({ "views" : { "TimeCriticalRenderView" : { "BackgroundHierarchyBuilds" : 1 } } })";
}

double vtkSMTimeCriticalRenderViewProxy::GetGUIDefaultsPriority()
{
  return 0.0;
}

//------------------------------------------------------------------------------
void vtkSMTimeCriticalRenderViewProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GUIApplication: " << vtkSMTimeCriticalRenderViewProxy::IsGUIApplication()
     << "\n";
  os << indent << "GUIDefaultsAdded: " << GUIDefaultsAdded << "\n";
}
