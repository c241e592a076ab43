# The certificate checker (src/checker/) must share no numeric code with the producer: its
# sources may include only each other, the standard library, Arb/FLINT and nlohmann-json, never
# a header of include/gyrores/ or of another part of src/. Run by ctest (test
# "checker_independent"):
#   cmake -DGYRORES_CHECKER_DIR=<repo>/src/checker -P cmake/check_checker_independent.cmake
cmake_minimum_required(VERSION 3.16)
if(NOT GYRORES_CHECKER_DIR)
  message(FATAL_ERROR "check_checker_independent: pass -DGYRORES_CHECKER_DIR=<repo>/src/checker")
endif()
file(GLOB sources ${GYRORES_CHECKER_DIR}/*.cpp ${GYRORES_CHECKER_DIR}/*.hpp)
set(allowed_local certificate_checker.hpp horizon_checker.hpp band_checker.hpp exact_field.hpp checker_support.hpp)
set(violations 0)
set(lines_total 0)
foreach(source ${sources})
  file(STRINGS ${source} includes REGEX "^[ \t]*#[ \t]*include")
  file(READ ${source} text)
  string(REGEX MATCHALL "\n" newlines "${text}")
  list(LENGTH newlines n)
  math(EXPR lines_total "${lines_total} + ${n}")
  foreach(line ${includes})
    if(line MATCHES "[<\"]gyrores/" OR line MATCHES "[<\"]\\.\\./")
      message(SEND_ERROR "${source}: includes producer code: ${line}")
      math(EXPR violations "${violations} + 1")
    elseif(line MATCHES "\"([^\"]+)\"" AND NOT CMAKE_MATCH_1 IN_LIST allowed_local)
      message(SEND_ERROR "${source}: includes a local file outside the checker: ${line}")
      math(EXPR violations "${violations} + 1")
    endif()
  endforeach()
endforeach()
if(violations GREATER 0)
  message(FATAL_ERROR "check_checker_independent: ${violations} violation(s)")
endif()
# Three checkers: lattice-theorem certificates (about 380 lines), coupling certificates (about
# 1000: its own Q(sqrt D) arithmetic, MinFrac, FirstHit, the minimum and the first time below) and
# band certificates (about 900: its own Stern-Brocot search, the lobe value's bisection, the end
# point's mean-value form, the covers and the claims).
if(lines_total GREATER 2400)
  message(FATAL_ERROR "check_checker_independent: the checker has ${lines_total} lines (the aim is at most 2400)")
endif()
message(STATUS "check_checker_independent: ${lines_total} lines, includes only Arb/FLINT, nlohmann-json and the standard library")
