// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSMTimeCriticalRenderViewProxy
 * @brief   the proxy of the Time-Critical Render View: its defaults in the ParaView GUI
 *
 * A vtkSMRenderViewProxy (the GUI makes a pqRenderView of it, Python a
 * render view) that gives new views defaults of their own in the ParaView
 * GUI: BackgroundHierarchyBuilds on, so that new data, a new time step or
 * an upstream edit is drawn at once while its hierarchy builds. Everywhere
 * else (pvpython, pvbatch, their client-server sessions) the XML default
 * (off) stays, so that scripts and tests get the same images run after run.
 *
 * The GUI defaults are a vtkSMSettings collection at priority 0, below the
 * site settings (1) and the user's settings (highest): a value the user
 * saves as the default (the Properties panel's "save as default") wins, and
 * they only set up new views (state files and scripts that set the property
 * keep their value). The GUI is recognised by the render windows it gives
 * views: vtkPVView::GetUseGenericOpenGLRenderWindow(), which the GUI's
 * application core turns on (its views draw into Qt widgets) and pvpython
 * and pvbatch leave off. The collection is added once per process, by the
 * first proxy constructed, before any view reads its settings.
 *
 * @sa vtkPVTimeCriticalRenderView vtkSMSettings
 */
#ifndef vtkSMTimeCriticalRenderViewProxy_h
#define vtkSMTimeCriticalRenderViewProxy_h

#include "TimeCriticalViewsModule.h" // for export macro
#include "vtkSMRenderViewProxy.h"

class TIMECRITICALVIEWS_EXPORT vtkSMTimeCriticalRenderViewProxy : public vtkSMRenderViewProxy
{
public:
  static vtkSMTimeCriticalRenderViewProxy* New();
  vtkTypeMacro(vtkSMTimeCriticalRenderViewProxy, vtkSMRenderViewProxy);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Whether this process is the ParaView GUI (its views draw into Qt widgets).
  static bool IsGUIApplication();

  /**
   * Adds the GUI defaults (GetGUIDefaults()) to vtkSMSettings at
   * GetGUIDefaultsPriority(), once per process; returns whether this call
   * added them. The constructor calls it in the GUI; a test calls it to see
   * the GUI's defaults in pvbatch.
   */
  static bool AddGUIDefaults();

  /// The GUI defaults, as vtkSMSettings JSON.
  static const char* GetGUIDefaults();

  /// 0: below the site settings (1) and the user's settings (highest).
  static double GetGUIDefaultsPriority();

protected:
  vtkSMTimeCriticalRenderViewProxy();
  ~vtkSMTimeCriticalRenderViewProxy() override;

private:
  vtkSMTimeCriticalRenderViewProxy(const vtkSMTimeCriticalRenderViewProxy&) = delete;
  void operator=(const vtkSMTimeCriticalRenderViewProxy&) = delete;
};

#endif
