# One interface target carries the language level and the warning flags for every mcpp target.
add_library(mcpp_project_options INTERFACE)
target_compile_features(mcpp_project_options INTERFACE cxx_std_20)
set(CMAKE_CXX_EXTENSIONS OFF)
target_compile_options(mcpp_project_options INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast -Wcast-align
  -Woverloaded-virtual -Wimplicit-fallthrough)
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  # GCC 12 reports false -Wrestrict and -Wmaybe-uninitialized positives inside libstdc++ string and
  # optional code at -O2 and above; -Wnull-dereference likewise fires inside libstdc++ headers.
  target_compile_options(mcpp_project_options INTERFACE -Wno-restrict -Wno-maybe-uninitialized)
endif()
if(MCPP_WARNINGS_AS_ERRORS)
  target_compile_options(mcpp_project_options INTERFACE -Werror)
endif()
if(MCPP_FUZZ)
  # Coverage feedback for libFuzzer in every mcpp library, with the address and undefined-behaviour checks.
  target_compile_options(mcpp_project_options INTERFACE -fsanitize=fuzzer-no-link,address,undefined
                                                        -fno-sanitize-recover=all -fno-omit-frame-pointer)
  target_link_options(mcpp_project_options INTERFACE -fsanitize=address,undefined)
endif()
if(MCPP_SANITIZE)
  # Any undefined-behaviour report stops the program, so a test with one fails.
  target_compile_options(mcpp_project_options INTERFACE -fsanitize=address,undefined -fno-sanitize-recover=all
                                                        -fno-omit-frame-pointer)
  target_link_options(mcpp_project_options INTERFACE -fsanitize=address,undefined)
endif()
