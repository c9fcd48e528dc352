# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
# Which VTK (and ParaView) vtkHAVS builds against, included from the top-level
# CMakeLists.txt before find_package(VTK).
#
# 1. VTK_DIR and ParaView_DIR given by the user win. Otherwise the newest
#    <libdir>/cmake/paraview-* is used (Debian's paraview-dev: 5.11 on
#    Debian 12, 5.13 on Debian 13, 6.1 on Debian testing) with its VTK: the
#    one inside it (vtk/, ParaView 5.x) or, for a ParaView built on an
#    external VTK (6.1 on Debian testing), the newest vtk-9.* beside it
#    (libvtk9-dev); else the newest standalone vtk-9.*, without the plugin.
#    The plugin needs the ParaView whose VTK builds the module; with any other
#    VTK it is switched off (VTKHAVS_BUILD_PARAVIEW_PLUGIN).
#
# 2. Debian 13's paraview-dev (5.13.2+dfsg-3) and Debian testing's (6.1.1)
#    export their Python extension modules (VTKPython, ParaViewPython,
#    ParaViewPythonIncubator target files; 6.1's own VTK 9.6 is right)
#    as .../vtkmodules/vtkCommonCore.so while the package ships them renamed
#    with Python's extension suffix (vtkCommonCore.cpython-313-x86_64-linux-gnu.so),
#    so the target files stop every find_package(VTK) on their existence check.
#    Where that is the case, corrected copies of those target files (the same
#    text, the missing file names replaced by the ones that are there) are
#    written into the build tree and included first; the installed files then
#    find their targets already defined and return without doing anything
#    (CMake's guard against a second inclusion). Nothing outside the build tree
#    is touched, and where the names are right (Debian 12) nothing happens.

set(_vtkhavs_cmake_dirs)
foreach (_vtkhavs_libdir IN ITEMS "lib/${CMAKE_LIBRARY_ARCHITECTURE}" lib lib64)
  foreach (_vtkhavs_prefix IN LISTS CMAKE_PREFIX_PATH CMAKE_SYSTEM_PREFIX_PATH)
    if (IS_DIRECTORY "${_vtkhavs_prefix}/${_vtkhavs_libdir}/cmake")
      list(APPEND _vtkhavs_cmake_dirs "${_vtkhavs_prefix}/${_vtkhavs_libdir}/cmake")
    endif ()
  endforeach ()
endforeach ()
list(REMOVE_DUPLICATES _vtkhavs_cmake_dirs)

# vtkhavs_newest_config(<out> <glob>): the directory of highest version among
# <cmake dir>/<glob> that holds a package config file.
function (vtkhavs_newest_config out glob)
  set(best "")
  set(best_version "")
  foreach (dir IN LISTS _vtkhavs_cmake_dirs)
    file(GLOB candidates LIST_DIRECTORIES true "${dir}/${glob}")
    foreach (candidate IN LISTS candidates)
      string(REGEX MATCH "[0-9]+(\\.[0-9]+)*$" version "${candidate}")
      if (version AND (EXISTS "${candidate}/paraview-config.cmake" OR EXISTS "${candidate}/vtk-config.cmake")
          AND (best STREQUAL "" OR version VERSION_GREATER best_version))
        set(best "${candidate}")
        set(best_version "${version}")
      endif ()
    endforeach ()
  endforeach ()
  set("${out}" "${best}" PARENT_SCOPE)
endfunction ()

# vtkhavs_paraview_vtk(<out> <ParaView dir>): the VTK config directory a
# ParaView builds with: its own (<dir>/vtk, ParaView 5.x as Debian 12 and 13
# ship it) or, for a ParaView built on an external VTK (ParaView 6.1 on Debian
# testing: `_paraview_use_external_vtk ON`), the newest vtk-9.* config beside
# it (Debian's libvtk9-dev, which paraview-dev does not pull in); "" if none.
function (vtkhavs_paraview_vtk out pvdir)
  set(result "")
  if (EXISTS "${pvdir}/vtk/vtk-config.cmake")
    set(result "${pvdir}/vtk")
  elseif (EXISTS "${pvdir}/paraview-config.cmake")
    file(STRINGS "${pvdir}/paraview-config.cmake" external
      REGEX "set\\(_paraview_use_external_vtk \"ON\"\\)")
    if (external)
      vtkhavs_newest_config(result "vtk-9.*")
    endif ()
  endif ()
  set("${out}" "${result}" PARENT_SCOPE)
