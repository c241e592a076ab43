# Sanitizer builds (docs/testing.md). GYRORES_SANITIZE is a comma-separated list for
# -fsanitize= (e.g. "address,undefined"); every target of this build, libraries included, is
# instrumented. UBSan does not recover: the first report aborts the process, so a finding fails
# its test instead of scrolling past. GMP, MPFR, MPFI, FLINT and Arb are not rebuilt (their code
# is not instrumented; ASan still sees our calls into them).
if(GYRORES_SANITIZE)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    message(FATAL_ERROR "GYRORES_SANITIZE needs GCC or Clang")
  endif()
  set(gyrores_sanitize_flags -fsanitize=${GYRORES_SANITIZE} -fno-omit-frame-pointer)
  if(GYRORES_SANITIZE MATCHES "undefined")
    list(APPEND gyrores_sanitize_flags -fno-sanitize-recover=all)
  endif()
  add_compile_options(${gyrores_sanitize_flags})
  add_link_options(-fsanitize=${GYRORES_SANITIZE})
  message(STATUS "gyrores: sanitizers ${GYRORES_SANITIZE}")
endif()
