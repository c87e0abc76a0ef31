# check_layers.cmake -- which part of the library may include which (run by CTest in script mode).
#
#   -DSRC=<a source tree laid out like src/>
#
# Kea (src/mdt/kea) is a solver library: it includes its own headers, Me's (<karma/Me*.h>,
# src/me/) and the C library, never Mdt, BCL, Mcd or Mst. Mdt (src/mdt, BCL included) never
# includes Mcd or Mst; Mcd (src/mcd) never includes Mdt, Kea, BCL or Mst. Only Mst joins them.
# Mdt's stages (src/mdt/*.c: LOD, debug drawing) do not include the contact's struct. Mst (src/mst)
# is written as an application's own bridge would be: public headers (<karma/*.h>), its own headers,
# Me's internal helpers (src/me/: messages, handles) and the C library, nothing private of Mdt or Mcd.
# Each #include line is read as text; a violation names the file, the line and the rule.
cmake_minimum_required(VERSION 3.20)
if(NOT SRC)
  message(FATAL_ERROR "SRC (the source tree) not given")
endif()
set(failures "")

# Report every #include of `files` whose target matches `forbidden` (a regex), or does not match
# `allowed` when that is given.
function(check_includes rule files forbidden allowed)
  foreach(f ${files})
    file(STRINGS ${f} lines REGEX "^[ \t]*#[ \t]*include")
    foreach(line ${lines})
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]+)[>\"].*$" "\\1" target "${line}")
      set(bad FALSE)
      if(forbidden AND target MATCHES "${forbidden}")
        set(bad TRUE)
      endif()
      if(allowed AND NOT target MATCHES "${allowed}")
        set(bad TRUE)
      endif()
      if(bad)
        file(RELATIVE_PATH rel ${SRC} ${f})
        list(APPEND failures "${rel}: #include ${target}: ${rule}")
      endif()
    endforeach()
  endforeach()
  set(failures "${failures}" PARENT_SCOPE)
endfunction()

file(GLOB kea ${SRC}/mdt/kea/*.c ${SRC}/mdt/kea/*.h)
# Kea: its own files (kea*.h, no directory), Me (<karma/Me*.h>, ../../me/), system headers.
check_includes("Kea includes only Kea, Me and system headers" "${kea}" ""
               "^(kea[A-Za-z0-9_]*\\.h|karma/Me[A-Za-z0-9]*\\.h|\\.\\./\\.\\./me/[A-Za-z0-9_]+\\.h|[a-z0-9_]+\\.h)$")
check_includes("Kea includes no Mdt, BCL, Mcd or Mst header" "${kea}"
               "(^|/)(Mdt|Mcd|Mst)[A-Za-z0-9]*\\.h$|\\.\\./(world|body|constraint)|bcl/|mcd/|mst/" "")

file(GLOB_RECURSE mdt ${SRC}/mdt/*.c ${SRC}/mdt/*.h)
check_includes("Mdt includes no Mcd or Mst header" "${mdt}" "(^|/)(Mcd|Mst)[A-Za-z0-9]*\\.h$|(^|/)(mcd|mst)/" "")

# Mdt's stages outside BCL reach contacts through bcl/contact_lod.h, not the contact's struct.
file(GLOB mdtStages ${SRC}/mdt/*.c ${SRC}/mdt/*.h)
check_includes("Mdt's stages see contacts through bcl/contact_lod.h only" "${mdtStages}" "contact_internal\\.h$" "")

file(GLOB_RECURSE mcd ${SRC}/mcd/*.c ${SRC}/mcd/*.h)
check_includes("Mcd includes no Mdt, Kea, BCL or Mst header" "${mcd}"
               "(^|/)(Mdt|Mst)[A-Za-z0-9]*\\.h$|(^|/)(mdt|mst|kea|bcl)/" "")

file(GLOB_RECURSE mst ${SRC}/mst/*.c ${SRC}/mst/*.h)
check_includes("Mst includes only public headers, Me's helpers and its own" "${mst}" ""
               "^(karma/[A-Za-z0-9_]+\\.h|\\.\\./me/[A-Za-z0-9_]+\\.h|[a-z0-9_]+\\.h)$")

list(LENGTH kea keaCount)
list(LENGTH mdt mdtCount)
list(LENGTH mcd mcdCount)
list(LENGTH mst mstCount)
if(failures)
  list(JOIN failures "\n  " text)
  message(FATAL_ERROR "layering violations:\n  ${text}")
endif()
message(STATUS "layers: ${keaCount} Kea, ${mdtCount} Mdt, ${mcdCount} Mcd and ${mstCount} Mst files include only what they may")
