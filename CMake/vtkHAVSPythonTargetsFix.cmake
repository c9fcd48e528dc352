# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
# Debian 13's paraview-dev (5.13.2+dfsg-3) exports its Python extension modules
# as .../vtkmodules/<name>.so while the package ships them with Python's
# extension suffix (<name>.cpython-313-x86_64-linux-gnu.so), so the target
# files stop every find_package(VTK) on their existence check.
# vtkhavs_fix_python_targets(<config dir> <export set> ...) writes corrected
# copies of those target files under the calling project's build tree and
# includes them first; the installed files then find their targets defined and
# return on CMake's own guard. Nothing outside the build tree is touched, and
# where the names are right (Debian 12) nothing happens. Included by
# vtkHAVSFindVTK.cmake (building vtkHAVS) and by the installed
# vtkHAVSConfig.cmake (projects that use vtkHAVS).
include_guard(GLOBAL)

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

