# Included by run.cmake once the package is installed in ${WORK_DIR}/prefix and capi.c has run
# through bezel::bezel_c: the C API as a C programmer gets it.
#   1. capi.c compiled as C11 (-Wall -Wextra -Werror -pedantic) with nothing but
#      `pkg-config --cflags --libs bezel` (PKG_CONFIG_PATH at the prefix), and run;
#   2. that program needs libbezel_c's SONAME and none of bezel's dependencies, nor libstdc++
#      (they are libbezel_c's own business);
#   3. libbezel_c.so exports exactly the functions bezel.h declares, each under the version node
#      of lib/bezel_c.map, and nothing else (`nm -D --defined-only`).
file(GLOB_RECURSE pc_file "${WORK_DIR}/prefix/bezel.pc")
if(NOT pc_file)
  message(FATAL_ERROR "the install has no bezel.pc")
endif()
get_filename_component(pc_dir "${pc_file}" DIRECTORY)
set(ENV{PKG_CONFIG_PATH} "${pc_dir}")
capture(pc_flags pkg-config --cflags --libs bezel)
string(STRIP "${pc_flags}" pc_flags)
separate_arguments(pc_flags UNIX_COMMAND "${pc_flags}")
separate_arguments(extra UNIX_COMMAND "${EXTRA_FLAGS}")
file(GLOB_RECURSE c_lib "${WORK_DIR}/prefix/libbezel_c.so")
if(NOT c_lib)
  message(FATAL_ERROR "the install has no libbezel_c.so")
endif()
get_filename_component(c_lib_dir "${c_lib}" DIRECTORY)
run(${C_COMPILER} -std=c11 -Wall -Wextra -Werror -pedantic ${extra}
    "${SOURCE_DIR}/tests/consumer/capi.c" -o "${WORK_DIR}/capi_pkgconfig" ${pc_flags}
    "-Wl,-rpath,${c_lib_dir}")
run(${emulator} "${WORK_DIR}/capi_pkgconfig" "${FONT}")

capture(c_dynamic readelf -d "${c_lib}")
if(NOT c_dynamic MATCHES "Library soname: \\[(libbezel_c\\.so\\.[0-9]+(\\.[0-9]+)?)\\]")
  message(FATAL_ERROR "${c_lib} has no libbezel_c.so.N[.M] SONAME:\n${c_dynamic}")
endif()
set(c_soname "${CMAKE_MATCH_1}")
capture(c_needed readelf -d "${WORK_DIR}/capi_pkgconfig")
if(NOT c_needed MATCHES "\\[${c_soname}\\]")
  message(FATAL_ERROR "the C consumer does not load ${c_soname}:\n${c_needed}")
endif()
if(c_needed MATCHES "freetype|harfbuzz|png|fribidi|fontconfig|isal|icu|stdc\\+\\+|libbezel\\.so")
  message(FATAL_ERROR "the C consumer links bezel's dependencies itself:\n${c_needed}")
endif()

# What bezel.h declares: every `BEZEL_API <type> bezel_name(`.
file(GLOB_RECURSE header "${WORK_DIR}/prefix/bezel.h")
file(READ "${header}" header_text)
string(REGEX MATCHALL "BEZEL_API[^(;]*[ *](bezel_[a-z0-9_]+)\\(" declared "${header_text}")
set(declared_names)
foreach(d IN LISTS declared)
  string(REGEX REPLACE ".*[ *](bezel_[a-z0-9_]+)\\($" "\\1" d "${d}")
  list(APPEND declared_names "${d}")
endforeach()
list(SORT declared_names)
list(LENGTH declared_names declared_count)
if(declared_count LESS 30)
  message(FATAL_ERROR "found only ${declared_count} declarations in ${header}: the parse is wrong")
endif()
capture(c_exported nm -D --defined-only "${c_lib}")
string(REPLACE "\n" ";" c_exported "${c_exported}")
set(exported_names)
foreach(line IN LISTS c_exported)
  if(line MATCHES "^[0-9a-f]+ A BEZEL_C_[0-9.]+$" OR line STREQUAL "")
    continue()
  endif()
  if(NOT line MATCHES "^[0-9a-f]+ T (bezel_[a-z0-9_]+)@@BEZEL_C_[0-9.]+$")
    message(FATAL_ERROR "libbezel_c exports a symbol that is not a versioned bezel_* function: "
      "${line}")
  endif()
  list(APPEND exported_names "${CMAKE_MATCH_1}")
endforeach()
list(SORT exported_names)
if(NOT exported_names STREQUAL declared_names)
  message(FATAL_ERROR "libbezel_c exports\n  ${exported_names}\nbut bezel.h declares\n  "
    "${declared_names}")
endif()
message(STATUS "${c_soname}: the ${declared_count} functions of bezel.h exported, nothing else; "
  "the C consumer needs:${c_needed}")
