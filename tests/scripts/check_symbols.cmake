# check_symbols.cmake -- what libkarma exports and what it depends on (run by CTest in script mode).
#
#   -DSHARED=<libkarma.so> -DSTATIC=<libkarma.a> -DHEADERS=<include/karma> -DNM=<nm> -DREADELF=<readelf>
#   -DCC=<compiler> -DWORK=<scratch dir> -DSANITIZE=ON|OFF
#
# 1. The shared library exports exactly the functions and data declared with ME_API in the public headers:
#    nothing internal leaks (hidden visibility works) and nothing declared is missing.
# 2. It needs only libm and libc (plus the sanitizer runtimes in a sanitizer build).
# 3. Every global symbol of the static library carries a Karma prefix (no clash with users' names).
# 4. The static library links into a program with libm alone.
cmake_minimum_required(VERSION 3.20)
set(failures "")

# ---- 1. exported symbols = ME_API declarations ----------------------------------------------
file(GLOB headers ${HEADERS}/*.h)
set(declared "")
set(renamed "")
foreach(h ${headers})
  file(READ ${h} text)
  string(REGEX MATCHALL "ME_API[^(;#]*\\(" decls "${text}")
  foreach(d ${decls})
    string(REGEX MATCH "([A-Za-z_][A-Za-z0-9_]*)[ \t\n]*\\($" m "${d}")
    list(APPEND declared ${CMAKE_MATCH_1})
  endforeach()
  # Exported data: Karma 1.2's global tables and hooks (`ME_API extern MeMemoryAPIStruct MeMemoryAPI;`).
  string(REGEX MATCHALL "ME_API extern [^;(]*[A-Za-z0-9_]" datas "${text}")
  foreach(d ${datas})
    string(REGEX MATCH "([A-Za-z_][A-Za-z0-9_]*)$" m "${d}")
    list(APPEND declared ${CMAKE_MATCH_1})
  endforeach()
  string(REGEX MATCHALL "#define[ \t]+[A-Za-z0-9_]+[ \t]+ME_PRECISION_SYMBOL" defs "${text}")
  foreach(d ${defs})
    string(REGEX MATCH "#define[ \t]+([A-Za-z0-9_]+)" m "${d}")
    list(APPEND renamed ${CMAKE_MATCH_1})
  endforeach()
endforeach()
if(SUFFIX STREQUAL "")
  message(FATAL_ERROR "SUFFIX (_f or _d) not given")
endif()
set(expected "")
foreach(name ${declared})
  if(name IN_LIST renamed)
    list(APPEND expected ${name}${SUFFIX})
  else()
    list(APPEND expected ${name})
  endif()
endforeach()
list(REMOVE_DUPLICATES expected)
list(LENGTH expected declaredCount)

execute_process(COMMAND ${NM} -D --defined-only ${SHARED} OUTPUT_VARIABLE out RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "${NM} -D failed on ${SHARED}")
endif()
string(REGEX MATCHALL "[^\n]+" lines "${out}")
set(exported "")
foreach(line ${lines})
  string(REGEX MATCH "^[0-9a-fA-F]* *([A-Za-z]) ([^ ]+)$" m "${line}")
  set(name ${CMAKE_MATCH_2})
  # Symbols the linker defines in every shared object.
  if(name MATCHES "^(_init|_fini|_edata|_end|__bss_start)$")
    continue()
  endif()
  # AddressSanitizer's ODR indicator of each exported variable (MeMemoryAPI...).
  if(SANITIZE AND name MATCHES "^__odr_asan")
    continue()
  endif()
  list(APPEND exported ${name})
  if(NOT name IN_LIST expected)
    list(APPEND failures "exported but not declared with ME_API in a public header: ${name}")
  endif()
endforeach()
foreach(name ${expected})
  if(NOT name IN_LIST exported)
    list(APPEND failures "declared with ME_API but not exported (missing definition or ME_API): ${name}")
  endif()
endforeach()
list(LENGTH exported exportedCount)
message(STATUS "exported: ${exportedCount} symbols; ME_API declarations: ${declaredCount}")

# ---- 2. shared library dependencies --------------------------------------------------------
execute_process(COMMAND ${READELF} -d ${SHARED} OUTPUT_VARIABLE out RESULT_VARIABLE rc)
string(REGEX MATCHALL "Shared library: \\[[^]]+\\]" needed "${out}")
set(allowed "^(libm|libc)\\.so")
if(SANITIZE)
  set(allowed "^(libm|libc|libasan|libubsan|libstdc\\+\\+|libgcc_s)\\.so")
endif()
foreach(n ${needed})
  string(REGEX REPLACE "Shared library: \\[([^]]+)\\]" "\\1" lib "${n}")
  message(STATUS "libkarma.so needs ${lib}")
  if(NOT lib MATCHES "${allowed}")
    list(APPEND failures "libkarma.so depends on ${lib}; the core may depend on libm (and libc) only")
  endif()
endforeach()

# ---- 3. static library globals carry Karma prefixes -----------------------------------------
execute_process(COMMAND ${NM} -g --defined-only ${STATIC} OUTPUT_VARIABLE out RESULT_VARIABLE rc)
string(REGEX MATCHALL "[^\n]+" lines "${out}")
set(globals 0)
foreach(line ${lines})
  if(NOT line MATCHES "^[0-9a-fA-F]+ [A-Za-z] ")
    continue() # archive member headers
  endif()
  string(REGEX MATCH "^[0-9a-fA-F]+ [A-Za-z] (.+)$" m "${line}")
  set(name ${CMAKE_MATCH_1})
  math(EXPR globals "${globals} + 1")
  if(SANITIZE AND name MATCHES "^(__odr_asan|__asan|__ubsan)")
    continue() # instrumentation the sanitizers add for each global (ODR indicators)
  endif()
  if(NOT name MATCHES "^(Me|Mdt|Mcd|Mst|Kea|ME_|MDT_|MCD_|MST_)")
    list(APPEND failures "libkarma.a defines the global '${name}' without a Karma prefix")
  endif()
endforeach()
message(STATUS "libkarma.a: ${globals} global symbols, all with a Karma prefix unless listed below")

# ---- 4. the static library links with libm alone ------------------------------------------
file(MAKE_DIRECTORY ${WORK})
file(WRITE ${WORK}/empty_main.c "int main(void) { return 0; }\n")
set(flags "")
if(SANITIZE)
  set(flags -fsanitize=address,undefined)
endif()
execute_process(COMMAND ${CC} ${flags} ${WORK}/empty_main.c -Wl,--whole-archive ${STATIC} -Wl,--no-whole-archive
                        -lm -o ${WORK}/whole_archive
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  list(APPEND failures "the whole of libkarma.a does not link with libm alone:\n${err}")
endif()

if(failures)
  list(JOIN failures "\n  " text)
  message(FATAL_ERROR "symbol check failed:\n  ${text}")
endif()
message(STATUS "symbol check passed")
