# Compile settings for tandem's own targets: warnings on, optional sanitizers.
# Third-party headers are included as SYSTEM so their warnings stay out of our builds.

set(TANDEM_DEBUG_INFO "lines" CACHE STRING
    "Debug information of RelWithDebInfo builds: 'lines' (-g1) or 'full' (-g)")
set_property(CACHE TANDEM_DEBUG_INFO PROPERTY STRINGS lines full)
if(NOT TANDEM_DEBUG_INFO MATCHES "^(lines|full)$")
  message(FATAL_ERROR "TANDEM_DEBUG_INFO: 'lines' or 'full', not '${TANDEM_DEBUG_INFO}'")
endif()

function(tandem_target_settings target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion -Wnon-virtual-dtor
    -Wold-style-cast -Woverloaded-virtual -Wdouble-promotion -Wformat=2)
  # Line tables only (-g1 after CMake's -g): backtraces, sanitizer reports and perf keep their
  # files and lines, and a build from nothing takes a quarter less time (README); "full" for a
  # debugger's variables.
  if(TANDEM_DEBUG_INFO STREQUAL "lines")
    target_compile_options(${target} PRIVATE $<$<CONFIG:RelWithDebInfo>:-g1>)
  endif()
  if(TANDEM_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=${TANDEM_SANITIZE} -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=${TANDEM_SANITIZE})
  endif()
  # The fuzzing build (clang): libFuzzer's coverage instrumentation in every target of ours; the
  # fuzz targets link libFuzzer itself (fuzz/CMakeLists.txt).
  if(TANDEM_FUZZ)
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
  endif()
endfunction()
