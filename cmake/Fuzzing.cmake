# HYLIOS_FUZZ=ON builds the libFuzzer harnesses of fuzz/ (clang only: CC=clang CXX=clang++).
# Every target is instrumented for coverage-guided fuzzing with ASan + UBSan; UBSan findings
# abort, so libFuzzer records them as crashes. Only the harnesses link the libFuzzer driver.
if(HYLIOS_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "HYLIOS_FUZZ needs clang (configure with CC=clang CXX=clang++), "
                        "not ${CMAKE_CXX_COMPILER_ID}")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined
                      -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