endfunction ()

if (NOT VTK_DIR AND NOT ParaView_DIR)
  vtkhavs_newest_config(_vtkhavs_paraview_dir "paraview-*")
  set(_vtkhavs_paraview_vtk_dir "")
  if (_vtkhavs_paraview_dir)
    vtkhavs_paraview_vtk(_vtkhavs_paraview_vtk_dir "${_vtkhavs_paraview_dir}")
  endif ()
  if (_vtkhavs_paraview_dir AND NOT _vtkhavs_paraview_vtk_dir)
    message(WARNING "vtkHAVS: the VTK of the ParaView in ${_vtkhavs_paraview_dir} has no "
      "development files here (neither its own vtk/ nor, for a ParaView built on an external "
      "VTK, a vtk-9.* config: Debian's libvtk9-dev); the ParaView plugin is not built")
  endif ()
  if (_vtkhavs_paraview_vtk_dir)
    set(ParaView_DIR "${_vtkhavs_paraview_dir}" CACHE PATH "ParaView config directory")
    set(VTK_DIR "${_vtkhavs_paraview_vtk_dir}" CACHE PATH "VTK config directory")
  else ()
    vtkhavs_newest_config(_vtkhavs_vtk_dir "vtk-9.*")
    if (_vtkhavs_vtk_dir)
      set(VTK_DIR "${_vtkhavs_vtk_dir}" CACHE PATH "VTK config directory")
    endif ()
  endif ()
endif ()
if (NOT VTK_DIR AND ParaView_DIR)
  vtkhavs_paraview_vtk(_vtkhavs_paraview_vtk_dir "${ParaView_DIR}")
  if (_vtkhavs_paraview_vtk_dir)
    set(VTK_DIR "${_vtkhavs_paraview_vtk_dir}" CACHE PATH "VTK config directory")
  endif ()
endif ()
if (VTK_DIR AND NOT ParaView_DIR AND EXISTS "${VTK_DIR}/../paraview-config.cmake")
  get_filename_component(_vtkhavs_paraview_dir "${VTK_DIR}/.." ABSOLUTE)
  set(ParaView_DIR "${_vtkhavs_paraview_dir}" CACHE PATH "ParaView config directory")
endif ()

# The plugin only with the ParaView that this VTK belongs to.
if (VTK_DIR)
  set(_vtkhavs_paraview_vtk "")
  if (ParaView_DIR)
    vtkhavs_paraview_vtk(_vtkhavs_paraview_vtk "${ParaView_DIR}")
    if (_vtkhavs_paraview_vtk)
      get_filename_component(_vtkhavs_paraview_vtk "${_vtkhavs_paraview_vtk}" REALPATH)
    endif ()
  endif ()
  get_filename_component(_vtkhavs_vtk_real "${VTK_DIR}" REALPATH)
  if (NOT _vtkhavs_paraview_vtk STREQUAL _vtkhavs_vtk_real)
    message(STATUS "vtkHAVS: ${VTK_DIR} is not the VTK of a ParaView (ParaView_DIR: "
      "${ParaView_DIR}); the ParaView plugin is not built")
    set(VTKHAVS_BUILD_PARAVIEW_PLUGIN OFF)
  endif ()
endif ()

# The packaging fault of point 2 (also used by the installed vtkHAVSConfig.cmake).
include("${CMAKE_CURRENT_LIST_DIR}/vtkHAVSPythonTargetsFix.cmake")

if (VTK_DIR AND NOT TARGET VTK::vtkpythonmodules)
  set(_vtkhavs_sets "${VTK_DIR}" VTKPython)
  if (ParaView_DIR AND NOT VTKHAVS_BUILD_PARAVIEW_PLUGIN STREQUAL "OFF")
    list(APPEND _vtkhavs_sets "${ParaView_DIR}" ParaViewPython "${ParaView_DIR}" ParaViewPythonIncubator)
  endif ()
  vtkhavs_fix_python_targets(${_vtkhavs_sets})
endif ()
