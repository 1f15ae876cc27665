# cmake -P script behind the InstallPackage test: install the build tree into a scratch prefix,
# then configure, build and run the README's library example (its first ```cpp block, taken from
# README.md itself, so the example a newcomer copies is the one tested) with tests/consumer's
# CMakeLists.txt against it through find_package(bezel CONFIG).
# Inputs: BUILD_DIR, SOURCE_DIR, WORK_DIR, FONT, EXTRA_FLAGS (sanitizer flags of the build, if any),
# TOOLCHAIN (a cross build's toolchain file, if any: the consumer is built with it too and run
# through the CMAKE_CROSSCOMPILING_EMULATOR it sets).
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                  WORKING_DIRECTORY "${WORK_DIR}")
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
file(READ "${SOURCE_DIR}/README.md" readme)
string(FIND "${readme}" "```cpp\n" begin)
if(begin EQUAL -1)
  message(FATAL_ERROR "README.md has no ```cpp block (the library example)")
endif()
math(EXPR begin "${begin} + 7")
string(SUBSTRING "${readme}" ${begin} -1 example)
string(FIND "${example}" "\n```" end)
string(SUBSTRING "${example}" 0 ${end} example)
file(WRITE "${WORK_DIR}/src/main.cpp" "${example}\n")
configure_file("${SOURCE_DIR}/tests/consumer/CMakeLists.txt" "${WORK_DIR}/src/CMakeLists.txt" COPYONLY)
run(${CMAKE_COMMAND} -S "${WORK_DIR}/src" -B "${WORK_DIR}/build"
    "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix" "-DCMAKE_CXX_FLAGS=${EXTRA_FLAGS}"
    "-DCMAKE_EXE_LINKER_FLAGS=${EXTRA_FLAGS}" ${cross})
run(${CMAKE_COMMAND} --build "${WORK_DIR}/build")
run(${emulator} "${WORK_DIR}/build/consumer" "${FONT}")
