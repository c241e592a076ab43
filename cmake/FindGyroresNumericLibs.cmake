# Finds GMP, MPFR and MPFI (Debian: libgmp-dev, libmpfr-dev, libmpfi-dev) and defines the
# imported target gyrores::numeric_libs linking all three. MPFI needs MPFR, which needs GMP.
find_path(GYRORES_MPFI_INCLUDE_DIR mpfi.h)
find_path(GYRORES_MPFR_INCLUDE_DIR mpfr.h)
find_path(GYRORES_GMP_INCLUDE_DIR gmp.h)
find_library(GYRORES_MPFI_LIBRARY mpfi)
find_library(GYRORES_MPFR_LIBRARY mpfr)
find_library(GYRORES_GMP_LIBRARY gmp)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(GyroresNumericLibs
  REQUIRED_VARS GYRORES_GMP_LIBRARY GYRORES_MPFR_LIBRARY GYRORES_MPFI_LIBRARY
                GYRORES_GMP_INCLUDE_DIR GYRORES_MPFR_INCLUDE_DIR GYRORES_MPFI_INCLUDE_DIR)

if(GyroresNumericLibs_FOUND AND NOT TARGET gyrores::numeric_libs)
  add_library(gyrores::numeric_libs INTERFACE IMPORTED)
  set_target_properties(gyrores::numeric_libs PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${GYRORES_MPFI_INCLUDE_DIR};${GYRORES_MPFR_INCLUDE_DIR};${GYRORES_GMP_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${GYRORES_MPFI_LIBRARY};${GYRORES_MPFR_LIBRARY};${GYRORES_GMP_LIBRARY};quadmath")
endif()
