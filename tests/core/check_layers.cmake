# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# core/'s folders are layers (docs/design.md "Layout"), each using only those below it:
#   numbers < model < solver < orbits < methods < experiments
# A file may include core/F/... only when F is its own folder's layer or below. No source lies
# in core/ itself (a concept has its folder).
set(layers numbers model solver orbits methods experiments)
file(GLOB_RECURSE sources RELATIVE "${CORE_DIR}" "${CORE_DIR}/*.h" "${CORE_DIR}/*.cpp")
set(count 0)
foreach(source IN LISTS sources)
  math(EXPR count "${count} + 1")
  string(REGEX MATCH "^[a-z_]+/" folder "${source}")
  if(NOT folder)
    message(FATAL_ERROR "core/${source} lies in core/ itself: it belongs in a folder of its concept")
  endif()
  string(REPLACE "/" "" folder "${folder}")
  list(FIND layers "${folder}" own)
  if(own EQUAL -1)
    message(FATAL_ERROR "core/${folder}/ is not a layer (${layers}): add it to docs/design.md and here")
  endif()
  file(STRINGS "${CORE_DIR}/${source}" includes REGEX "#[ \t]*include[ \t]*\"core/[a-z_]+/")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE ".*\"core/([a-z_]+)/.*" "\\1" used "${line}")
    list(FIND layers "${used}" rank)
    if(rank GREATER own)
      message(FATAL_ERROR "core/${source} (layer ${folder}) includes core/${used}/, a layer above it: ${line}")
    endif()
  endforeach()
endforeach()
if(count EQUAL 0)
  message(FATAL_ERROR "no sources found in ${CORE_DIR}")
endif()
message(STATUS "${count} core files, every include on its own layer or below (${layers})")
