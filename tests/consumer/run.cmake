# cmake -P script behind the InstallPackage test: install the build tree into a scratch prefix,
# configure and build tests/consumer against it with find_package(bezel CONFIG), run it.
# Inputs: BUILD_DIR, SOURCE_DIR, WORK_DIR, FONT, EXTRA_FLAGS (sanitizer flags of the build, if any),
# TOOLCHAIN (a cross build's toolchain file, if any: the consumer is built with it too and run
# through the CMAKE_CROSSCOMPILING_EMULATOR it sets).
file(REMOVE_RECURSE "${WORK_DIR}")
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  message(STATUS "${out}")
endfunction()
set(cross)
set(emulator)
if(TOOLCHAIN)
  set(cross "-DCMAKE_TOOLCHAIN_FILE=${TOOLCHAIN}")
  include("${TOOLCHAIN}")
  set(emulator ${CMAKE_CROSSCOMPILING_EMULATOR})
endif()
run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix")
run(${CMAKE_COMMAND} -S "${SOURCE_DIR}/tests/consumer" -B "${WORK_DIR}/build"
    "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix" "-DCMAKE_CXX_FLAGS=${EXTRA_FLAGS}"
    "-DCMAKE_EXE_LINKER_FLAGS=${EXTRA_FLAGS}" ${cross})
run(${CMAKE_COMMAND} --build "${WORK_DIR}/build")
run(${emulator} "${WORK_DIR}/build/consumer" "${FONT}")
