# The tests' oracles (tests/reference/, e.g. the retired cover certificate) are not part of the
# product: no source of the library, the I/O part, the application layer, the tool and its report
# generator, the checker or the Python module may include them. Run by ctest (test
# "reference_outside_product"):
#   cmake -DGYRORES_SOURCE_DIR=<repo> -P cmake/check_reference_outside_product.cmake
cmake_minimum_required(VERSION 3.25)
if(NOT GYRORES_SOURCE_DIR)
  message(FATAL_ERROR "check_reference_outside_product: pass -DGYRORES_SOURCE_DIR=<repo>")
endif()
set(product_dirs include/gyrores src/lib src/io src/app src/frontend src/report src/cli src/checker python/src)
set(violations 0)
foreach(dir ${product_dirs})
  file(GLOB_RECURSE sources ${GYRORES_SOURCE_DIR}/${dir}/*.hpp ${GYRORES_SOURCE_DIR}/${dir}/*.cpp)
  foreach(source ${sources})
    file(STRINGS ${source} includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"](tests/)?reference/")
    foreach(line ${includes})
      message(SEND_ERROR "${source}: includes a test reference: ${line}")
      math(EXPR violations "${violations} + 1")
    endforeach()
  endforeach()
endforeach()
if(violations GREATER 0)
  message(FATAL_ERROR "check_reference_outside_product: ${violations} violation(s)")
endif()
message(STATUS "check_reference_outside_product: no product source includes tests/reference/")
