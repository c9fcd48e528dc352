# Which VTK (and ParaView) vtkHAVS builds against, included from the top-level
# CMakeLists.txt before find_package(VTK).
#
# 1. VTK_DIR and ParaView_DIR given by the user win. Otherwise the newest
#    <libdir>/cmake/paraview-5.* is used (Debian's paraview-dev: 5.11 on
#    Debian 12, 5.13 on Debian 13) with the VTK inside it (its vtk/), else the
#    newest standalone vtk-9.* (Debian's libvtk9-dev), without the plugin.
#    The plugin needs the ParaView whose VTK builds the module; with any other
#    VTK it is switched off (VTKHAVS_BUILD_PARAVIEW_PLUGIN).
#
# 2. Debian 13's paraview-dev (5.13.2+dfsg-3) exports its Python extension
#    modules (VTKPython, ParaViewPython, ParaViewPythonIncubator target files)
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

if (NOT VTK_DIR AND NOT ParaView_DIR)
  vtkhavs_newest_config(_vtkhavs_paraview_dir "paraview-5.*")
  if (_vtkhavs_paraview_dir AND EXISTS "${_vtkhavs_paraview_dir}/vtk/vtk-config.cmake")
    set(ParaView_DIR "${_vtkhavs_paraview_dir}" CACHE PATH "ParaView config directory")
  else ()
    vtkhavs_newest_config(_vtkhavs_vtk_dir "vtk-9.*")
    if (_vtkhavs_vtk_dir)
      set(VTK_DIR "${_vtkhavs_vtk_dir}" CACHE PATH "VTK config directory")
    endif ()
  endif ()
endif ()
if (NOT VTK_DIR AND ParaView_DIR AND EXISTS "${ParaView_DIR}/vtk/vtk-config.cmake")
  set(VTK_DIR "${ParaView_DIR}/vtk" CACHE PATH "VTK config directory")
endif ()
if (VTK_DIR AND NOT ParaView_DIR AND EXISTS "${VTK_DIR}/../paraview-config.cmake")
  get_filename_component(_vtkhavs_paraview_dir "${VTK_DIR}/.." ABSOLUTE)
  set(ParaView_DIR "${_vtkhavs_paraview_dir}" CACHE PATH "ParaView config directory")
endif ()

# The plugin only with the ParaView that this VTK belongs to.
if (VTK_DIR)
  set(_vtkhavs_paraview_vtk "")
  if (ParaView_DIR)
    get_filename_component(_vtkhavs_paraview_vtk "${ParaView_DIR}/vtk" REALPATH)
  endif ()
  get_filename_component(_vtkhavs_vtk_real "${VTK_DIR}" REALPATH)
  if (NOT _vtkhavs_paraview_vtk STREQUAL _vtkhavs_vtk_real)
    message(STATUS "vtkHAVS: ${VTK_DIR} is not the VTK of a ParaView (ParaView_DIR: "
      "${ParaView_DIR}); the ParaView plugin is not built")
    set(VTKHAVS_BUILD_PARAVIEW_PLUGIN OFF)
  endif ()
endif ()

