# libFuzzer builds (GYRORES_FUZZ=ON; clang only, docs/testing.md). Every target is compiled with
# coverage instrumentation for libFuzzer plus AddressSanitizer and UndefinedBehaviorSanitizer
# (aborting on the first report), so the libraries the targets call are instrumented too; the
# targets themselves are tests/fuzz/fuzz_*.cpp, linked with -fsanitize=fuzzer.
if(GYRORES_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "GYRORES_FUZZ needs clang (e.g. -DCMAKE_CXX_COMPILER=clang++-14)")
  endif()
  if(GYRORES_SANITIZE)
    message(FATAL_ERROR "GYRORES_FUZZ already sanitizes (address,undefined): leave GYRORES_SANITIZE empty")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
  # Boost's float128 includes GCC's quadmath.h, which clang does not ship: that one header is
  # copied from GCC's include directory (adding the whole directory would shadow clang's own
  # stddef.h and intrinsics).
  execute_process(COMMAND g++ -print-file-name=include/quadmath.h OUTPUT_VARIABLE gyrores_quadmath_h
                  OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT EXISTS "${gyrores_quadmath_h}")
    message(FATAL_ERROR "GYRORES_FUZZ: GCC's quadmath.h not found (Debian: g++)")
  endif()
  configure_file(${gyrores_quadmath_h} ${PROJECT_BINARY_DIR}/fuzz-include/quadmath.h COPYONLY)
  include_directories(SYSTEM ${PROJECT_BINARY_DIR}/fuzz-include)
endif()
