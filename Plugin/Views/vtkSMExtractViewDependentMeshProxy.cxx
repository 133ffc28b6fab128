// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSMExtractViewDependentMeshProxy.h"

#include "vtkObjectFactory.h"
#include "vtkPVXMLElement.h"

#include <cstring>
#include <string>

vtkStandardNewMacro(vtkSMExtractViewDependentMeshProxy);

vtkSMExtractViewDependentMeshProxy::vtkSMExtractViewDependentMeshProxy() = default;

vtkSMExtractViewDependentMeshProxy::~vtkSMExtractViewDependentMeshProxy() = default;

namespace
{
vtkPVXMLElement* FindProperty(vtkPVXMLElement* element, const char* name)
{
  for (unsigned int i = 0; i < element->GetNumberOfNestedElements(); ++i)
  {
    vtkPVXMLElement* child = element->GetNestedElement(i);
    const char* childName = child->GetAttribute("name");
    if (std::strcmp(child->GetName(), "Property") == 0 && childName &&
      std::strcmp(childName, name) == 0)
    {
      return child;
    }
  }
  return nullptr;
}
}

bool vtkSMExtractViewDependentMeshProxy::TranslateLegacyRefinementMode(vtkPVXMLElement* element)
{
  vtkPVXMLElement* legacy = element ? FindProperty(element, "RefinementMode") : nullptr;
  if (!legacy || FindProperty(element, "Mode"))
  {
    return false;
  }
  vtkPVXMLElement* value = legacy->FindNestedElementByName("Element");
  const char* text = value ? value->GetAttribute("value") : nullptr;
  if (!text || (std::strcmp(text, "0") != 0 && std::strcmp(text, "1") != 0))
  {
    return false; // not a mode: left for the internal property to report
  }
  // Former 0 = Fixed Accuracy is now 1; former 1 = Triangle Budget is now 0 (budget).
  value->SetAttribute("value", std::strcmp(text, "0") == 0 ? "1" : "0");
  legacy->SetAttribute("name", "Mode");
  const char* id = legacy->GetAttribute("id");
  if (id)
  {
    std::string newId(id);
    const std::string::size_type dot = newId.rfind('.');
    newId = (dot == std::string::npos ? newId : newId.substr(0, dot)) + ".Mode";
    legacy->SetAttribute("id", newId.c_str());
  }
  // The saved domain lists the former texts; the proxy's own domain applies.
  while (vtkPVXMLElement* domain = legacy->FindNestedElementByName("Domain"))
  {
    legacy->RemoveNestedElement(domain);
  }
  return true;
}

int vtkSMExtractViewDependentMeshProxy::LoadXMLState(
  vtkPVXMLElement* element, vtkSMProxyLocator* locator)
{
  TranslateLegacyRefinementMode(element);
  return this->Superclass::LoadXMLState(element, locator);
}

void vtkSMExtractViewDependentMeshProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