# _vtkhavs_python_targets(<out var> <config dir> <export set> [<copy dir>]):
# counts the Python module files that <config dir>/<export set>-targets-*.cmake
# name but that are not there while exactly one <name>.<suffix>.so is; with
# <copy dir>, writes the target files there with those names corrected.
function (_vtkhavs_python_targets out dir name)
  set(copy "${ARGN}")
  set(fixed 0)
  set(main "${dir}/${name}-targets.cmake")
  if (NOT EXISTS "${main}")
    set("${out}" 0 PARENT_SCOPE)
    return ()
  endif ()
  # The prefix the file computes: its directory, up once per
  # get_filename_component(_IMPORT_PREFIX "${_IMPORT_PREFIX}" PATH).
  file(READ "${main}" text)
  string(REGEX MATCHALL "get_filename_component\\(_IMPORT_PREFIX \"\\\${_IMPORT_PREFIX}\" PATH\\)"
    ups "${text}")
  set(prefix "${dir}")
  foreach (up IN LISTS ups)
    get_filename_component(prefix "${prefix}" DIRECTORY)
  endforeach ()
  if (copy)
    # The copy computes its prefix from the installed file's place and loads
    # the per-configuration files beside itself (the corrected copies).
    string(REPLACE "\"\${CMAKE_CURRENT_LIST_FILE}\"" "\"${main}\"" text "${text}")
    _vtkhavs_write_if_changed("${copy}/${name}-targets.cmake" "${text}")
  endif ()
  file(GLOB per_config "${dir}/${name}-targets-*.cmake")
  foreach (config_file IN LISTS per_config)
    file(READ "${config_file}" text)
    string(REGEX MATCHALL "\"\\\${_IMPORT_PREFIX}/[^\";]+\\.so\"" paths "${text}")
    list(REMOVE_DUPLICATES paths)
    foreach (quoted IN LISTS paths)
      string(REGEX REPLACE "^\"\\\${_IMPORT_PREFIX}/(.*)\\.so\"$" "\\1" stem "${quoted}")
      if (NOT EXISTS "${prefix}/${stem}.so")
        file(GLOB tagged "${prefix}/${stem}.*.so")
        list(LENGTH tagged n)
        if (n EQUAL 1)
          file(RELATIVE_PATH tagged "${prefix}" "${tagged}")
          string(REPLACE "${quoted}" "\"\${_IMPORT_PREFIX}/${tagged}\"" text "${text}")
          math(EXPR fixed "${fixed} + 1")
        endif ()
      endif ()
    endforeach ()
    if (copy)
      get_filename_component(config_name "${config_file}" NAME)
      _vtkhavs_write_if_changed("${copy}/${config_name}" "${text}")
    endif ()
  endforeach ()
  set("${out}" "${fixed}" PARENT_SCOPE)
endfunction ()

function (_vtkhavs_write_if_changed path text)
  set(old "")
  if (EXISTS "${path}")
    file(READ "${path}" old)
  endif ()
  if (NOT old STREQUAL text)
    file(WRITE "${path}" "${text}")
  endif ()
endfunction ()

# vtkhavs_fix_python_targets(<config dir> <export set> ...): where any of the
# given target files name such missing modules, corrected copies of all of
# them are written under the build tree and included in the order given
# (ParaView's sets check that VTK's VTK::vtkpythonmodules exists).
function (vtkhavs_fix_python_targets)
  set(fixed 0)
  set(args "${ARGN}")
  while (args)
    list(POP_FRONT args dir name)
    _vtkhavs_python_targets(n "${dir}" "${name}")
    math(EXPR fixed "${fixed} + ${n}")
  endwhile ()
  if (fixed EQUAL 0)
    return ()
  endif ()
  set(out_root "${CMAKE_BINARY_DIR}/CMakeFiles/vtkHAVSPythonTargets")
  message(STATUS "vtkHAVS: ${fixed} Python module file names in the installed target files "
    "are not the files on disk (those carry Python's extension suffix); using corrected "
    "copies in ${out_root}")
  set(args "${ARGN}")
  while (args)
    list(POP_FRONT args dir name)
    if (EXISTS "${dir}/${name}-targets.cmake")
      _vtkhavs_python_targets(n "${dir}" "${name}" "${out_root}")
      include("${out_root}/${name}-targets.cmake")
    endif ()
  endwhile ()
endfunction ()

if (VTK_DIR AND NOT TARGET VTK::vtkpythonmodules)
  set(_vtkhavs_sets "${VTK_DIR}" VTKPython)
  if (ParaView_DIR AND NOT VTKHAVS_BUILD_PARAVIEW_PLUGIN STREQUAL "OFF")
    list(APPEND _vtkhavs_sets "${ParaView_DIR}" ParaViewPython "${ParaView_DIR}" ParaViewPythonIncubator)
  endif ()
  vtkhavs_fix_python_targets(${_vtkhavs_sets})
endif ()
