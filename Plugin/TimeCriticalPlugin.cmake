# Declares the ParaView plugin. Included by the top-level CMakeLists.txt when
# paraview_plugin_build() enters the folder holding paraview.plugin.
set(timecritical_plugin_module_args)
if (TIMECRITICAL_PLUGIN_BUILDS_MODULES)
  # Built as an external plugin directory: the modules are not built yet.
  set(timecritical_plugin_module_args
    MODULE_FILES
      "${CMAKE_CURRENT_LIST_DIR}/../Core/Mesh/vtk.module"
      "${CMAKE_CURRENT_LIST_DIR}/../Core/Budget/vtk.module"
      "${CMAKE_CURRENT_LIST_DIR}/../Filters/vtk.module"
      "${CMAKE_CURRENT_LIST_DIR}/../Rendering/vtk.module"
      "${CMAKE_CURRENT_LIST_DIR}/Views/vtk.module")
  if (NOT COMMAND timecritical_strict_warnings)
    function (timecritical_strict_warnings)
    endfunction ()
  endif ()
endif ()

paraview_add_plugin(TimeCritical
  VERSION "0.1"
  MODULES
    TimeCritical::Filters
    TimeCritical::Rendering
    TimeCritical::Views
  ${timecritical_plugin_module_args}
  SERVER_MANAGER_XML
    "${CMAKE_CURRENT_LIST_DIR}/TimeCriticalFilters.xml"
    "${CMAKE_CURRENT_LIST_DIR}/TimeCriticalViews.xml")
