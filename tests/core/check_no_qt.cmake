# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
file(GLOB_RECURSE sources "${CORE_DIR}/*.h" "${CORE_DIR}/*.cpp")
foreach(source IN LISTS sources)
  file(STRINGS "${source}" hits REGEX "#[ \t]*include[ \t]*[<\"]Q")
  if(hits)
    message(FATAL_ERROR "${source} includes Qt: ${hits}")
  endif()
endforeach()
list(LENGTH sources count)
if(count EQUAL 0)
  message(FATAL_ERROR "no sources found in ${CORE_DIR}")
endif()
message(STATUS "${count} core files, none includes Qt")
