# Project-wide compile settings, applied through the interface target strata_settings. The
# installed strata::strata links it too (cmake/StrataInstall.cmake), so what only strata's own
# build wants (warnings, -Werror, sanitizer and fuzzer instrumentation) is BUILD_INTERFACE: a
# program using the library keeps its own flags.
add_library(strata_settings INTERFACE)
target_compile_features(strata_settings INTERFACE cxx_std_20)
# SPEC §2: every grid quantity in plain IEEE double, no fused multiply-add. Exported: the public
# headers compute grid quantities inline (GridSpec::xc), in the user's translation units.
target_compile_options(strata_settings INTERFACE -ffp-contract=off -fno-fast-math)
target_compile_options(strata_settings INTERFACE
  "$<BUILD_INTERFACE:-Wall;-Wextra;-Wpedantic;-Wno-unused-parameter>")
if(STRATA_WERROR)
  target_compile_options(strata_settings INTERFACE $<BUILD_INTERFACE:-Werror>)
endif()
if(STRATA_SANITIZE)
  # The sanitizers' compile flags; tests/package compiles the example program with them too.
  set(strata_sanitize_flags -fsanitize=${STRATA_SANITIZE} -fno-omit-frame-pointer
                            -fno-sanitize-recover=all)
  if(STRATA_SANITIZE_EXCLUDE)
    list(APPEND strata_sanitize_flags -fno-sanitize=${STRATA_SANITIZE_EXCLUDE})
  endif()
  target_compile_options(strata_settings INTERFACE "$<BUILD_INTERFACE:${strata_sanitize_flags}>")
  # The link options stay exported: a static library built with sanitizers cannot link without
  # their runtime.
  target_link_options(strata_settings INTERFACE -fsanitize=${STRATA_SANITIZE})
  if(STRATA_SANITIZE_EXCLUDE)
    target_link_options(strata_settings INTERFACE -fno-sanitize=${STRATA_SANITIZE_EXCLUDE})
  endif()
endif()
# Fuzzing: coverage instrumentation everywhere, the libFuzzer runtime only in the fuzz targets
# (fuzz/CMakeLists.txt adds -fsanitize=fuzzer to them).
if(STRATA_BUILD_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "STRATA_BUILD_FUZZ needs clang (libFuzzer); configure with "
                        "-DCMAKE_CXX_COMPILER=clang++ or the `asan` preset")
  endif()
  target_compile_options(strata_settings INTERFACE $<BUILD_INTERFACE:-fsanitize=fuzzer-no-link>)
endif()

# Every source file below a folder of src/ belongs to the strata library, so adding a file to a
# module needs no edit here.
function(strata_glob_sources out_var)
  file(GLOB_RECURSE _files CONFIGURE_DEPENDS ${ARGN})
  set(${out_var} ${_files} PARENT_SCOPE)
endfunction()
