# Installs the build tree into a temporary prefix and builds two external consumers against it:
#  - kernel_consumer: find_package(CoolingGen COMPONENTS kernel), links coolinggen::coolinggen_kernel;
#    its compile and link commands must mention no OCCT, VTK, gmsh or CGNS path or library;
#  - full_consumer: find_package(CoolingGen) (every component), links coolinggen::coolinggen and OCCT.
# Both are run and must print "ok". Invoked by CTest (label "package") with -DBUILD_DIR, -DSOURCE_DIR
# (this folder) and -DWORK_DIR.
cmake_minimum_required(VERSION 3.16)
foreach(v BUILD_DIR SOURCE_DIR WORK_DIR)
  if(NOT ${v})
    message(FATAL_ERROR "run_package_test.cmake needs -D${v}=...")
  endif()
endforeach()

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
run("install into ${prefix}" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

set(launcher)
find_program(CCACHE_PROGRAM ccache)
if(CCACHE_PROGRAM)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${CCACHE_PROGRAM})
endif()
foreach(consumer kernel full)
  set(bin ${WORK_DIR}/${consumer})
  run("configure ${consumer}_consumer" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/${consumer}_consumer -B ${bin} -G Ninja
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix} ${launcher})
  run("build ${consumer}_consumer" ${CMAKE_COMMAND} --build ${bin})
  run("run ${consumer}_consumer" ${bin}/${consumer}_consumer)
  message(STATUS "${last_output}")
  if(NOT last_output MATCHES ": ok")
    message(FATAL_ERROR "${consumer}_consumer printed no \"ok\": ${last_output}")
  endif()
endforeach()

# The installed executable finds its output module (<libdir>/coolinggen, src/cli/output_jobs.hpp): the
# built-in blade without its cooling (a second's build), written as STL.
run("coolinggen example" ${prefix}/bin/coolinggen example)
string(JSON cfg REMOVE "${last_output}" cooling)
string(JSON cfg SET "${cfg}" output "{\"formats\": [\"stl\"]}")
file(WRITE ${WORK_DIR}/blade.json "${cfg}")
run("installed coolinggen build" ${prefix}/bin/coolinggen build ${WORK_DIR}/blade.json -o ${WORK_DIR}/blade -q)
if(NOT EXISTS ${WORK_DIR}/blade/blade.stl)
  message(FATAL_ERROR "the installed coolinggen wrote no blade.stl")
endif()

# The kernel consumer's build rules must not name any OCCT/VTK/gmsh/CGNS directory or library.
file(READ ${WORK_DIR}/kernel/build.ninja rules)
string(TOLOWER "${rules}" rules)
foreach(word opencascade libtk -ltk vtk gmsh cgns)
  string(FIND "${rules}" "${word}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "kernel-only consumer build mentions '${word}' (OCCT or another heavy dependency)")
  endif()
endforeach()
message(STATUS "package: kernel-only and full consumers built and ran against ${prefix}")
