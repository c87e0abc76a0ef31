# check_install.cmake -- install this build into a scratch prefix and use it from outside
# (run by CTest in script mode; see tests/cmake/install.cmake).
#
#   -DBUILD=<build dir> -DWORK=<scratch dir> -DHELLO=<examples/hello.c> -DOUTSIDE=<tests/install>
#   -DCC=<C compiler> -DPRECISION=single|double -DSANITIZE=ON|OFF -DPKG_CONFIG=<pkg-config or empty>
#
# 1. cmake --install puts headers, libkarma.a/.so, the CMake package and karma.pc under the prefix;
# 2. a separate CMake project finds the package and builds hello.c against karma::karma (static) and
#    karma::karma_shared; both programs run and print the expected fall; hello_threads links
#    karma::threads (the installed pool, found with its Threads dependency) and steps on two threads;
# 3. with pkg-config: `precision` matches the build, and hello.c builds from `--cflags --libs`
#    (shared) and from `--static --libs` with libkarma.a, and both run.
cmake_minimum_required(VERSION 3.20)
set(prefix ${WORK}/prefix)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(expected "Karma [0-9.]+ \\(${PRECISION} precision\\): the ball fell from 10 m to 5\\.013 m in one second")
set(flags "")
if(SANITIZE)
  set(flags -fsanitize=address,undefined -fno-sanitize-recover=all)
endif()

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

function(run_hello program)
  run("running ${program}" ${program})
  if(NOT last_output MATCHES "${expected}")
    message(FATAL_ERROR "${program} printed:\n${last_output}\nexpected a line matching:\n${expected}")
  endif()
  string(REGEX MATCH "${expected}" line "${last_output}")
  message(STATUS "${program}: ${line}")
endfunction()

# ---- 1. install ----------------------------------------------------------------------------
run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD} --prefix ${prefix})
foreach(f include/karma/karma.h include/karma/config.h include/karma/MdtWorld.h include/karma/MeThreadPool.h)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()
file(GLOB_RECURSE pc ${prefix}/*/karma.pc)
file(GLOB_RECURSE config ${prefix}/*/karmaConfig.cmake)
file(GLOB_RECURSE archive ${prefix}/*/libkarma.a)
if(NOT pc OR NOT config OR NOT archive)
  message(FATAL_ERROR "install is missing karma.pc (${pc}), karmaConfig.cmake (${config}) or libkarma.a (${archive})")
endif()

# ---- 2. find_package(karma) -----------------------------------------------------------------
list(JOIN flags " " flag_string)
run("configuring the outside project" ${CMAKE_COMMAND} -S ${OUTSIDE} -B ${WORK}/outside
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON -DCMAKE_C_COMPILER=${CC}
    -DCMAKE_BUILD_TYPE=Release -DHELLO=${HELLO} "-DCMAKE_C_FLAGS=${flag_string}"
    "-DCMAKE_EXE_LINKER_FLAGS=${flag_string}")
if(NOT last_output MATCHES "found karma [0-9.]+ \\(${PRECISION} precision\\) in ${prefix}/")
  message(FATAL_ERROR "find_package(karma) did not find the installed package:\n${last_output}")
endif()
run("building the outside project" ${CMAKE_COMMAND} --build ${WORK}/outside)
run_hello(${WORK}/outside/hello_static)
run_hello(${WORK}/outside/hello_shared)
run("running hello_threads" ${WORK}/outside/hello_threads)
if(NOT last_output MATCHES "threads: [0-9.]+ m on one thread, [0-9.]+ m on 2: bit-identical")
  message(FATAL_ERROR "hello_threads printed:\n${last_output}")
endif()

# ---- 3. pkg-config ------------------------------------------------------------------------
if(NOT PKG_CONFIG)
  message(STATUS "pkg-config not found: the pkg-config half is skipped")
  return()
endif()
get_filename_component(pcdir ${pc} DIRECTORY)
set(pkg ${CMAKE_COMMAND} -E env PKG_CONFIG_PATH=${pcdir} ${PKG_CONFIG})
run("pkg-config --variable=precision" ${pkg} --variable=precision karma)
string(STRIP "${last_output}" pc_precision)
if(NOT pc_precision STREQUAL PRECISION)
  message(FATAL_ERROR "karma.pc says precision=${pc_precision}; the library is ${PRECISION}")
endif()
run("pkg-config --variable=libdir" ${pkg} --variable=libdir karma)
string(STRIP "${last_output}" libdir)
if(NOT EXISTS ${libdir}/libkarma.a)
  message(FATAL_ERROR "karma.pc's libdir (${libdir}) does not hold the installed library")
endif()
run("pkg-config --cflags --libs" ${pkg} --cflags --libs karma)
separate_arguments(shared_args UNIX_COMMAND "${last_output}")
run("compiling hello.c with pkg-config (shared)" ${CC} -std=c11 ${flags} ${HELLO} ${shared_args}
    -Wl,-rpath,${libdir} -o ${WORK}/hello_pkgconfig_shared)
run_hello(${WORK}/hello_pkgconfig_shared)
run("pkg-config --static --cflags --libs" ${pkg} --static --cflags --libs karma)
string(REPLACE "-lkarma" "-l:libkarma.a" static_line "${last_output}")
separate_arguments(static_args UNIX_COMMAND "${static_line}")
run("compiling hello.c with pkg-config (static)" ${CC} -std=c11 ${flags} ${HELLO} ${static_args}
    -o ${WORK}/hello_pkgconfig_static)
run_hello(${WORK}/hello_pkgconfig_static)
message(STATUS "install check passed (prefix ${prefix}, precision ${PRECISION})")
