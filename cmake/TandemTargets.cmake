# Compile settings for tandem's own targets: warnings on, optional sanitizers.
# Third-party headers are included as SYSTEM so their warnings stay out of our builds.

function(tandem_target_settings target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion -Wnon-virtual-dtor
    -Wold-style-cast -Woverloaded-virtual -Wdouble-promotion -Wformat=2)
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
