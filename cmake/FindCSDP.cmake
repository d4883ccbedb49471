# Finds CSDP (Debian: libsdp-dev) and defines the imported target CSDP::CSDP.
# CSDP links against LAPACK and BLAS; its headers are included as <csdp/declarations.h>.
find_path(CSDP_INCLUDE_DIR NAMES csdp/declarations.h)
find_library(CSDP_LIBRARY NAMES sdp)
find_package(LAPACK QUIET)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(CSDP
  REQUIRED_VARS CSDP_LIBRARY CSDP_INCLUDE_DIR LAPACK_FOUND
  REASON_FAILURE_MESSAGE "install libsdp-dev and liblapack-dev (scripts/install-deps.sh)")
if(CSDP_FOUND AND NOT TARGET CSDP::CSDP)
  add_library(CSDP::CSDP UNKNOWN IMPORTED)
  set_target_properties(CSDP::CSDP PROPERTIES
    IMPORTED_LOCATION "${CSDP_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${CSDP_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${LAPACK_LIBRARIES};m")
endif()
mark_as_advanced(CSDP_INCLUDE_DIR CSDP_LIBRARY)
